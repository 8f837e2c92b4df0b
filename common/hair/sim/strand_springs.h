#pragma once
// The springs of an altitude strand as linear forms of its particles' positions, and the
// banded symmetric system they assemble into: shared by the time step
// (strand_dynamics.cpp), the sag-free rest solve (sag_free_rest.cpp) and the measure of
// the chain's rigidity (strand_stiffness.cpp). Internal to sim/.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "hair/sim/altitude_strand.h"

namespace hair::strand_springs {

/// Particles a spring reaches along the sequence: q_k to q_k+3, so 3 particles, and
/// the band of the system holds 3 * 3 + 2 super-diagonals.
constexpr int kParticleReach = 3;
constexpr int kBandwidth = 3 * kParticleReach + 2;

/// Where a LinearSpring comes from: a two-particle spring or a tetrahedron's altitude.
enum class SpringSource : uint8_t { two_particle, altitude };

/// A spring as a linear form: length = direction . sum_i weight_i x_{particle_i}.
struct LinearSpring {
  std::array<int32_t, 4> particle{};
  std::array<double, 4> weight{};
  int count = 0;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  double length_m = 0, rest_length_m = 0, stiffness = 0, damping = 0;
  SpringSource source = SpringSource::two_particle;
  int32_t index = 0;  ///< into strand.springs or strand.tetrahedra
  int which = 0;      ///< an altitude: which of the seven (ChainTetrahedron::rest_altitude_m)
};

/// Calls `visit(LinearSpring)` for every spring of the strand at `position_m`, anchors
/// excluded, with each spring's stiffness and damping times `stiffness_scale`; a spring
/// of zero length (no direction) is left out. Each tetrahedron contributes the altitude
/// with the most robust normal at `position_m` (Selle et al.), sharing its spring with
/// the second where that is within kAltitudeBlendFactor of it.
template <typename Visit>
void for_each_spring(const AltitudeStrand& strand, double stiffness_scale,
                     const std::vector<Eigen::Vector3d>& position_m, Visit&& visit) {
  // A scaled spring's damping stays the same fraction of critical: sqrt(scale) times.
  const double damping_scale = stiffness_scale == 1 ? 1.0 : std::sqrt(stiffness_scale);
  LinearSpring linear;
  linear.count = 2;
  linear.source = SpringSource::two_particle;
  for (size_t s = 0; s < strand.springs.size(); ++s) {
    const TwoParticleSpring& spring = strand.springs[s];
    Eigen::Vector3d span =
        position_m[static_cast<size_t>(spring.b)] - position_m[static_cast<size_t>(spring.a)];
    double length = span.norm();
    if (!(length > 1e-12)) continue;
    linear.particle[0] = spring.a;
    linear.particle[1] = spring.b;
    linear.weight[0] = -1;
    linear.weight[1] = 1;
    linear.direction = span / length;
    linear.length_m = length;
    linear.rest_length_m = spring.rest_length_m;
    linear.stiffness = spring.stiffness_n_m * stiffness_scale;
    linear.damping = spring.damping_n_s_m * damping_scale;
    linear.index = static_cast<int32_t>(s);
    visit(linear);
  }
  linear.count = 4;
  linear.source = SpringSource::altitude;
  for (size_t t = 0; t < strand.tetrahedra.size(); ++t) {
    const ChainTetrahedron& tetrahedron = strand.tetrahedra[t];
    std::array<Eigen::Vector3d, 4> corners;
    for (size_t i = 0; i < 4; ++i)
      corners[i] = position_m[static_cast<size_t>(tetrahedron.particle[i])];
    const RobustAltitudes robust = robust_altitudes(corners);
    if (robust.best < 0) continue;
    // (Most tetrahedra have no second within the factor: no square root for them.)
    const double second_share =
        robust.second >= 0 &&
                robust.second_size * kAltitudeBlendFactor * kAltitudeBlendFactor > robust.best_size
            ? second_altitude_share(std::sqrt(robust.second_size / robust.best_size))
            : 0.0;
    linear.particle = tetrahedron.particle;
    linear.index = static_cast<int32_t>(t);
    for (int pick = 0; pick < (second_share > 0 ? 2 : 1); ++pick) {
      const int which = pick == 0 ? robust.best : robust.second;
      const double share = pick == 0 ? 1 - second_share : second_share;
      Altitude altitude = tetrahedron_altitude(corners, which);
      linear.weight = altitude.weight;
      linear.direction = altitude.direction;
      linear.length_m = altitude.length_m;
      linear.rest_length_m = tetrahedron.rest_altitude_m[static_cast<size_t>(which)];
      linear.stiffness = share * tetrahedron.stiffness_n_m * stiffness_scale;
      linear.damping = share * tetrahedron.damping_n_s_m * damping_scale;
      linear.which = which;
      visit(linear);
    }
  }
}

/// A spring's elastic energy, k (l - L)^2 / 2.
inline double spring_energy(const LinearSpring& spring) {
  const double stretch = spring.length_m - spring.rest_length_m;
  return 0.5 * spring.stiffness * stretch * stretch;
}

/// A symmetric positive definite system over the free particles (those from `first_free`
/// on, three unknowns each): its matrix in LAPACK upper band storage, A(i, j) for i <= j at
/// band[kBandwidth + i - j + j * (kBandwidth + 1)], and its right-hand side.
class BandSystem {
 public:
  BandSystem(std::vector<double>& band, std::vector<double>& rhs, int32_t first_free)
      : band_(band), rhs_(rhs), first_free_(first_free) {}

  /// Zeroed storage for `particle_count` particles of which the first `first_free` are
  /// not unknowns.
  static void reset(std::vector<double>& band, std::vector<double>& rhs, int32_t particle_count,
                    int32_t first_free) {
    const auto n = static_cast<size_t>(3 * (particle_count - first_free));
    band.assign(static_cast<size_t>(kLdab) * n, 0.0);
    rhs.assign(n, 0.0);
  }

  int32_t first_free() const { return first_free_; }

  /// Adds scale * d d^T to the block (qa, qb), qa <= qb: the whole block lies in the
  /// upper triangle when qa < qb, its upper half when qa == qb. `outer` holds d d^T
  /// (column-major) of the spring at hand.
  void add_outer(int32_t qa, int32_t qb, double scale, const Eigen::Matrix3d& outer) {
    int row0 = 3 * (qa - first_free_), col0 = 3 * (qb - first_free_);
    for (int c = 0; c < 3; ++c) {
      int j = col0 + c;
      double* column = band_.data() + kBandwidth - j + static_cast<ptrdiff_t>(j) * kLdab + row0;
      const double* outer_column = outer.data() + 3 * c;
      if (qa == qb) {
        for (int r = 0; r <= c; ++r) column[r] += scale * outer_column[r];
      } else {
        for (int r = 0; r < 3; ++r) column[r] += scale * outer_column[r];
      }
    }
  }
  /// Adds `value` to the diagonal of particle q's block.
  void add_diagonal(int32_t q, double value) {
    for (int r = 0; r < 3; ++r) {
      int i = 3 * (q - first_free_) + r;
      band_[static_cast<size_t>(kBandwidth + i * kLdab)] += value;
    }
  }
  void add_rhs(int32_t q, const Eigen::Vector3d& value) {
    int row0 = 3 * (q - first_free_);
    for (int r = 0; r < 3; ++r) rhs_[static_cast<size_t>(row0 + r)] += value[r];
  }

  /// Adds `scale` w_a w_b d d^T for every pair of the spring's free particles: the
  /// spring's J^T J times scale, where J is its length's gradient.
  void add_spring_outer(const LinearSpring& spring, double scale) {
    const Eigen::Matrix3d outer = spring.direction * spring.direction.transpose();
    for (int a = 0; a < spring.count; ++a) {
      int32_t qa = spring.particle[static_cast<size_t>(a)];
      if (qa < first_free_) continue;
      for (int b = a; b < spring.count; ++b) {
        int32_t qb = spring.particle[static_cast<size_t>(b)];
        if (qb < first_free_) continue;
        double coefficient =
            scale * spring.weight[static_cast<size_t>(a)] * spring.weight[static_cast<size_t>(b)];
        if (qa <= qb)
          add_outer(qa, qb, coefficient, outer);
        else
          add_outer(qb, qa, coefficient, outer);
      }
    }
  }

  static constexpr int kLdab = kBandwidth + 1;

 private:
  std::vector<double>& band_;
  std::vector<double>& rhs_;
  int32_t first_free_;
};

/// The solution of a solved BandSystem for particle q (q >= first_free).
inline Eigen::Vector3d solved_particle(const std::vector<double>& rhs, int32_t first_free,
                                       int32_t q) {
  const auto row0 = static_cast<size_t>(3 * (q - first_free));
  return {rhs[row0], rhs[row0 + 1], rhs[row0 + 2]};
}

}  // namespace hair::strand_springs
