// Strands bound to wisps (braids): their bound points, seams and bridges (wisp_binding.h).
#include "hair/interp/wisp_binding.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "hair/core/error.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

}  // namespace

void bind_wisp_points(const InterpolationGuides& guides, int64_t point_count,
                      StrandBinding& binding) {
  for (size_t b = 0; b < guides.binding_point.size(); ++b) {
    int64_t row = guides.binding_point[b];
    int32_t wisp = guides.binding_wisp[b];
    if (row < 0 || row >= point_count || wisp < 0 ||
        static_cast<size_t>(wisp) + 1 >= guides.wisp_tetrahedron_offsets.size())
      throw Error::runtime("guides", "wisp binding " + std::to_string(b) +
                                         " names a point or wisp that does not exist");
    int32_t first = guides.wisp_tetrahedron_offsets[static_cast<size_t>(wisp)];
    int32_t tetrahedron = first + guides.binding_tetrahedron[b];
    if (guides.binding_tetrahedron[b] < 0 ||
        tetrahedron >= guides.wisp_tetrahedron_offsets[static_cast<size_t>(wisp) + 1])
      throw Error::runtime("guides", "wisp binding " + std::to_string(b) +
                                         " names a tetrahedron its wisp does not have");
    binding.tetrahedron[static_cast<size_t>(row)] = tetrahedron;
    binding.offset_m.row(row) = guides.binding_local_m[b].transpose();
  }
}

void bind_wisp_seams(const StrandSet& strands, const InterpolationGuides& guides,
                     double seam_length_m, StrandBinding& binding) {
  const int64_t strand_count = strands.strand_count();
  binding.seam_offsets.assign(static_cast<size_t>(strand_count) + 1, 0);
  std::vector<double> arc;
  std::vector<size_t> seams;  // index k in the bound run: tetrahedron[k] != tetrahedron[k - 1]
  for (int64_t s = 0; s < strand_count; ++s) {
    const auto si = static_cast<size_t>(s);
    const int64_t bound = strands.offsets[si] + binding.bound_from[si],
                  end = strands.offsets[si + 1];
    const auto tetrahedron_of = [&](size_t k) {
      return binding.tetrahedron[static_cast<size_t>(bound) + k];
    };
    seams.clear();
    if (seam_length_m > 0 && end - bound >= 2) {
      const auto n = static_cast<size_t>(end - bound);
      arc.assign(n, 0.0);
      for (size_t k = 1; k < n; ++k) {
        const auto row = bound + static_cast<int64_t>(k);
        arc[k] =
            arc[k - 1] + (point_of(strands.points, row) - point_of(strands.points, row - 1)).norm();
        if (tetrahedron_of(k) != tetrahedron_of(k - 1)) seams.push_back(k);
      }
      for (size_t k = 0; k < n && !seams.empty(); ++k) {
        // The nearest seam by arc; the point lies in the tetrahedron on its own side.
        double nearest_m = std::numeric_limits<double>::infinity();
        size_t seam = 0;
        for (size_t j : seams) {
          const double distance_m = std::abs(arc[k] - 0.5 * (arc[j - 1] + arc[j]));
          if (distance_m < nearest_m) {
            nearest_m = distance_m;
            seam = j;
          }
        }
        if (nearest_m >= seam_length_m) continue;
        const int32_t other = k < seam ? tetrahedron_of(seam) : tetrahedron_of(seam - 1);
        const float* rest = guides.wisp_rest_frames.data() + 7 * static_cast<size_t>(other);
        const Eigen::Quaterniond rotation(rest[3], rest[4], rest[5], rest[6]);
        const Vec3 local = rotation.normalized().conjugate() *
                           (point_of(strands.points, bound + static_cast<int64_t>(k)) -
                            Vec3(rest[0], rest[1], rest[2]));
        binding.seam_row.push_back(bound + static_cast<int64_t>(k));
        binding.seam_tetrahedron.push_back(other);
        binding.seam_weight.push_back(static_cast<float>(0.5 * (1 - nearest_m / seam_length_m)));
        for (int r = 0; r < 3; ++r) binding.seam_local_m.push_back(static_cast<float>(local[r]));
      }
    }
    binding.seam_offsets[si + 1] = static_cast<int64_t>(binding.seam_row.size());
  }
}

int64_t bridge_start(const StrandSet& strands, int64_t s, int64_t held, int64_t bound_from,
                     double length_m) {
  const int64_t begin = strands.offsets[static_cast<size_t>(s)];
  int64_t start = std::min(held, bound_from);
  if (start == 0) return 0;  // nothing held: bridged from the root
  double arc = 0;            // from point start - 1 to bound_from
  for (int64_t i = start; i <= bound_from; ++i)
    arc += (point_of(strands.points, begin + i) - point_of(strands.points, begin + i - 1)).norm();
  while (start > 1 && arc < length_m) {
    --start;
    arc += (point_of(strands.points, begin + start) - point_of(strands.points, begin + start - 1))
               .norm();
  }
  return start;
}

int64_t bridge_end(const StrandSet& strands, int64_t s, int64_t start, int64_t bound_from,
                   double length_m) {
  const int64_t begin = strands.offsets[static_cast<size_t>(s)];
  const int64_t size = strands.offsets[static_cast<size_t>(s) + 1] - begin;
  double arc = 0;  // from point max(start - 1, 0) to bound_from
  for (int64_t i = std::max<int64_t>(start, 1); i <= bound_from; ++i)
    arc += (point_of(strands.points, begin + i) - point_of(strands.points, begin + i - 1)).norm();
  while (bound_from + 2 < size && arc < length_m) {
    ++bound_from;
    arc += (point_of(strands.points, begin + bound_from) -
            point_of(strands.points, begin + bound_from - 1))
               .norm();
  }
  return bound_from;
}

void bridge_to_wisp(const StrandSet& strands, int64_t s, StrandBinding& binding) {
  const auto si = static_cast<size_t>(s);
  const int64_t begin = strands.offsets[si];
  const int64_t held = binding.held_count[si], bound_from = binding.bound_from[si];
  const int64_t from = held > 0 ? held - 1 : 0;
  std::vector<double> arc(static_cast<size_t>(bound_from - from + 1), 0.0);
  for (int64_t i = from + 1; i <= bound_from; ++i)
    arc[static_cast<size_t>(i - from)] =
        arc[static_cast<size_t>(i - from - 1)] +
        (point_of(strands.points, begin + i) - point_of(strands.points, begin + i - 1)).norm();
  for (int64_t i = held; i < bound_from; ++i) {
    const auto row = static_cast<size_t>(begin + i);
    binding.parameter[row] =
        arc.back() > 0 ? static_cast<float>(arc[static_cast<size_t>(i - from)] / arc.back()) : 0.0f;
    binding.offset_m.row(begin + i) = strands.points.row(begin + i);
  }
  binding.bridged[si] = 1;
  binding.method[si] = InterpolationMethod::braided;
}

}  // namespace hair
