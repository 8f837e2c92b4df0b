#include "hair/sim/sag_free_rest.h"

#include <algorithm>
#include <cmath>

#include "hair/sim/strand_springs.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;
using strand_springs::for_each_spring;
using strand_springs::LinearSpring;

}  // namespace

SagFreeReport make_sag_free(AltitudeStrand& strand, const StrandMaterial& material,
                            const Vec3& gravity_m_s2) {
  SagFreeReport report;
  const int32_t first_free = strand.kinematic_count, count = strand.particle_count();
  const std::vector<Vec3>& groom = strand.rest_m;
  strand.rest_support_n.assign(static_cast<size_t>(count), Vec3::Zero());
  const Vec3 down = gravity_m_s2.norm() > 0 ? Vec3(gravity_m_s2.normalized()) : Vec3::Zero();
  // Every spring rests in the groom.
  for (TwoParticleSpring& spring : strand.springs)
    spring.rest_length_m =
        (groom[static_cast<size_t>(spring.b)] - groom[static_cast<size_t>(spring.a)]).norm();
  for (ChainTetrahedron& tetrahedron : strand.tetrahedra) {
    std::array<Vec3, 4> corners;
    for (size_t i = 0; i < 4; ++i) corners[i] = groom[static_cast<size_t>(tetrahedron.particle[i])];
    for (int which = 0; which < 7; ++which)
      tetrahedron.rest_altitude_m[static_cast<size_t>(which)] =
          tetrahedron_altitude(corners, which).length_m;
  }
  // Ghosts are held up by their support.
  for (int32_t q = first_free; q < count; ++q) {
    auto k = static_cast<size_t>(q);
    const Vec3 weight = strand.mass_kg[k] * gravity_m_s2;
    report.weight_n += weight.norm();
    if (strand.is_ghost[k]) {
      strand.rest_support_n[k] = -weight;
      report.support_n += weight.norm();
    }
  }
  // Tensions from the tip to the root.
  const int32_t hairs = strand.hair_count();
  std::vector<double> tension(static_cast<size_t>(std::max(0, hairs - 1)), 0.0);
  Vec3 pull_beyond = Vec3::Zero();  // the segment beyond's pull on the particle at hand
  for (int32_t i = hairs - 1; i >= 0; --i) {
    const auto q = static_cast<size_t>(strand.hair_particle[static_cast<size_t>(i)]);
    if (static_cast<int32_t>(q) < first_free) break;
    const Vec3 load = strand.mass_kg[q] * gravity_m_s2 + pull_beyond;
    Vec3 carried = Vec3::Zero();
    if (i > 0) {
      const Vec3 inner = groom[static_cast<size_t>(strand.hair_particle[static_cast<size_t>(i) - 1])];
      const Vec3 direction = (groom[q] - inner).normalized();
      const double t = std::max(0.0, load.dot(direction));
      tension[static_cast<size_t>(i) - 1] = t;
      carried = t * direction;
      pull_beyond = carried;  // the segment pulls its inner particle towards this one
    }
    strand.rest_support_n[q] = carried - load;
    report.support_n -= strand.rest_support_n[q].dot(down);
  }
  // The hair segments' springs stretched by their tension at the groom.
  for (TwoParticleSpring& spring : strand.springs) {
    if (!spring.hair_segment) continue;
    // The segment's index: the hair particle at its inner end.
    const auto inner = std::find(strand.hair_particle.begin(), strand.hair_particle.end(), spring.a);
    if (inner == strand.hair_particle.end()) continue;
    const auto i = static_cast<size_t>(inner - strand.hair_particle.begin());
    if (i >= tension.size() || tension[i] <= 0) continue;
    const double stiffness = spring.stiffness_n_m * material.stiffness_scale;
    if (!(stiffness > 0)) continue;
    const double stretch = tension[i] / stiffness;
    spring.rest_length_m -= stretch;
    report.largest_tension_strain =
        std::max(report.largest_tension_strain, stretch / spring.rest_length_m);
  }
  return report;
}

std::vector<Vec3> strand_static_force(const AltitudeStrand& strand, const StrandMaterial& material,
                                      const std::vector<Vec3>& position_m,
                                      const Vec3& gravity_m_s2) {
  const int32_t first_free = strand.kinematic_count, count = strand.particle_count();
  std::vector<Vec3> force(static_cast<size_t>(count), Vec3::Zero());
  for (int32_t q = first_free; q < count; ++q) {
    auto k = static_cast<size_t>(q);
    force[k] = strand.mass_kg[k] * gravity_m_s2;
    if (!strand.rest_support_n.empty()) force[k] += strand.rest_support_n[k];
  }
  for_each_spring(strand, material.stiffness_scale, position_m, [&](const LinearSpring& spring) {
    const double tension = spring.stiffness * (spring.length_m - spring.rest_length_m);
    for (int i = 0; i < spring.count; ++i) {
      const int32_t q = spring.particle[static_cast<size_t>(i)];
      if (q >= first_free)
        force[static_cast<size_t>(q)] -=
            tension * spring.weight[static_cast<size_t>(i)] * spring.direction;
    }
  });
  return force;
}

}  // namespace hair
