// libFuzzer program for read_resume_bytes (file_fuzzers.hpp); tools/fuzz.sh resume builds and runs it.
#include "fuzz/file_fuzzers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  snell::fuzz::read_resume_bytes(data, size);
  return 0;
}
