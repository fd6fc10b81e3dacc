// libFuzzer program for read_mesh_bytes (file_fuzzers.hpp); tools/fuzz.sh mesh builds and runs it.
#include "fuzz/file_fuzzers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  snell::fuzz::read_mesh_bytes(data, size);
  return 0;
}
