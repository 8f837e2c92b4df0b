// The head synthetic hair grows on: directions over it, its hairline, its measures, the
// scalp under the hair and the roots in a region of it.
#include "hair/synth/synth_head.h"

#include <algorithm>
#include <cmath>

#include "hair/mesh/body_measures.h"

namespace hair::synth {

double radians(double degrees) { return degrees * kPi / 180.0; }

Vec3 direction(double azimuth_deg, double polar_deg) {
  double azimuth = radians(azimuth_deg), polar = radians(polar_deg);
  return {std::sin(polar) * std::sin(azimuth), std::cos(polar),
          std::sin(polar) * std::cos(azimuth)};
}

double hairline_polar_deg(double azimuth_deg) {
  return 45.0 + 70.0 * std::pow(std::abs(azimuth_deg) / 180.0, 0.8);
}

Head measure_head(const PolyMesh& body_m) {
  HeadMeasures measures = head_measures(body_m, "body");
  Triangles3i triangles = fan_triangulation(body_m.face_offsets, body_m.face_vertices);
  Head head{Vec3::Zero(), 0.5 * measures.head_width,
            TriangleMeshDistance(body_m.vertices, triangles)};
  Eigen::Vector3d low = Vec3::Constant(1e9), high = Vec3::Constant(-1e9);
  double floor_y = measures.neck_y + 0.35 * measures.head_height;
  for (Eigen::Index v = 0; v < body_m.vertices.rows(); ++v) {
    Vec3 p = body_m.vertices.row(v).cast<double>().transpose();
    if (p.y() < floor_y) continue;
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  head.radius_m = 0.5 * (high.x() - low.x());
  head.centre = {0.5 * (low.x() + high.x()), measures.head_top_y - head.radius_m,
                 0.5 * (low.z() + high.z())};
  return head;
}

Vec3 on_scalp(const Head& head, const Vec3& point, double lift_m) {
  auto nearest = head.body.nearest(point);
  Vec3 out = point - nearest.closest_point;
  if (out.norm() < 1e-9) out = point - head.centre;
  if (out.dot(point - head.centre) < 0) out = -out;
  return nearest.closest_point + lift_m * out.normalized();
}

std::vector<Vec3> root_directions(const ComponentSpec& component, int count, Rng& rng) {
  auto in_region = [&](double azimuth_deg, double polar_deg) {
    return azimuth_deg >= component.azimuth_min_deg && azimuth_deg <= component.azimuth_max_deg &&
           polar_deg >= component.polar_min_deg && polar_deg <= component.polar_max_deg &&
           polar_deg <= hairline_polar_deg(azimuth_deg);
  };
  const double golden_deg = 180.0 * (3.0 - std::sqrt(5.0));
  auto lattice = [&](int size, std::vector<Vec3>* out) {
    int found = 0;
    for (int i = 0; i < size; ++i) {
      double polar_deg = std::acos(1.0 - (2.0 * i + 1.0) / size) * 180.0 / kPi;
      double azimuth_deg = std::fmod(i * golden_deg, 360.0);
      if (azimuth_deg > 180.0) azimuth_deg -= 360.0;
      if (!in_region(azimuth_deg, polar_deg)) continue;
      ++found;
      if (out) out->push_back(direction(azimuth_deg, polar_deg));
    }
    return found;
  };
  if (count <= 0) return {};
  int size = count;
  while (lattice(size, nullptr) < count && size < 200000) size += std::max(1, size / 50);
  std::vector<Vec3> directions;
  lattice(size, &directions);
  directions.resize(std::min<size_t>(directions.size(), static_cast<size_t>(count)));
  for (Vec3& d : directions) {
    d += Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * 0.03;
    d.normalize();
  }
  return directions;
}

}  // namespace hair::synth
