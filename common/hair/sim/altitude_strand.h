#pragma once
// The altitude mass-spring strand of Selle, Lentine and Fedkiw 2008 ("A mass spring model
// for hair simulation"), which the paper simulates hair with (section 5.2): the hair's
// particles, extra ("ghost") particles where consecutive ones are nearly collinear, and
// the springs of the chain of tetrahedra they make.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace hair {

/// The kinds of two-particle springs along the particle sequence q_0, q_1, ...: edge
/// (q_k, q_k+1), bend (q_k, q_k+2), torsion (q_k, q_k+3). Together they make the
/// tetrahedra (q_k .. q_k+3); altitude springs (one per tetrahedron) keep those from
/// collapsing or inverting.
enum class SpringKind : uint8_t { edge, bend, torsion };

/// A spring between two particles of the sequence, its rest length from the rest shape.
struct TwoParticleSpring {
  int32_t a = 0, b = 0;
  double rest_length_m = 0;
  SpringKind kind = SpringKind::edge;
  bool hair_segment = false;  ///< the hair between two hair particles (an edge)
  double stiffness_n_m = 0;   ///< set by StrandStiffness::assign() (strand_stiffness.h)
  double damping_n_s_m = 0;
};

/// A tetrahedron (q_k, q_k+1, q_k+2, q_k+3) of the chain, with the rest lengths of its
/// seven altitudes: point 0..3 to the opposite face, then the edge pairs (01, 23),
/// (02, 13), (03, 12). Each is signed at rest (positive or negative by the orientation of
/// the face's or edge pair's normal), so an inverted tetrahedron is pushed back.
struct ChainTetrahedron {
  std::array<int32_t, 4> particle{};
  std::array<double, 7> rest_altitude_m{};
  double stiffness_n_m = 0;  ///< of its altitude spring, set by StrandStiffness::assign()
  double damping_n_s_m = 0;
};

/// Options of build_altitude_strand().
struct AltitudeStrandOptions {
  /// A ghost particle is inserted before a hair particle where the tetrahedron it would
  /// close with the three previous particles has a quality (6 sqrt 2 V / l_rms^3: 1 for
  /// a regular tetrahedron, 0 for a flat one) below this.
  double min_tetrahedron_quality = 0.15;
  /// A ghost sits beside the middle of its hair segment, this many segment lengths off it.
  double ghost_offset = 0.5;
  /// Share of its hair segment's mass that a ghost particle takes (the segment's two hair
  /// particles share the rest), so the strand weighs what its hair does.
  double ghost_mass_share = 1.0 / 3.0;
  /// The root is clamped: a second ghost goes before the root in the sequence, beside the
  /// first segment a quarter turn from the ghost after the root, and all three are
  /// kinematic. (The root and one ghost alone leave the strand free to turn about the
  /// line through them: a hinge, not a follicle.) false: no leading ghost, and the root
  /// and its ghost are kinematic (a wisp's centre, which hangs from anchors, sets none).
  bool clamped_root = true;
};

/// The particles and springs of one strand. Hair particle i is sequence particle
/// hair_particle[i]; the others are ghosts. The first `kinematic_count` particles of the
/// sequence (the ghost before the root, the root and the ghost after it) are not
/// simulated: they move with the head.
struct AltitudeStrand {
  std::vector<Eigen::Vector3d> rest_m;  ///< rest positions of the sequence, hair and ghosts
  std::vector<double> mass_kg;          ///< per sequence particle
  std::vector<int32_t> hair_particle;   ///< sequence index of each hair particle
  std::vector<uint8_t> is_ghost;        ///< per sequence particle
  int32_t kinematic_count = 0;          ///< leading sequence particles moved with the head
  std::vector<TwoParticleSpring> springs;
  std::vector<ChainTetrahedron> tetrahedra;
  /// Rest lengths of the hair segments (hair particle i to i + 1), for strain limiting.
  std::vector<double> hair_segment_m;
  /// Per sequence particle, the force that holds it up at rest (sag_free_rest.h), in the
  /// frame of the head's rest pose: it turns with the head. Empty: none.
  std::vector<Eigen::Vector3d> rest_support_n;

  int32_t particle_count() const { return static_cast<int32_t>(rest_m.size()); }
  int32_t hair_count() const { return static_cast<int32_t>(hair_particle.size()); }
  /// Ghost particles inserted.
  int32_t ghost_count() const { return particle_count() - hair_count(); }
};

/// Builds the strand of the hair particles `hair_points_m` (root first, at least two,
/// no two consecutive ones closer than 1e-9 m), its springs without their constants
/// (StrandStiffness::assign() in strand_stiffness.h gives them). Each hair segment
/// weighs `mass_per_length_kg_m` times its length, shared by its two hair particles and
/// its ghost if it has one (`ghost_mass_share`). A ghost always follows
/// the root, so that the root's direction is held by the head; the root and that ghost
/// are kinematic. Further ghosts go where the chain's tetrahedra would be flat (straight
/// or gently curved hair); curly hair needs few. With `clamped_root`, a ghost before the
/// root too (the three kinematic).
///
/// Ghost placement: beside the middle of the segment it splits, at the angle about the
/// segment (of twelve) that makes the worst of the two new tetrahedra best.
/// Deterministic. Throws std::invalid_argument on fewer than two points, a non-finite one
/// or a zero-length segment (callers resample the strands first).
AltitudeStrand build_altitude_strand(const std::vector<Eigen::Vector3d>& hair_points_m,
                                     double mass_per_length_kg_m,
                                     const AltitudeStrandOptions& options = {});

/// Quality of the tetrahedron (a, b, c, d): 6 sqrt(2) |V| / l_rms^3, 1 for a regular one,
/// 0 for a flat one; 0 when all edges are zero.
double tetrahedron_quality(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                           const Eigen::Vector3d& c, const Eigen::Vector3d& d);

/// One altitude of a tetrahedron as a linear form of its four corners: length =
/// direction . sum_i weight[i] * x[i], with weights summing to zero.
struct Altitude {
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  ///< unit
  std::array<double, 4> weight{};                       ///< per corner of the tetrahedron
  double length_m = 0;                                  ///< signed
  /// Size of the face (twice its area) or of the edge pair (|e1 x e2|): the robustness of
  /// the direction. Selle et al. take the altitude whose normal is the most robust.
  double robustness_m2 = 0;
};

/// Which of the seven altitudes of (x0, x1, x2, x3) has the largest robustness_m2: the
/// one Selle et al. use. Cheaper than computing all seven with tetrahedron_altitude().
int most_robust_altitude(const std::array<Eigen::Vector3d, 4>& x);

/// The two most robust altitudes of (x0, x1, x2, x3) and their squared robustness
/// (-1 and 0 where there is none).
struct RobustAltitudes {
  int best = -1, second = -1;
  double best_size = 0, second_size = 0;  ///< robustness_m2 squared
};
RobustAltitudes robust_altitudes(const std::array<Eigen::Vector3d, 4>& x);

/// Where the second most robust altitude is within this factor of the most robust, the
/// tetrahedron's altitude spring is shared between the two, from nothing at this factor
/// to half each when they tie: the spring changes smoothly as they trade places (Selle et
/// al.'s single choice jumps, and two nearly equal altitudes took turns step after step,
/// a chatter that never came to rest). 3%: a cantilever within 10% of Euler-Bernoulli
/// in every direction; 10% does no better and costs a tenth more time per frame.
constexpr double kAltitudeBlendFactor = 1.03;
/// The second altitude's share of the spring for robustness ratio second / best.
double second_altitude_share(double robustness_ratio);

/// Altitude `which` (0..6, as ChainTetrahedron::rest_altitude_m) of (x0, x1, x2, x3).
/// Point-face altitudes weigh the face's corners by the barycentric coordinates of the
/// point's projection, clamped into the face; edge-edge ones by the closest points' line
/// parameters, clamped into the edges.
Altitude tetrahedron_altitude(const std::array<Eigen::Vector3d, 4>& x, int which);

}  // namespace hair
