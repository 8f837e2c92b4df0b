// Fuzz target: an embedded painted texture, decoded and carried onto faces (fuzz_readers.h).
#include "fuzz/fuzz_readers.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hair::fuzz::abort_on(hair::fuzz::texture_finding(data, size));
  return 0;
}
