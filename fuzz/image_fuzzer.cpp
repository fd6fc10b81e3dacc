// libFuzzer program for read_image_bytes (file_fuzzers.hpp); tools/fuzz.sh image builds and runs it.
#include "fuzz/file_fuzzers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  snell::fuzz::read_image_bytes(data, size);
  return 0;
}
