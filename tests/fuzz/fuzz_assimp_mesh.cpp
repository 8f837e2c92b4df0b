// Fuzz target: the assimp path of the mesh reader, GLB, glTF, FBX and PLY (fuzz_readers.h).
#include "fuzz/fuzz_readers.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hair::fuzz::abort_on(hair::fuzz::assimp_mesh_finding(data, size));
  return 0;
}
