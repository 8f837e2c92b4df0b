#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "hair/geom/triangle_mesh_distance.h"

namespace hair {

/// Faces (CSR, as PolyMesh) fanned into triangles, each with its face's group: what
/// GrowInput::hair_triangles and hair_triangle_group hold. Throws std::invalid_argument
/// when `face_group` is not one per face.
void fan_triangulation_with_groups(const std::vector<int64_t>& face_offsets,
                                   const std::vector<int32_t>& face_vertices,
                                   const std::vector<int32_t>& face_group, Triangles3i& triangles,
                                   std::vector<int32_t>& triangle_group);

/// Per triangle of fan_triangulation_with_groups(): its face's painted flow axis
/// (`face_flow`, extract.h5 /mesh/face_flow) where the face's strokes are clear (`coherence`
/// at least `min_coherence`: kClearFlowCoherence), else zero (GrowInput::hair_triangle_flow).
/// Throws std::invalid_argument when `face_flow` or `coherence` is not one per face.
Points3f fan_painted_flow(const std::vector<int64_t>& face_offsets, const Points3f& face_flow,
                          const std::vector<float>& coherence, double min_coherence);

/// The faces of each strand group (patch, card) of the hair mesh, for the nearest point of
/// a group's own card: a strand following a card's input strands keeps to that card's
/// surface (GrowParams::follow_card_keep_h), where a card lies on, under or across
/// another (spiky cards over a cap, a braid's locks) and the nearest face of the whole
/// mesh may be the other card's.
class CardSurfaces {
 public:
  CardSurfaces() = default;
  /// @param vertices        the hair mesh's vertices (extract.h5 /mesh/vertices)
  /// @param triangles       its faces as triangles (fan_triangulation())
  /// @param triangle_group  the group of each triangle, -1 for none; groups in
  ///                        [0, group_count)
  CardSurfaces(const Points3f& vertices, const Triangles3i& triangles,
               const std::vector<int32_t>& triangle_group, int64_t group_count);

  /// Whether `group` has faces (false for every group when built empty).
  bool has(int32_t group) const {
    return group >= 0 && static_cast<size_t>(group) < surfaces_.size() && surfaces_[group];
  }
  /// Nearest point of `group`'s faces to `point`; std::nullopt where it has none.
  /// Thread-safe.
  std::optional<TriangleMeshDistance::Nearest> nearest(int32_t group,
                                                       const Eigen::Vector3d& point) const;

 private:
  std::vector<std::unique_ptr<TriangleMeshDistance>> surfaces_;  ///< per group; null: none
};

}  // namespace hair
