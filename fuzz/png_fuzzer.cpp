// libFuzzer program for read_png_bytes (file_fuzzers.hpp); tools/fuzz.sh png builds and runs it.
#include "fuzz/file_fuzzers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  snell::fuzz::read_png_bytes(data, size);
  return 0;
}
