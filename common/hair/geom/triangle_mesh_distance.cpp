#include "hair/geom/triangle_mesh_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nanoflann.hpp>

namespace hair {

struct TriangleMeshDistance::Index {
  /// nanoflann dataset adaptor over the triangle centroids.
  struct Centroids {
    std::vector<Eigen::Vector3d> points;
    size_t kdtree_get_point_count() const { return points.size(); }
    double kdtree_get_pt(size_t i, size_t dim) const { return points[i][static_cast<int>(dim)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
      return false;
    }
  };
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Centroids>,
                                                   Centroids, 3>;

  std::vector<std::array<Eigen::Vector3d, 3>> corners;  ///< per indexed piece
  std::vector<int32_t> source_triangle;                 ///< per indexed piece
  std::vector<double> radius;  ///< per indexed piece, its centroid-to-corner distance
  Centroids centroids;
  std::unique_ptr<Tree> tree;
  double largest_radius = 0;  ///< largest centroid-to-corner distance of a triangle
};

namespace {

double piece_radius(const std::array<Eigen::Vector3d, 3>& c) {
  Eigen::Vector3d centroid = (c[0] + c[1] + c[2]) / 3.0;
  return std::max({(c[0] - centroid).norm(), (c[1] - centroid).norm(), (c[2] - centroid).norm()});
}

}  // namespace

TriangleMeshDistance::TriangleMeshDistance(const Points3f& vertices, const Triangles3i& triangles)
    : index_(std::make_unique<Index>()) {
  std::vector<std::array<Eigen::Vector3d, 3>> all(static_cast<size_t>(triangles.rows()));
  std::vector<double> radii(all.size());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k)
      all[t][k] = vertices.row(triangles(t, k)).cast<double>().transpose();
    radii[t] = piece_radius(all[t]);
  }
  // Triangles much larger than the typical one are indexed as pieces (split at their
  // edge midpoints), so that the search bound below stays small; each piece answers
  // for its own triangle, so distances stay exact.
  std::vector<double> sorted = radii;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2),
                   sorted.end());
  double target_radius = sorted.empty() ? 0.0 : 2.0 * std::max(sorted[sorted.size() / 2], 1e-12);
  std::vector<std::pair<std::array<Eigen::Vector3d, 3>, int32_t>> stack;
  for (size_t t = 0; t < all.size(); ++t) {
    stack.push_back({all[t], static_cast<int32_t>(t)});
    while (!stack.empty()) {
      auto [c, id] = stack.back();
      stack.pop_back();
      if (piece_radius(c) > target_radius) {
        Eigen::Vector3d ab = (c[0] + c[1]) / 2, bc = (c[1] + c[2]) / 2, ca = (c[2] + c[0]) / 2;
        stack.push_back({{c[0], ab, ca}, id});
        stack.push_back({{ab, c[1], bc}, id});
        stack.push_back({{ca, bc, c[2]}, id});
        stack.push_back({{ab, bc, ca}, id});
        continue;
      }
      index_->largest_radius = std::max(index_->largest_radius, piece_radius(c));
      index_->radius.push_back(piece_radius(c));
      index_->corners.push_back(c);
      index_->source_triangle.push_back(id);
      index_->centroids.points.push_back((c[0] + c[1] + c[2]) / 3.0);
    }
  }
  index_->tree = std::make_unique<Index::Tree>(3, index_->centroids,
                                               nanoflann::KDTreeSingleIndexAdaptorParams(10));
  index_->tree->buildIndex();
}

TriangleMeshDistance::~TriangleMeshDistance() = default;
TriangleMeshDistance::TriangleMeshDistance(TriangleMeshDistance&&) noexcept = default;
TriangleMeshDistance& TriangleMeshDistance::operator=(TriangleMeshDistance&&) noexcept = default;

namespace {

/// A nanoflann result set that finds the nearest triangle piece in one pass of the k-d
/// tree: each piece whose centroid the search meets is tested at once, and the search
/// bound shrinks with the best distance d so far to d + R (R: the largest centroid-to-corner
/// distance of a piece), since no piece nearer than d has its centroid farther than that.
/// Ties in distance go to the lower triangle id, then the lower piece, whatever the order
/// of the search, so a search started from any piece (consider()) finds the same answer.
class NearestPiece {
 public:
  using DistanceType = double;
  using IndexType = uint32_t;
  NearestPiece(const Eigen::Vector3d& point, double largest_radius,
               const std::vector<std::array<Eigen::Vector3d, 3>>& corners,
               const std::vector<int32_t>& source_triangle, const std::vector<double>& radius)
      : point_(point), largest_radius_(largest_radius), corners_(corners),
        source_triangle_(source_triangle), radius_(radius) {
    best_.distance = std::numeric_limits<double>::infinity();
  }
  bool full() const { return true; }
  size_t size() const { return best_.triangle >= 0 ? 1 : 0; }
  double worstDist() const { return bound_squared_; }
  bool addPoint(double squared_distance, uint32_t piece) {
    if (squared_distance > bound_squared_) return true;
    // No point of the piece is nearer than its centroid less its radius.
    if (std::sqrt(squared_distance) - radius_[piece] > best_.distance) return true;
    consider(piece);
    return true;
  }
  /// Tests `piece` against the best so far.
  void consider(uint32_t piece) {
    const auto& c = corners_[piece];
    const Eigen::Vector3d closest = closest_point_on_triangle(point_, c[0], c[1], c[2]);
    const double distance = (closest - point_).norm();
    const int32_t id = source_triangle_[piece];
    if (distance < best_.distance ||
        (distance == best_.distance &&
         (id < best_.triangle || (id == best_.triangle && piece < best_piece_)))) {
      best_ = {distance, id, closest};
      best_piece_ = piece;
      // A little over (d + R)^2, so that rounding never drops a piece as near as d.
      const double bound = (distance + largest_radius_) * (1 + 1e-9) + 1e-12;
      bound_squared_ = bound * bound;
    }
  }
  const TriangleMeshDistance::Nearest& best() const { return best_; }
  uint32_t best_piece() const { return best_piece_; }

 private:
  const Eigen::Vector3d& point_;
  double largest_radius_;
  const std::vector<std::array<Eigen::Vector3d, 3>>& corners_;
  const std::vector<int32_t>& source_triangle_;
  const std::vector<double>& radius_;
  TriangleMeshDistance::Nearest best_;
  uint32_t best_piece_ = std::numeric_limits<uint32_t>::max();
  double bound_squared_ = std::numeric_limits<double>::infinity();
};

/// The piece nearest to this thread's last query of an index (queries come along strands,
/// so the next answer is usually that piece or one beside it): the search starts from
/// it, with its distance as the bound from the first node on.
struct LastNearest {
  const void* index = nullptr;
  uint32_t piece = 0;
};
thread_local LastNearest last_nearest;

}  // namespace

TriangleMeshDistance::Nearest TriangleMeshDistance::nearest(const Eigen::Vector3d& point) const {
  NearestPiece nearest(point, index_->largest_radius, index_->corners, index_->source_triangle,
                       index_->radius);
  // (An index made where a destroyed one was may see its piece: any piece is a valid start.)
  if (last_nearest.index == index_.get() && last_nearest.piece < index_->corners.size())
    nearest.consider(last_nearest.piece);
  index_->tree->findNeighbors(nearest, point.data(), nanoflann::SearchParams());
  last_nearest = {index_.get(), nearest.best_piece()};
  return nearest.best();
}

namespace {

/// A nanoflann result set that tests each triangle piece whose centroid the search meets
/// and stops the search at the first within `radius` of the point: whether any is, without
/// gathering, sorting or testing the rest.
class FirstWithin {
 public:
  using DistanceType = double;
  using IndexType = uint32_t;
  FirstWithin(const Eigen::Vector3d& point, double radius, double bound,
              const std::vector<std::array<Eigen::Vector3d, 3>>& corners,
              const std::vector<double>& piece_radius)
      : point_(point), radius_(radius), bound_squared_(bound * bound), corners_(corners),
        piece_radius_(piece_radius) {}
  bool full() const { return true; }
  size_t size() const { return found_ ? 1 : 0; }
  double worstDist() const { return bound_squared_; }
  bool addPoint(double squared_distance, uint32_t piece) {
    if (squared_distance >= bound_squared_) return true;
    // No point of the piece is nearer than its centroid less its own radius.
    if (std::sqrt(squared_distance) - piece_radius_[piece] > radius_) return true;
    const auto& c = corners_[piece];
    found_ = (closest_point_on_triangle(point_, c[0], c[1], c[2]) - point_).norm() <= radius_;
    return !found_;  // stop at the first
  }
  bool found() const { return found_; }

 private:
  const Eigen::Vector3d& point_;
  double radius_, bound_squared_;
  const std::vector<std::array<Eigen::Vector3d, 3>>& corners_;
  const std::vector<double>& piece_radius_;
  bool found_ = false;
};

}  // namespace

bool TriangleMeshDistance::is_within(const Eigen::Vector3d& point, double radius) const {
  FirstWithin first(point, radius, radius + index_->largest_radius, index_->corners,
                    index_->radius);
  index_->tree->radiusSearchCustomCallback(point.data(), first, nanoflann::SearchParams());
  return first.found();
}

Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  Eigen::Vector3d bp = p - b;
  double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  Eigen::Vector3d cp = p - c;
  double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  double denominator = va + vb + vc;
  if (denominator <= 0) return a;  // degenerate triangle
  double v = vb / denominator, w = vc / denominator;
  return a + ab * v + ac * w;
}

Triangles3i fan_triangulation(const std::vector<int64_t>& face_offsets,
                              const std::vector<int32_t>& face_vertices) {
  int64_t triangle_count = 0;
  for (size_t f = 0; f + 1 < face_offsets.size(); ++f)
    triangle_count += std::max<int64_t>(0, face_offsets[f + 1] - face_offsets[f] - 2);
  Triangles3i triangles(triangle_count, 3);
  Eigen::Index t = 0;
  for (size_t f = 0; f + 1 < face_offsets.size(); ++f)
    for (int64_t c = face_offsets[f] + 1; c + 1 < face_offsets[f + 1]; ++c)
      triangles.row(t++) << face_vertices[face_offsets[f]], face_vertices[c], face_vertices[c + 1];
  return triangles;
}

}  // namespace hair
