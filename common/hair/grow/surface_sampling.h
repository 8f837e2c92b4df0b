#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "hair/core/strand_set.h"              // Points3f (row-major n x 3 float)
#include "hair/geom/triangle_mesh_distance.h"  // Triangles3i (row-major n x 3 int32)

namespace hair {

/// Points spread over a region of a triangle mesh, with what a caller checks them by.
struct SurfaceSamples {
  Points3f positions;             ///< #samples x 3, metres, on the triangles
  Points3f normals;               ///< #samples x 3 unit face normals (right-hand rule of the
                                  ///< triangle's vertex order)
  std::vector<int32_t> triangle;  ///< #samples: the triangle each sample lies on
  double area_m2 = 0;             ///< area of the triangles sampled
  double max_radius_m = 0;        ///< r_max of max_poisson_disk_radius_m(area_m2, #samples):
                                  ///< the spacing scale the samples are measured against
  double min_spacing_m = 0;       ///< smallest distance between two samples (0 for one sample);
                                  ///< about 1.38 max_radius_m for blue noise
};

/// The largest Poisson-disk radius `count` samples can have on `area_m2` of surface,
/// r_max = sqrt(A / (2 sqrt(3) N)) (Yuksel 2015, the 2-D bound): the radius of the disks
/// of the densest (hexagonal) packing, whose samples lie 2 r_max apart. A set's "relative
/// radius" is its smallest spacing over 2 r_max; weighted sample elimination reaches about
/// 0.69 (smallest spacing about 1.38 r_max), a uniform draw close to 0.
double max_poisson_disk_radius_m(double area_m2, int64_t count);

/// Exactly `count` samples spread as blue noise (Poisson-disk) over the triangles with
/// use_triangle[t] != 0: the hair roots of the grow stage (paper, section 4.4).
///
/// Yuksel's weighted sample elimination (C. Yuksel, "Sample Elimination for Generating
/// Poisson Disk Sample Sets", Eurographics 2015): candidate_factor * count candidates are
/// drawn uniformly by area; each candidate weighs sum_j (1 - d_ij / (2 r_max))^8 over its
/// neighbours within 2 r_max, with d_ij clamped from below at 2 r_max * 0.65 (1 - (N/M)^1.5)
/// (the paper's weight limiting, N samples from M candidates: it keeps a tight pair from
/// outweighing a spread-out crowd); the heaviest candidate is removed and its neighbours
/// lightened until `count` remain. Distances are Euclidean in 3-D, fine for a gently
/// curved region like a scalp (not for a region folded within 2 r_max of itself).
///
/// Deterministic for a seed on every platform and thread count: std::mt19937_64 with
/// hand-written draws, ties between equal weights broken by candidate index. The samples
/// come in Z-order (Morton order over cells of 2 r_max): near in space, mostly near in
/// the list. Boundaries of the region are not treated specially: samples there have fewer
/// neighbours and so stay slightly farther apart, and the holes (the largest distance
/// from a point of the region to its nearest sample) reach about 2 r_max.
///
/// @param vertices      #V x 3 positions, metres
/// @param triangles     #T x 3 vertex ids
/// @param use_triangle  #T flags: sample triangle t where use_triangle[t] != 0
/// @param count         number of samples wanted, >= 1
/// @param seed          random seed
/// @param candidate_factor  candidates drawn per sample (>= 1; 1 means plain uniform
///                      samples, 3-5 is Yuksel's range, more costs time for little gain)
/// @param accept        if given, where on the triangles samples may lie: a candidate
///                      point (and its triangle) it refuses is drawn again, so that the
///                      samples spread over the accepted part of the triangles only; the
///                      area (and r_max) is that of the selected triangles times the share
///                      of draws accepted
///
/// Throws hair::Error: usage for count < 1, candidate_factor < 1, more than 2^26
/// candidates, use_triangle of the wrong size; bad_input for no triangle selected, a
/// selected triangle with a vertex id out of range or a non-finite vertex, a selected
/// area that is zero or not finite, or `accept` refusing every one of 1000 draws per
/// candidate wanted.
using SampleAcceptance = std::function<bool(const Eigen::Vector3d& point, int32_t triangle)>;
SurfaceSamples poisson_disk_samples(const Points3f& vertices, const Triangles3i& triangles,
                                    const std::vector<uint8_t>& use_triangle, int64_t count,
                                    uint64_t seed, int candidate_factor = 5,
                                    const SampleAcceptance& accept = {});

}  // namespace hair
