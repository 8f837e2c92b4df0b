#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_validation.h"

namespace hair::testing {

/// Deletes the dataset or attribute-free object `path` so a test can write another.
inline void remove_object(h5::File& file, const std::string& path) {
  ASSERT_GE(H5Ldelete(file.id(), path.c_str(), H5P_DEFAULT), 0) << path;
}

/// Writes a small file that conforms to hairstyle.extract v3 (2 groups, 3 strands of 2,
/// 3 and 2 points, a hair mesh of 8 vertices and 3 faces, a body of 4 vertices and 2
/// triangles), then lets `tamper` change it; the file is named "extract.h5" in errors.
inline void write_extract_file(const std::filesystem::path& path,
                               const std::function<void(h5::File&)>& tamper = {}) {
  using namespace h5;
  const Schema& schema = Schema::find("hairstyle.extract");
  File file = File::create(path, "extract.h5");
  write_schema_attributes(file, schema);
  write_string_attribute(file, "/", "unit", "m");
  write_string_attribute(file, "/", "up_axis", "+Y");
  write_double_attribute(file, "/", "unit_scale", 0.1);
  write_double_attribute(file, "/", "head_height_m", 0.25);
  write_double_attribute(file, "/", "head_top_y_m", 1.75);
  write_double_attribute(file, "/", "neck_y_m", 1.5);
  write_provenance(file, {.stage = "extract",
                          .project_version = "test",
                          .parameters = R"({"min_points": 2})",
                          .inputs = {{"hair_mesh", "bob.obj", std::string(64, '0')}},
                          .wall_time_s = 0.5,
                          .created_utc = "2024-01-01T00:00:00Z"});

  write_dataset<float>(file, "/strands/points",
                       {0, 1.7f, 0,    0, 1.6f, 0,    0.1f, 1.7f, 0,    0.1f, 1.6f,
                        0, 0.1f, 1.5f, 0, 0.2f, 1.7f, 0,    0.2f, 1.6f, 0},
                       {7, 3});
  write_vector<int64_t>(file, "/strands/offsets", {0, 2, 5, 7});
  write_vector<int32_t>(file, "/strands/strand_attributes/group", {0, 0, 1});
  write_vector<int32_t>(file, "/strands/strand_attributes/rail", {0, 1, 0});
  write_vector<int32_t>(file, "/strands/point_attributes/source_vertex", {0, 1, 2, 3, 4, 5, 6});

  write_enum_dataset(file, "/groups/patch_kind", {1, 0},
                     schema.dataset("/groups/patch_kind").enum_members);
  write_enum_dataset(file, "/groups/orientation_rule", {0, 1},
                     schema.dataset("/groups/orientation_rule").enum_members);
  write_vector<float>(file, "/groups/orientation_confidence", {1.0f, 0.5f});
  write_vector<int32_t>(file, "/groups/first_strand", {0, 2, 3});
  write_vector<int32_t>(file, "/groups/face_count", {2, 1});

  write_dataset<float>(file, "/mesh/vertices", std::vector<float>(24, 0.5f), {8, 3});
  write_vector<int64_t>(file, "/mesh/face_offsets", {0, 4, 8, 11});
  write_vector<int32_t>(file, "/mesh/face_vertices", {0, 1, 2, 3, 2, 3, 4, 5, 5, 6, 7});
  write_vector<int32_t>(file, "/mesh/face_group", {0, 0, 1});
  write_dataset<float>(file, "/mesh/face_flow", std::vector<float>(9, 0.0f), {3, 3});
  write_vector<float>(file, "/mesh/face_flow_coherence", {0, 0, 0});
  write_vector<float>(file, "/mesh/face_flow_alpha_fall", {0, 0, 0});

  write_dataset<float>(file, "/body/vertices", std::vector<float>(12, 0.25f), {4, 3});
  write_dataset<int32_t>(file, "/body/triangles", {0, 1, 2, 0, 2, 3}, {2, 3});
  write_vector<uint8_t>(file, "/body/scalp_triangle", {1, 0});
  if (tamper) tamper(file);
  file.close();
}

}  // namespace hair::testing
