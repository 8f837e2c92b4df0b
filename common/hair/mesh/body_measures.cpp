#include "hair/mesh/body_measures.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "hair/core/error.h"

namespace hair {

HeadMeasures head_measures(const PolyMesh& body, const std::string& file) {
  constexpr int slice_count = 300;
  constexpr double shoulder_factor = 1.6;
  constexpr double narrowing_factor = 0.7;
  double top = body.vertices.col(1).maxCoeff();
  double bottom = body.vertices.col(1).minCoeff();
  double height = top - bottom;
  if (!(height > 0)) throw Error::bad_input(file, "body mesh has no height along +Y");

  double thickness = height / slice_count;
  constexpr double infinity = std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector2d> low(slice_count, Eigen::Vector2d::Constant(infinity));
  std::vector<Eigen::Vector2d> high(slice_count, Eigen::Vector2d::Constant(-infinity));
  // Cross-sections of the surface: every edge adds its crossing of each slice's centre
  // plane, so the width does not depend on how densely the mesh is sampled.
  auto slice_centre = [&](int slice) { return top - (slice + 0.5) * thickness; };
  for (int64_t f = 0; f < body.face_count(); ++f) {
    auto face = body.face(f);
    for (size_t c = 0; c < face.size(); ++c) {
      Eigen::Vector3d a = body.vertices.row(face[c]).cast<double>().transpose();
      Eigen::Vector3d b = body.vertices.row(face[(c + 1) % face.size()]).cast<double>().transpose();
      if (a.y() < b.y()) std::swap(a, b);  // a above b
      int first = std::max(0, static_cast<int>(std::ceil((top - a.y()) / thickness - 0.5)));
      int last =
          std::min(slice_count - 1, static_cast<int>(std::floor((top - b.y()) / thickness - 0.5)));
      for (int slice = first; slice <= last; ++slice) {
        double t = a.y() > b.y() ? (a.y() - slice_centre(slice)) / (a.y() - b.y()) : 0.0;
        Eigen::Vector3d p = a + t * (b - a);
        Eigen::Vector2d xz(p.x(), p.z());
        low[slice] = low[slice].cwiseMin(xz);
        high[slice] = high[slice].cwiseMax(xz);
      }
    }
  }
  std::vector<double> width(slice_count, -1);  // -1: the surface does not reach the slice
  for (int s = 0; s < slice_count; ++s)
    if (high[s].x() >= low[s].x()) width[s] = (high[s] - low[s]).maxCoeff();

  HeadMeasures measures;
  measures.head_top_y = top;
  int widest_head = -1;
  int neck = -1;
  for (int s = 0; s < slice_count; ++s) {
    if (width[s] < 0) continue;
    bool narrowed = neck >= 0 && width[neck] <= narrowing_factor * width[widest_head];
    if (widest_head < 0 || (!narrowed && width[s] >= width[widest_head])) {
      widest_head = s;  // still growing towards the head's widest slice
      neck = -1;
      continue;
    }
    if (neck < 0 || width[s] < width[neck]) neck = s;
    narrowed = width[neck] <= narrowing_factor * width[widest_head];
    if (narrowed && width[s] > shoulder_factor * width[widest_head]) break;  // shoulders
  }
  if (neck < 0) neck = slice_count - 1;
  measures.head_width = width[widest_head];
  measures.neck_width = std::max(0.0, width[neck]);
  measures.neck_y = top - (neck + 0.5) * thickness;
  measures.head_height = measures.head_top_y - measures.neck_y;
  return measures;
}

}  // namespace hair
