#pragma once
// Style-specific simulation of guide strands (paper section 5.2): fixed clusters move
// with the head, normal and short clusters are simulated by guide strands of the
// altitude mass-spring model (short ones with fewer particles per length), and each
// braided cluster by a wisp: one centre strand that its strands follow rigidly.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hair/sim/simulation_profile.h"
#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/sim/altitude_strand.h"
#include "hair/sim/guide_selection.h"
#include "hair/sim/head_motion.h"
#include "hair/sim/strand_dynamics.h"

namespace hair {

/// Parameters of simulate_hair(); lengths relative to the head height H where they end
/// in _h.
struct SimulationParams {
  double fps = 30;                     ///< frames per second of the output
  double duration_s = 0;               ///< 0: one cycle of the head motion
  int substeps = 2;                    ///< time steps per frame
  int guide_count = 169;               ///< guides over the normal and short clusters (paper: 169)
  double segment_length_h = 0.15;      ///< guide particle spacing along normal hair
  double short_segment_factor = 2;     ///< short hair: this many times longer segments (stiffer)
  double wisp_segment_factor = 1;      ///< a wisp's centre strand: segments this many times longer
  double wisp_gather_radius_h = 0.15;  ///< a braid's strands are a bundle where their mean
                                       ///< distance from their mean point is within this
  /// The hair (a fibre's moduli, radius and density; fibres per guide) and how it moves.
  StrandMaterial material;
  /// Each simulated strand's groom is made its rest under gravity with the head still
  /// (sag_free_rest.h: tension along the hair, a support force fixed in the head's frame
  /// for the rest); false: the groom is the springs' rest shape, and the hair sags from it.
  bool sag_free = true;
  /// Tails hold together: a hair particle of a guide hanging from a band is drawn back
  /// towards its bundle's centre line where it strays farther from it than at rest, with
  /// this stiffness per kilogram (1/s^2; 0: off). See bundle_cohesion.h.
  double bundle_cohesion_per_s2 = 1600;
  /// The hair-hair friction inside a tail: a hair particle straying beyond its rest
  /// distance is damped in its speed away from the centre line (relative to the bundle's
  /// own motion), as this fraction of the cohesion spring's critical damping (held to
  /// 1 / dt). See bundle_cohesion.h.
  double bundle_damping_ratio = 1;
  double gravity_m_s2 = 9.81;       ///< along -Y
  double body_clearance_h = 0.004;  ///< hair particles are kept this far outside the body
                                    ///< (as grow keeps the grown points)
  double body_voxel_h = 0.01;       ///< spacing of the body's signed distance field
  double body_band_h = 0.1;         ///< exact distances this far from the body (deeper
                                    ///< points are pushed out along the field's gradient)
  double friction = 0.3;            ///< Coulomb friction against the body
  bool body_collisions = true;      ///< false: hair passes through the body (benchmarks)
  bool profile_phases = false;      ///< time each phase of every strand step (the log)
  double repulsion_m_s2 = 1.0;      ///< hair-hair repulsion strength (0: none)
  double density_cell_h = 0.08;     ///< cell of the hair density grid
  /// The repulsion is worked out at the first step of every this many frames (from the
  /// density then) and held in between: 1 is every frame. At 2 it costs a tenth less time
  /// and the same error against a reference (docs/simulate.md).
  int repulsion_interval_frames = 2;
  /// A still head: integration stops once no hair particle has moved faster than this
  /// (H per second) for settle_frames frames in a row; later frames repeat the last.
  double settle_speed_h_s = 0.05;
  int settle_frames = 10;
  /// false: every cluster is simulated as normal hair, with guides over all of it (the
  /// style rules off: no fixed hair, no short-hair segments, no wisps; benchmarks).
  bool by_style = true;
};

/// What simulate_hair() needs: the grown strands (with the "cluster" point attribute), the
/// style of each cluster (-1 none), the body and the head height.
struct SimulationScene {
  StrandSet strands;
  std::vector<int8_t> cluster_style;
  Points3f body_vertices;
  Triangles3i body_triangles;
  double head_height_m = 0;
  std::string source;  ///< the file errors name
};

/// How a guide is simulated.
enum class GuideKind : int8_t {
  strand = 0,       ///< a grown strand, simulated from its anchor point
  wisp_centre = 1,  ///< the centre strand of a braided cluster's wisp
};

/// One simulated strand: its hair particles at rest (root or anchor first) and what it is.
struct SimulatedGuide {
  GuideKind kind = GuideKind::strand;
  int64_t strand = -1;       ///< grown strand (-1 for a wisp centre)
  int64_t anchor_point = 0;  ///< index of the anchor within the grown strand (strand guides)
  int32_t cluster = 0;
  HairStyle style = HairStyle::normal;
  double mass_scale = 1;                ///< a wisp centre: the number of strands it carries
  std::vector<Eigen::Vector3d> rest_m;  ///< hair particles
  int32_t ghost_count = 0;
  int32_t anchor_count = 0;  ///< a wisp centre: the strand ends it hangs from
};

/// A point of a braided strand, fixed in the frame of the nearest tetrahedron of its
/// wisp's centre strand.
struct WispBinding {
  int64_t point = 0;                                  ///< row of the grown strands' points
  int32_t wisp = 0;                                   ///< index into SimulationResult::wisp_guide
  int32_t tetrahedron = 0;                            ///< of that wisp's centre strand
  Eigen::Vector3f local_m = Eigen::Vector3f::Zero();  ///< in the tetrahedron's frame
};

/// Per-frame figures.
struct FrameStatistics {
  double time_s = 0;
  double kinetic_energy_j = 0;
  double elastic_energy_j = 0;
  double gravity_energy_j = 0;   ///< m g (y - y_rest), summed
  double max_stretch = 0;        ///< largest |strain| of a hair segment
  double max_penetration_m = 0;  ///< deepest a hair particle was inside the body before
                                 ///< it was pushed out, over the frame's steps
  double inside_fraction = 0;    ///< hair particles inside the body at the frame's end
  double max_speed_m_s = 0;      ///< fastest hair particle over the frame (its
                                 ///< displacement since the last frame times fps)
  bool integrated = true;        ///< false once a still head has settled
};

/// The simulation: guides, their positions per frame, the head, the wisps.
struct SimulationResult {
  std::vector<SimulatedGuide> guides;
  /// The style each cluster was simulated as: its style, but for a braided cluster whose
  /// strands do not gather into a bundle, fixed if most of its points lie on the body
  /// (within 0.1 H: a cap gathered into a braid) and normal otherwise.
  std::vector<int8_t> simulated_style;
  GuidePlan plan;
  int32_t frame_count = 0;
  double fps = 0;
  /// frame_count x (sum of the guides' hair particles) x 3, frame-major.
  std::vector<float> guide_points_m;
  std::vector<RigidTransform> head;  ///< per frame, world from rest
  /// Wisps: the guide index of each wisp's centre, its tetrahedra frames per frame
  /// (frame-major: origin xyz, quaternion wxyz; tetrahedra of all wisps in order), and
  /// the bindings of the braided points.
  std::vector<int32_t> wisp_guide;
  std::vector<int32_t> wisp_tetrahedron_offset;  ///< #wisps + 1
  std::vector<float> wisp_frames;                ///< frame_count x tetrahedra x 7
  std::vector<WispBinding> wisp_bindings;
  std::vector<FrameStatistics> statistics;
  int32_t settled_at_frame = -1;  ///< first frame not integrated; -1 if all were
  /// Strands per style that are not simulated themselves: fixed (rigid with the head),
  /// braided (following their wisp), and the rest (interpolated from guides).
  int64_t fixed_strands = 0, braided_strands = 0;
  double setup_s = 0;       ///< guides, body field
  double simulation_s = 0;  ///< the frames
  SimulationProfile profile;  ///< where the frames' time went, by phase
};

/// The point the head turns about: below the crown (the body's highest vertex) by the
/// head height, centred on the head's vertices (those within H of the crown) in x and z;
/// near the top of the neck.
Eigen::Vector3d head_pivot(const Points3f& body_vertices, double head_height_m);

/// Simulates `scene` under `motion`. Frame 0 is the rest state at time 0; frame f is at
/// f / fps. Deterministic whatever the thread count. Guide strands are resampled to equal
/// arcs, so repeated points in a grown strand are harmless; a guide strand with no length
/// (a single point, or all its points at one place) is left out; a root inside the body
/// is held where the head puts it, and the hair beyond it is pushed out as far as its
/// length allows. Throws hair::Error: runtime naming the strand with a non-finite point,
/// and the frame and guide where a position becomes non-finite; usage for parameters out
/// of range.
SimulationResult simulate_hair(const SimulationScene& scene, const HeadMotion& motion,
                               const SimulationParams& params);

}  // namespace hair
