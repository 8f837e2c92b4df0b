// Fuzz target: the MTL reader and the images it names (fuzz_readers.h).
#include "fuzz/fuzz_readers.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hair::fuzz::abort_on(hair::fuzz::mtl_finding(data, size));
  return 0;
}
