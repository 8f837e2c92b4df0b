// Every grown point in one frame from the binding (interpolate_frame()): the table of the
// guides' particles and frames, the rigid frames, and each strand's points from them.
#include "hair/interp/strand_interpolation.h"

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "hair/interp/interpolation_kernel.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// Per guide particle in a frame's table: eight 4-float columns (interpolation_kernel.h's
/// kParticleFloats: of the position and of each of the frame's three columns, P_j and
/// then Q_j), so that a point is a few SIMD multiply-adds per guide.
constexpr int kColumns = 8;
static_assert(kColumns * 4 == kParticleFloats);
using Column = Eigen::Array4f;

/// Per guide particle of one frame: its position and frame (see interpolate_frame()).
void guide_frame_table(const StrandBinding& binding, const GuideFrame& frame, Column* table) {
  const float* rest_points = binding.guide_rest_points.data();
  const int64_t guides = static_cast<int64_t>(binding.guide_offsets.size()) - 1;
  const Eigen::Quaterniond head = frame.head.rotation.normalized();
  auto put = [&](int64_t row, const Eigen::Quaterniond& q) {
    Eigen::Matrix3f m = q.toRotationMatrix().cast<float>();
    Column* out = table + row * kColumns;
    const float* p = frame.guide_points_m + 3 * row;
    out[0] = Column(p[0], p[1], p[2], 0);
    for (int c = 0; c < 3; ++c) out[2 + 2 * c] = Column(m(0, c), m(1, c), m(2, c), 0);
  };
  std::vector<Eigen::Quaterniond> segment;
  for (int64_t g = 0; g < guides; ++g) {
    const int64_t first = binding.guide_offsets[static_cast<size_t>(g)];
    const int64_t count = binding.guide_offsets[static_cast<size_t>(g) + 1] - first;
    segment.resize(static_cast<size_t>(count - 1));
    for (int64_t j = 0; j + 1 < count; ++j) {
      const float* r0 = rest_points + 3 * (first + j);
      const float* p0 = frame.guide_points_m + 3 * (first + j);
      Vec3 rest_direction(r0[3] - r0[0], r0[4] - r0[1], r0[5] - r0[2]);
      Vec3 now(p0[3] - p0[0], p0[4] - p0[1], p0[5] - p0[2]);
      Vec3 carried = head * rest_direction;
      Eigen::Quaterniond turn = Eigen::Quaterniond::Identity();
      if (carried.squaredNorm() > 0 && now.squaredNorm() > 0)
        turn = Eigen::Quaterniond::FromTwoVectors(carried, now);
      segment[static_cast<size_t>(j)] = (turn * head).normalized();
    }
    put(first, head);
    for (int64_t k = 1; k < count; ++k) {
      Eigen::Quaterniond q = segment[static_cast<size_t>(k - 1)];
      if (k + 1 < count) {
        Eigen::Quaterniond next = segment[static_cast<size_t>(k)];
        if (q.dot(next) < 0) next.coeffs() = -next.coeffs();
        q.coeffs() += next.coeffs();
        q.normalize();
      }
      put(first + k, q);
    }
    // Particle k's record as the kernel reads it: the columns C_k and the steps B_k =
    // C_k+1 - C_k make C(u) = C_k + (u S - k) B_k on the segment (S segments), so the
    // record holds, per column, P_k = C_k - k B_k and then Q_k = S B_k, and C(u) = P_k +
    // u Q_k.
    const auto segments = static_cast<float>(count - 1);
    for (int64_t k = 0; k < count; ++k) {
      Column* here = table + (first + k) * kColumns;
      for (int c = 0; c < 8; c += 2) {
        const Column step = k + 1 < count ? Column(here[kColumns + c] - here[c]) : Column::Zero();
        here[c] -= static_cast<float>(k) * step;
        here[c + 1] = segments * step;
      }
    }
  }
}

}  // namespace

void interpolate_frame(const StrandBinding& binding, const StrandSet& strands,
                       const GuideFrame& frame, std::vector<float>& points_m) {
  const int64_t strand_count = strands.strand_count();
  points_m.resize(static_cast<size_t>(strands.point_count()) * 3);
  // The table on a 64-byte boundary (the kernel's loads are aligned).
  std::vector<Column> table_storage(
      static_cast<size_t>(binding.guide_rest_points.rows()) * kColumns + 3);
  Column* table = table_storage.data() +
                  (4 - reinterpret_cast<uintptr_t>(table_storage.data()) / sizeof(Column) % 4) % 4;
  guide_frame_table(binding, frame, table);
  // Rigid frames in transform_points()'s layout: per wisp tetrahedron, where it is now;
  // and the head.
  auto put_frame = [](float* record, const Eigen::Vector3f& origin, const Eigen::Matrix3f& m) {
    for (int r = 0; r < 3; ++r) {
      record[r] = origin[r];
      for (int c = 0; c < 3; ++c) record[4 + 4 * c + r] = m(r, c);
    }
  };
  const auto tetrahedron_count = static_cast<size_t>(binding.tetrahedron_count);
  std::vector<float> tetrahedron_frames(tetrahedron_count * kFrameFloats);
  for (int64_t t = 0; t < binding.tetrahedron_count; ++t) {
    const float* in = frame.wisp_frames + 7 * t;
    Eigen::Matrix3f m =
        Eigen::Quaternionf(in[3], in[4], in[5], in[6]).normalized().toRotationMatrix();
    put_frame(tetrahedron_frames.data() + t * kFrameFloats, Eigen::Vector3f(in[0], in[1], in[2]),
              m);
  }
  float head_frame[kFrameFloats] = {};
  put_frame(head_frame, frame.head.translation_m.cast<float>(),
            frame.head.rotation.normalized().toRotationMatrix().cast<float>());
  const float* offset = binding.offset_m.data();
  float* out = points_m.data();

#pragma omp parallel for schedule(dynamic, 256)
  for (int64_t s = 0; s < strand_count; ++s) {
    const auto si = static_cast<size_t>(s);
    const int64_t begin = strands.offsets[si];
    const int64_t end = strands.offsets[si + 1];
    const int64_t interpolated = begin + binding.interpolated_from[si];
    const int64_t bound = begin + binding.bound_from[si];
    // Held: R p + t.
    transform_points(head_frame, nullptr, offset + 3 * begin, interpolated - begin,
                     out + 3 * begin);
    // Bound: origin + R_tet local.
    transform_points(tetrahedron_frames.data(), binding.tetrahedron.data() + bound,
                     offset + 3 * bound, end - bound, out + 3 * bound);
    // Near a seam between two tetrahedra: (1 - w)(o_own + R_own l_own) + w (o + R l) of
    // the other one.
    for (int64_t e = binding.seam_offsets[si]; e < binding.seam_offsets[si + 1]; ++e) {
      const auto ei = static_cast<size_t>(e);
      const float* f = tetrahedron_frames.data() +
                       static_cast<size_t>(binding.seam_tetrahedron[ei]) * kFrameFloats;
      const float* l = binding.seam_local_m.data() + 3 * ei;
      const float w = binding.seam_weight[ei];
      float* p = out + 3 * binding.seam_row[ei];
      for (int r = 0; r < 3; ++r)
        p[r] = (1 - w) * p[r] + w * (f[r] + f[4 + r] * l[0] + f[8 + r] * l[1] + f[12 + r] * l[2]);
    }
    // Bridged: R p + t + s (x_b - (R b + t)), b the first bound point at rest and x_b where
    // its tetrahedron carries it: the head's motion plus a share of how far the wisp's top
    // moved from where the head would have carried it (no lever arm from the tetrahedron).
    if (binding.bridged[si]) {
      const float* h = head_frame;
      float junction_move[3];
      for (int r = 0; r < 3; ++r) {
        const float b = h[4 + r] * strands.points(bound, 0) + h[8 + r] * strands.points(bound, 1) +
                        h[12 + r] * strands.points(bound, 2) + h[r];
        junction_move[r] = out[3 * bound + r] - b;
      }
      for (int64_t row = interpolated; row < bound; ++row) {
        const float share = binding.parameter[static_cast<size_t>(row)];
        const float* p = offset + 3 * row;
        for (int r = 0; r < 3; ++r)
          out[3 * row + r] = h[4 + r] * p[0] + h[8 + r] * p[1] + h[12 + r] * p[2] + h[r] +
                             share * junction_move[r];
      }
    } else if (interpolated < bound) {
      // Interpolated: sum_g w_g (G_g(u) + F_g(u) d), in runs where the strand has them.
      const StrandGuides used = strand_guides(binding, s);
      const float* guide_table[3];
      for (size_t k = 0; k < static_cast<size_t>(used.count); ++k)
        guide_table[k] = table->data() + binding.guide_offsets[static_cast<size_t>(used.guide[k])] *
                                             kParticleFloats;
      const int64_t first_run = binding.run_offsets[si];
      const auto run_count = static_cast<int>(binding.run_offsets[si + 1] - first_run);
      if (run_count > 0)
        interpolate_strand_runs(guide_table, used.weight.data(), used.count,
                                binding.run_particles.data() + first_run, run_count,
                                binding.run_of_point.data() + interpolated,
                                binding.parameter.data() + interpolated, offset + 3 * interpolated,
                                bound - interpolated, out + 3 * interpolated);
      else
        interpolate_strand_points(guide_table, used.segments.data(), used.weight.data(), used.count,
                                  binding.parameter.data() + interpolated,
                                  offset + 3 * interpolated, bound - interpolated,
                                  out + 3 * interpolated);
    }
  }
}

}  // namespace hair
