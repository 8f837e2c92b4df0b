// Fuzz target: every stage's HDF5 input checks and readers (fuzz_readers.h).
#include "fuzz/fuzz_readers.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hair::fuzz::abort_on(hair::fuzz::h5_input_finding(data, size));
  return 0;
}
