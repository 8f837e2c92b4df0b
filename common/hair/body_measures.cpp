#include "hair/body_measures.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "hair/error.h"

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
  for (Eigen::Index v = 0; v < body.vertices.rows(); ++v) {
    int slice = std::min(slice_count - 1, static_cast<int>((top - body.vertices(v, 1)) / thickness));
    Eigen::Vector2d xz(body.vertices(v, 0), body.vertices(v, 2));
    low[slice] = low[slice].cwiseMin(xz);
    high[slice] = high[slice].cwiseMax(xz);
  }
  // A slice's width spans its vertices and its two neighbours', so that thin slices
  // holding a few vertices do not read as narrow.
  std::vector<double> width(slice_count, -1);  // -1: empty
  for (int s = 0; s < slice_count; ++s) {
    Eigen::Vector2d lowest = low[s], highest = high[s];
    for (int n : {s - 1, s + 1})
      if (n >= 0 && n < slice_count) {
        lowest = lowest.cwiseMin(low[n]);
        highest = highest.cwiseMax(high[n]);
      }
    if (high[s].x() >= low[s].x()) width[s] = (highest - lowest).maxCoeff();
  }

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
