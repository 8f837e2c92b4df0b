// Mesh containers checked before assimp reads them (mesh_container_checks.h): malformed
// PLY headers and GLB headers that claim more than the file holds are refused by name,
// fast, where assimp 5.2 hung or allocated what they claimed.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "hair/core/error.h"
#include "hair/mesh/mesh_container_checks.h"
#include "hair/mesh/mesh_io.h"
#include "unit/file_test.h"

namespace hair {
namespace {

using MeshContainerChecks = test::FileTest;

const std::string kPlyQuad =
    "ply\nformat ascii 1.0\ncomment a quad\nelement vertex 4\nproperty float x\n"
    "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
    "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";

/// The error message of check_mesh_container() on `path`, or "" if it passes.
std::string refusal(const std::filesystem::path& path) {
  try {
    check_mesh_container(path);
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    return error.what();
  }
  return {};
}

TEST_F(MeshContainerChecks, AWellFormedPlyPassesAndReads) {
  const auto path = write_file("quad.ply", kPlyQuad);
  EXPECT_EQ(refusal(path), "");
  EXPECT_EQ(read_mesh(path).face_count(), 1);
}

TEST_F(MeshContainerChecks, MalformedPlyHeadersAreRefusedByLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      // An unknown line and no end_header: assimp's PLY reader looped for ever on it.
      {"ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\npropewty list r\n0 0 0\n",
       "line 5: unknown keyword 'propewty'"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "no end_header"},
      {"plx\nend_header\n", "line 1: expected 'ply'"},
      {"ply\nformat ascii 1.0\nelement vertex 99999999\nproperty float x\nend_header\n0\n",
       "line 3: expected 'element NAME COUNT' with a count the file can hold"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty quaternion x\nend_header\n0\n",
       "line 4: expected 'property TYPE NAME'"},
      {"ply\nformat ebcdic 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n",
       "line 2: expected 'format"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string message = refusal(write_file("bad.ply", text));
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_NE(message.find("bad.ply: PLY header, line"), std::string::npos) << message;
  }
}

std::string glb(uint32_t declared_length, uint32_t chunk_length, size_t chunk_bytes) {
  std::string bytes = "glTF";
  auto u32 = [&](uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) bytes.push_back(static_cast<char>((value >> shift) & 0xff));
  };
  u32(2);
  u32(declared_length);
  u32(chunk_length);
  u32(0x4E4F534A);  // JSON
  bytes += std::string(chunk_bytes, ' ');
  return bytes;
}

TEST_F(MeshContainerChecks, GlbHeadersThatClaimMoreThanTheFileHoldsAreRefused) {
  EXPECT_EQ(refusal(write_file("fits.glb", glb(12 + 8 + 4, 4, 4))), "");
  EXPECT_NE(refusal(write_file("long.glb", glb(0xffff0000u, 4, 4)))
                .find("long.glb: GLB header declares 4294901760 bytes; the file has 24"),
            std::string::npos);
  EXPECT_NE(refusal(write_file("chunk.glb", glb(12 + 8 + 4, 1000, 4)))
                .find("chunk.glb: GLB chunk at byte 12 (1000 bytes) runs past the end of the file"),
            std::string::npos);
  // Not GLB at all: left to the reader, which names it.
  EXPECT_EQ(refusal(write_file("text.glb", "not a binary glTF")), "");
}

}  // namespace
}  // namespace hair
