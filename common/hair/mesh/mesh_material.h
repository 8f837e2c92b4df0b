#pragma once
// The materials of a hair mesh: the images the artist painted on its faces, as the mesh
// file names them (an OBJ's MTL file with map_Kd and map_d; a glTF/GLB or FBX material's
// diffuse and opacity textures, external or embedded in the file).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace hair {

/// One painted image: a file, or an image embedded in the mesh file (its encoded bytes,
/// PNG or JPEG, with `path` naming it for messages).
struct MaterialImage {
  std::filesystem::path path;   ///< resolved against the file that names it; empty: none
  std::vector<uint8_t> encoded;  ///< embedded image bytes; empty: read `path`
  bool present() const { return !path.empty() || !encoded.empty(); }
};

/// A surface material: its name and the images painted on it.
struct MeshMaterial {
  std::string name;
  MaterialImage diffuse;  ///< map_Kd: the colour (its alpha channel, if any, is the coverage)
  MaterialImage alpha;    ///< map_d: the coverage; none: the diffuse image's alpha
};

/// The materials an MTL file defines (`newmtl`, `map_Kd`, `map_d`; options such as
/// `-bm 1` before the file name are skipped, and the file name may contain spaces), with
/// image paths resolved against the MTL file's folder. Throws Error::bad_input naming the
/// file if it cannot be read.
std::vector<MeshMaterial> read_mtl(const std::filesystem::path& path);

}  // namespace hair
