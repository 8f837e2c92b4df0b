#pragma once
// The steps of simulate_hair() before the first frame (hair_simulation.h): which style
// each cluster is simulated as, the body's distance field, the plan of guides and wisps,
// and the simulated strands built from them. Internal to sim/.

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "hair/geom/body_sdf.h"
#include "hair/sim/altitude_strand.h"
#include "hair/sim/hair_simulation.h"
#include <string>

#include "hair/sim/strand_dynamics.h"
#include "hair/sim/strand_stiffness.h"

namespace hair {

/// One simulated strand (a guide or a wisp's centre) during the run.
struct RunningStrand {
  AltitudeStrand model;
  StrandState state;
  std::vector<StrandAnchor> anchors;                ///< wisp centres
  std::vector<Eigen::Vector3d> anchor_rest_m;       ///< the anchors at rest
  std::vector<Eigen::Vector3d> acceleration_m_s2;   ///< repulsion, per particle
  size_t first_output_point = 0;                    ///< of this strand's hair particles in a frame
  std::vector<Eigen::Vector3d> frame_start_m;       ///< positions at the start of the frame
  double penetration_m = 0;                         ///< deepest in this frame
  bool failed = false;
};

/// Each braided cluster's wisp centre strand at rest, by cluster.
using WispCentres = std::map<int32_t, std::vector<Eigen::Vector3d>>;

/// The style each cluster is simulated by: its own, or normal for every cluster with
/// strands when the style rules are off (`by_style` false).
std::vector<int8_t> styles_to_simulate(const std::vector<int8_t>& cluster_style, bool by_style);

/// The body's signed distance field over the hair that is simulated at rest (every
/// cluster but the fixed ones), with a margin of H/4 for its swing; none when no hair is
/// simulated.
std::optional<BodySdf> body_field_over_hair(const SimulationScene& scene,
                                            const std::vector<int8_t>& simulated_style,
                                            const SimulationParams& params);

/// Guide planning: fills result.plan (plan_guides), gathers each braided cluster's wisp
/// and returns its centre strand. A braided cluster whose strands do not gather into a
/// bundle is simulated as fixed or normal hair instead (result.simulated_style), and the
/// plan is made again without it; the strands of a wisp that end away from the braid get
/// guides of their own, in proportion, as plan_guides gives them. Counts
/// result.fixed_strands.
WispCentres plan_simulation(const SimulationScene& scene, const SimulationParams& params,
                            const std::optional<BodySdf>& body, SimulationResult& result);

/// The strand guides of result.plan resampled to equal arcs (short hair with longer
/// segments) as altitude strands with the springs of `stiffness`, appended to
/// result.guides and returned in that order; a guide strand with no length is left out.
/// With body collisions, each particle after the root closer to the body than the
/// clearance is moved out to it first (resampling cuts corners into the body), so that
/// the rest shape is one the collisions keep.
std::vector<RunningStrand> build_strand_guides(const SimulationScene& scene,
                                               const SimulationParams& params,
                                               const StrandStiffness& stiffness,
                                               const std::optional<BodySdf>& body,
                                               SimulationResult& result);

/// Each wisp of result.plan: its centre strand, hung by springs from its members'
/// anchors, appended to result.guides and to `running`; every point of its members from
/// the braid on bound to the nearest tetrahedron of the centre strand
/// (result.wisp_bindings, wisp_guide, wisp_tetrahedron_offset). Counts
/// result.braided_strands.
void build_wisps(const SimulationScene& scene, const StrandStiffness& stiffness, const WispCentres& centres, SimulationResult& result,
                 std::vector<RunningStrand>& running);

/// Makes every running strand's groom its rest under gravity as the head holds it at
/// time 0 (make_sag_free: tension along the hair, a support force for the rest); logs the
/// share of the weight the strands carry along themselves.
void make_rests_sag_free(const SimulationParams& params, const HeadMotion& motion,
                         const std::string& source, std::vector<RunningStrand>& running);

/// The orthonormal frame of a centre-strand tetrahedron: origin at its first corner, x
/// along its first edge, y toward its third corner.
Eigen::Matrix3d tetrahedron_frame(const Eigen::Vector3d& q0, const Eigen::Vector3d& q1,
                                  const Eigen::Vector3d& q2);

}  // namespace hair
