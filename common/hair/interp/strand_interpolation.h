#pragma once
// Every grown strand per frame from the simulated guides (paper section 5.2,
// "Interpolation"): barycentric interpolation from three nearby guides of the same cluster
// that point in similar directions, clump interpolation from one guide otherwise; fixed
// hair rigid with the head; braided hair from its wisp's tetrahedra.
//
// The binding (which guides, which weights, where each point lies along them and its
// offset from them) is computed once at rest by bind_strands(); interpolate_frame() is a
// tight loop over it per frame.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/sim/head_motion.h"

namespace hair {

/// How a strand's moving part follows the simulation (/strands/method of frames.h5).
enum class InterpolationMethod : int8_t {
  fixed = 0,        ///< every point rigid with the head
  barycentric = 1,  ///< three guides, barycentric weights of its anchor among theirs
  clump = 2,        ///< one guide
  braided = 3,      ///< every moving point fixed in a wisp tetrahedron's frame
};

/// Word of a method, as in the enum dataset ("fixed", "barycentric", ...).
const char* interpolation_method_name(InterpolationMethod method);

/// Parameters of bind_strands().
struct InterpolationParams {
  /// Guides whose anchors are searched for the three nearest (k-d tree).
  int candidate_guides = 8;
  /// Barycentric only if the three guides' directions (anchor to tip at rest, unit) have
  /// pairwise cosines at least this (paper: "when their directions are similar").
  double min_direction_cosine = 0.8;
  /// Barycentric only if the triangle of the three anchors is not a sliver: its smallest
  /// height is at least this share of its longest edge.
  double min_triangle_aspect = 0.05;
  /// A guide a strand follows is at least this share of the strand's length (rest, from
  /// the anchor): each of a barycentric strand's three, else it is a clump; a clump's
  /// guide, from the candidates of its cluster, else of another cluster simulated alike,
  /// else (none long enough among the candidates) the best of its cluster whatever its
  /// length. A strand on a much shorter guide carries offsets tens of centimetres long
  /// that turn with the guide's tip.
  double min_guide_length_ratio = 0.5;
  /// A strand bound to a wisp (a braid) is bridged from the head to its first bound point
  /// over at least this much of its length: where its held points (a cap feeding the
  /// braid) run right up to the braid, their last stretch is bridged instead of held, so
  /// the braid's top moving against the head spreads over it rather than tearing one
  /// segment (docs/interpolate.md); where even its root lies nearer the braid than this
  /// (a strand rooted right by the braid's top), its first bound points are bridged too.
  double wisp_bridge_length_m = 0.08;
  /// Where a braided strand passes from one wisp tetrahedron to the next, its points
  /// within this arc length of the seam move partly with the other tetrahedron too (half
  /// at the seam, none at this distance), so that two tetrahedra turning apart bend the
  /// strand there instead of tearing the segment between them (docs/interpolate.md). 0:
  /// each point moves with its own tetrahedron only.
  double wisp_seam_length_m = 0.02;
};

/// The simulated guides as interpolation reads them (guides.h5).
struct InterpolationGuides {
  Points3f rest_points;                ///< #guide points x 3, at rest, anchor first
  std::vector<int64_t> offsets{0};     ///< #guides + 1 (CSR)
  std::vector<int32_t> cluster;        ///< #guides
  std::vector<int8_t> is_wisp_centre;  ///< #guides: 1 for a wisp centre (never interpolated from)
  std::vector<int64_t> strand;         ///< #guides: grown strand of a strand guide, else -1
  std::vector<int32_t> wisp_tetrahedron_offsets{0};  ///< #wisps + 1
  /// Braided points: grown point, wisp, tetrahedron of that wisp, position in its frame.
  std::vector<int64_t> binding_point;
  std::vector<int32_t> binding_wisp, binding_tetrahedron;
  std::vector<Eigen::Vector3f> binding_local_m;
  /// The wisp tetrahedra's frames at rest (#tetrahedra x 7: origin xyz, quaternion wxyz),
  /// for the points between a braided strand's held root and its wisp.
  std::vector<float> wisp_rest_frames;
  std::vector<int8_t> cluster_simulated_style;  ///< per cluster (HairStyle values, -1 none)

  int64_t guide_count() const { return static_cast<int64_t>(offsets.size()) - 1; }
};

/// One frame of the simulation.
struct GuideFrame {
  const float* guide_points_m = nullptr;  ///< #guide points x 3, world
  const float* wisp_frames = nullptr;     ///< #wisp tetrahedra x 7: origin xyz, quaternion wxyz
  RigidTransform head;                    ///< world from rest
};

/// The rest-state binding of every strand to what moves it.
struct StrandBinding {
  /// Per strand (#strands).
  std::vector<InterpolationMethod> method;
  std::vector<std::array<int32_t, 3>> guides;  ///< -1 where unused
  std::vector<std::array<float, 3>> weights;   ///< sum to 1 over the used guides
  /// Leading points rigid with the head (in fixed clusters from the root).
  std::vector<int64_t> held_count;
  /// First point bound to a wisp tetrahedron (the strand's size if none); the bound points
  /// before it that a bridge took over (params.wisp_bridge_length_m) are bridged.
  std::vector<int64_t> bound_from;
  /// Per grown point (#points): arc parameter along the guides (0 at the strand's anchor,
  /// 1 at its tip) of interpolated points, and the offset at rest from the weighted guide
  /// points at that parameter (rest frame), or the rest position of a held point, or the
  /// position in its tetrahedron's frame of a bound point.
  std::vector<float> parameter;
  Points3f offset_m;
  std::vector<int32_t> tetrahedron;  ///< bound points: global tetrahedron index; else -1
  /// Per strand: first point interpolated, one past the last.
  std::vector<int64_t> interpolated_from;
  /// Per strand: 1 where the points between held_count and bound_from are bridged from the
  /// head to the wisp (a braided strand): parameter is the share of the way along the
  /// bridge, offset_m the rest position.
  std::vector<int8_t> bridged;
  /// The interpolated points in runs (interpolation_kernel.h's strand_runs(), computed
  /// once here so that a frame does not search for them): per strand its first run
  /// (#strands + 1, CSR; no runs for a strand of more than kMaxStrandRuns, which is
  /// interpolated point by point), per run each used guide's particle (in the order of
  /// `guides`, the unused left out), and per point its run within its strand.
  std::vector<int64_t> run_offsets;
  std::vector<std::array<int32_t, 3>> run_particles;
  std::vector<uint8_t> run_of_point;
  int64_t tetrahedron_count = 0;
  /// Bound points near a seam between two wisp tetrahedra (wisp_seam_length_m): per strand
  /// its first entry (#strands + 1, CSR); per entry the point's row, the other
  /// tetrahedron, the share of the point's position it gives, and the point's rest
  /// position in that tetrahedron's rest frame (3 floats).
  std::vector<int64_t> seam_offsets;
  std::vector<int64_t> seam_row;
  std::vector<int32_t> seam_tetrahedron;
  std::vector<float> seam_weight;
  std::vector<float> seam_local_m;
  std::vector<int64_t> guide_offsets;  ///< the guides' CSR offsets
  Points3f guide_rest_points;          ///< the guides at rest (their segments' rest directions)
};

/// A strand's used guides (binding.guides without the -1), their segment counts and weights.
struct StrandGuides {
  int count = 0;
  std::array<int32_t, 3> guide = {-1, -1, -1};
  std::array<float, 3> segments = {0, 0, 0};
  std::array<float, 3> weight = {0, 0, 0};
};
StrandGuides strand_guides(const StrandBinding& binding, int64_t strand);

/// Binds `strands` (grown strands with the point attribute "cluster") to `guides` at
/// rest. A strand's points from the root that lie in fixed clusters are held by the head;
/// the points bound to a wisp follow it; the others are interpolated from guides chosen by
/// the strand's anchor (its last held point, or its root) and its cluster (that of its
/// first interpolated point): the three nearest guides if they are of that cluster and
/// point in similar directions (barycentric weights of the anchor projected onto their
/// triangle, clamped to it), else, of those candidates in the cluster, the guide whose
/// rest shape lies closest to the strand's (least mean distance at equal arc parameter;
/// clump), else the nearest guide of the cluster, else the nearest guide. A strand with points to
/// interpolate and no guide at all is held. A strand bound to a wisp follows no guide: its points
/// between its held ones (or its root) and its first bound point are bridged, over at least
/// params.wisp_bridge_length_m (held points giving way, the root excepted, then bound points
/// from the first, the tip excepted): they move with the
/// head plus, by their share of the arc, the first bound point's move away from where the head
/// would carry it (method braided).
/// Deterministic. Throws Error::usage for parameters out of range and Error::runtime for
/// guides or bindings that do not fit the strands.
StrandBinding bind_strands(const StrandSet& strands, const InterpolationGuides& guides,
                           const InterpolationParams& params);

/// Every grown point in one frame: #points x 3 floats into `points_m` (row-major).
/// Interpolated point: sum_g w_g (G_g(u) + F_g(u) d), G_g(u) the guide at arc parameter u
/// (linear between its particles), F_g(u) its frame there (the head's rotation turned by
/// the smallest rotation that takes each rest segment's direction to its current one,
/// averaged at the particles, linear between them; the head's rotation at the anchor,
/// so that roots move with the scalp); d the rest offset. At rest F = I and the sum
/// reproduces the grown strand. Held point: R p + t. Bound point: origin + R_tet local.
/// Bridged point at share s: (1 - s) (R p + t) + s T_tet T_tet,rest^-1 p.
/// Parallel over strands (OpenMP); the same result whatever the thread count.
void interpolate_frame(const StrandBinding& binding, const StrandSet& strands,
                       const GuideFrame& frame, std::vector<float>& points_m);

}  // namespace hair
