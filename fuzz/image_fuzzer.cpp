// libFuzzer program for read_image_bytes (file_fuzzers.hpp); tools/fuzz.sh image builds and runs it.
#include "fuzz/file_fuzzers.hpp"
#include "snell/io/image_backend.hpp"

// Loads the OpenImageIO plugin (about 260 shared libraries) before the first input: under the sanitizers on
// a busy machine that took over libFuzzer's 25 s per-input limit, which then reported the first seed.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  snell::io::image_backend();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  snell::fuzz::read_image_bytes(data, size);
  return 0;
}
