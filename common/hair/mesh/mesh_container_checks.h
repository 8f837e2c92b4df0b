#pragma once
// Checks of a mesh file's container before assimp reads it, for the formats where a
// malformed header makes assimp 5.2 hang or allocate what the file claims: a PLY header
// with an unknown line or no end_header sent its PLY reader into an endless loop, and a
// GLB whose header declares more bytes than the file holds had it allocate 4 GiB (both
// found by tests/fuzz/fuzz_assimp_mesh).

#include <filesystem>

namespace hair {

/// Throws Error::bad_input naming `path` and the problem if the file's container is
/// malformed: for .ply, a header that is not "ply", then format, comment, obj_info,
/// element (with a count no larger than the file) and property lines of known types, up
/// to end_header within the first 64 KiB; for .glb, a header or chunk that runs past the
/// end of the file. Other formats, and GLB files without the glTF magic, are left to the
/// reader.
void check_mesh_container(const std::filesystem::path& path);

}  // namespace hair
