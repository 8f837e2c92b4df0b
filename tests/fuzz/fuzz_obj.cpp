// Fuzz target: the native OBJ reader and the painted flow (fuzz_readers.h).
#include "fuzz/fuzz_readers.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hair::fuzz::abort_on(hair::fuzz::obj_finding(data, size));
  return 0;
}
