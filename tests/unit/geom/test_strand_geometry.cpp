#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "hair/core/error.h"
#include "hair/geom/strand_geometry.h"
#include "unit/point_rows.h"

namespace {

using hair::test::rows;

hair::StrandSet strand_set(std::initializer_list<hair::Points3f> strands) {
  hair::StrandSet set;
  for (const auto& strand : strands) set.append_strand(strand);
  return set;
}

/// `count` wavy strands of 2 to 40 points with uneven spacing, some zero-length segments,
/// and one attribute of each kind.
hair::StrandSet random_strands(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> step(-0.01f, 0.01f);
  std::uniform_int_distribution<int> size(2, 40);
  hair::StrandSet strands;
  std::vector<int32_t> strand_ids;
  for (int strand = 0; strand < count; ++strand) {
    hair::Points3f points(size(random), 3);
    points.row(0) << step(random), 0.1f, step(random);
    for (Eigen::Index row = 1; row < points.rows(); ++row) {
      const bool repeat = random() % 10 == 0;
      points.row(row) = points.row(row - 1);
      if (!repeat) points.row(row) += Eigen::RowVector3f(step(random), -0.01f, step(random));
    }
    strands.append_strand(points);
    strand_ids.push_back(strand);
  }
  std::vector<float> thickness_m(static_cast<size_t>(strands.point_count()));
  std::vector<int32_t> point_ids(thickness_m.size());
  for (size_t point = 0; point < thickness_m.size(); ++point) {
    thickness_m[point] = 1e-4f * static_cast<float>(point % 7);
    point_ids[point] = static_cast<int32_t>(point);
  }
  strands.strand_attributes["id"] = strand_ids;
  strands.point_attributes["thickness_m"] = thickness_m;
  strands.point_attributes["point_id"] = point_ids;
  strands.point_attributes["rest"] = strands.points;
  return strands;
}

/// Strand `strand` of `strands` alone, with its attributes.
hair::StrandSet single_strand(const hair::StrandSet& strands, int64_t strand) {
  hair::StrandSet single;
  single.append_strand(strands.strand(strand));
  const int64_t first = strands.offsets[strand];
  const int64_t size = strands.strand_size(strand);
  for (const auto& [name, column] : strands.strand_attributes) {
    single.strand_attributes[name] =
        std::vector<int32_t>{std::get<std::vector<int32_t>>(column)[strand]};
  }
  for (const auto& [name, column] : strands.point_attributes) {
    std::visit(
        [&](const auto& values) {
          using Values = std::decay_t<decltype(values)>;
          if constexpr (std::is_same_v<Values, hair::Points3f>) {
            single.point_attributes[name] = hair::Points3f(values.middleRows(first, size));
          } else {
            single.point_attributes[name] =
                Values(values.begin() + first, values.begin() + first + size);
          }
        },
        column);
  }
  return single;
}

void expect_same_strand_sets(const hair::StrandSet& a, const hair::StrandSet& b) {
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.strand_attributes, b.strand_attributes);
  EXPECT_EQ(a.point_attributes, b.point_attributes);
}

TEST(StrandLengths, HandMadeStrands) {
  const hair::StrandSet strands =
      strand_set({rows({{0, 0, 0}, {3, 4, 0}}), rows({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 0}}),
                  rows({{2, 2, 2}, {2, 2, 2}, {2, 2, 2}}), rows({{5, 5, 5}})});
  EXPECT_EQ(hair::strand_lengths(strands), (std::vector<float>{5, 2, 0, 0}));
}

TEST(StrandTangents, HandMadeStrands) {
  const float diagonal = static_cast<float>(std::numbers::sqrt2 / 2);
  const hair::StrandSet strands = strand_set({
      rows({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}),             // an L
      rows({{0, 0, 0}, {0, 0, 0}, {0, 0, 2}, {0, 0, 2}}),  // zero-length root and tip segments
      rows({{0, 0, 0}, {1, 0, 0}, {0, 0, 0}}),             // a hairpin
      rows({{1, 1, 1}, {1, 1, 1}}),                        // all points coincide
      rows({{1, 2, 3}}),                                   // a single point
  });
  const hair::Points3f tangents = hair::strand_tangents(strands);
  const hair::Points3f expected = rows({{1, 0, 0},
                                        {diagonal, diagonal, 0},
                                        {0, 1, 0},
                                        {0, 0, 1},
                                        {0, 0, 1},
                                        {0, 0, 1},
                                        {0, 0, 1},
                                        {1, 0, 0},
                                        {1, 0, 0},
                                        {-1, 0, 0},
                                        {0, 0, 0},
                                        {0, 0, 0},
                                        {0, 0, 0}});
  ASSERT_EQ(tangents.rows(), expected.rows());
  EXPECT_TRUE(tangents.isApprox(expected, 1e-6f)) << tangents;
}

TEST(StrandTangents, UnitLengthOnRandomStrands) {
  const hair::StrandSet strands = random_strands(200, 1);
  const hair::Points3f tangents = hair::strand_tangents(strands);
  ASSERT_EQ(tangents.rows(), strands.point_count());
  for (Eigen::Index row = 0; row < tangents.rows(); ++row) {
    EXPECT_NEAR(tangents.row(row).norm(), 1.0f, 1e-6f) << "row " << row;
  }
}

TEST(ResampleByCount, KeepsAStraightLineExactly) {
  // Uneven points on a line; the new points fall on whole numbers.
  const hair::StrandSet line = strand_set({rows({{0, 0, 0}, {1, 0, 0}, {3, 0, 0}})});
  const hair::StrandSet resampled = hair::resample_by_count(line, 4);
  EXPECT_EQ(resampled.points, rows({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}));
  EXPECT_EQ(hair::strand_lengths(resampled), std::vector<float>{3});
}

TEST(ResampleByCount, KeepsTheLengthOfSlantedLines) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::RowVector3f root(coordinate(random), coordinate(random), coordinate(random));
    const Eigen::RowVector3f tip(coordinate(random), coordinate(random), coordinate(random));
    hair::Points3f points(5, 3);
    const std::array<float, 5> fractions{0.0f, 0.1f, 0.15f, 0.7f, 1.0f};
    for (Eigen::Index row = 0; row < 5; ++row) {
      points.row(row) = row == 4 ? tip : root + fractions[static_cast<size_t>(row)] * (tip - root);
    }
    const hair::StrandSet line = strand_set({points});
    for (const int count : {2, 3, 11, 100}) {
      const hair::StrandSet resampled = hair::resample_by_count(line, count);
      ASSERT_EQ(resampled.point_count(), count);
      EXPECT_EQ(resampled.points.row(0), root);
      EXPECT_EQ(resampled.points.row(count - 1), tip);
      EXPECT_NEAR(hair::strand_lengths(resampled)[0], hair::strand_lengths(line)[0], 1e-6f);
    }
  }
}

TEST(ResampleByCount, CircleArcLengthConverges) {
  // A half circle of radius 0.1 m, sampled densely and unevenly.
  const double radius_m = 0.1;
  const int dense_count = 4001;
  hair::Points3f arc(dense_count, 3);
  for (int index = 0; index < dense_count; ++index) {
    const double unit = static_cast<double>(index) / (dense_count - 1);
    const double angle = std::numbers::pi * unit * unit;
    arc.row(index) << static_cast<float>(radius_m * std::cos(angle)),
        static_cast<float>(radius_m * std::sin(angle)), 0.0f;
  }
  const hair::StrandSet strands = strand_set({arc});
  const double exact_m = std::numbers::pi * radius_m;
  double previous_error_m = exact_m;
  for (const int count : {4, 8, 16, 32, 64, 128}) {
    const double error_m =
        exact_m - hair::strand_lengths(hair::resample_by_count(strands, count))[0];
    EXPECT_GT(error_m, 0.0) << count;                     // chords are shorter than the arc
    EXPECT_LT(error_m, previous_error_m * 0.3) << count;  // second order: about a quarter
    previous_error_m = error_m;
  }
  EXPECT_LT(previous_error_m / exact_m, 1e-4);
}

TEST(ResampleByCount, PointsAreUniformInArcLength) {
  const hair::StrandSet strands = random_strands(50, 2);
  const hair::StrandSet resampled = hair::resample_by_count(strands, 9);
  const std::vector<float> lengths_m = hair::strand_lengths(strands);
  for (int64_t strand = 0; strand < resampled.strand_count(); ++strand) {
    // Chords of a polyline are at most the arc length between their ends.
    const auto points = resampled.strand(strand);
    for (Eigen::Index row = 1; row < points.rows(); ++row) {
      EXPECT_LE((points.row(row) - points.row(row - 1)).norm(),
                lengths_m[static_cast<size_t>(strand)] / 8 + 1e-6f);
    }
  }
}

TEST(ResampleByCount, CarriesAttributesAlong) {
  hair::StrandSet strands = strand_set({rows({{0, 0, 0}, {1, 0, 0}, {3, 0, 0}})});
  strands.strand_attributes["cluster"] = std::vector<int32_t>{4};
  strands.point_attributes["thickness_m"] = std::vector<float>{0.0f, 1.0f, 3.0f};
  strands.point_attributes["rest"] = strands.points;
  strands.point_attributes["segment_id"] = std::vector<int32_t>{10, 11, 12};
  const hair::StrandSet resampled = hair::resample_by_count(strands, 7);  // every 0.5 m
  EXPECT_EQ(std::get<std::vector<int32_t>>(resampled.strand_attributes.at("cluster")),
            std::vector<int32_t>{4});
  EXPECT_EQ(std::get<std::vector<float>>(resampled.point_attributes.at("thickness_m")),
            (std::vector<float>{0, 0.5f, 1, 1.5f, 2, 2.5f, 3}));
  EXPECT_EQ(std::get<hair::Points3f>(resampled.point_attributes.at("rest")), resampled.points);
  // Nearest original point: at 0.5 m the tie goes to the root side; 1.5 m is nearer 1 m.
  EXPECT_EQ(std::get<std::vector<int32_t>>(resampled.point_attributes.at("segment_id")),
            (std::vector<int32_t>{10, 10, 11, 11, 11, 12, 12}));
  EXPECT_NO_THROW(hair::check_strand_set(resampled));
}

TEST(ResampleByCount, DegenerateStrandsStayFinite) {
  hair::StrandSet strands =
      strand_set({rows({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}}), rows({{4, 5, 6}})});
  strands.point_attributes["thickness_m"] = std::vector<float>{1, 2, 3, 4};
  const hair::StrandSet resampled = hair::resample_by_count(strands, 5);
  EXPECT_EQ(resampled.offsets, (std::vector<int64_t>{0, 5, 10}));
  EXPECT_TRUE(resampled.points.allFinite());
  EXPECT_EQ(resampled.points.topRows(5),
            rows({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}));
  EXPECT_EQ(resampled.points.bottomRows(5),
            rows({{4, 5, 6}, {4, 5, 6}, {4, 5, 6}, {4, 5, 6}, {4, 5, 6}}));
  const auto& thickness_m =
      std::get<std::vector<float>>(resampled.point_attributes.at("thickness_m"));
  EXPECT_EQ(thickness_m.front(), 1.0f);
  EXPECT_EQ(thickness_m[4], 3.0f);
  for (const float value : thickness_m) EXPECT_TRUE(std::isfinite(value));
}

TEST(ResampleByCount, StrandOrderDoesNotChangeResults) {
  const hair::StrandSet strands = random_strands(30, 3);
  std::vector<int64_t> order(static_cast<size_t>(strands.strand_count()));
  for (size_t index = 0; index < order.size(); ++index) order[index] = static_cast<int64_t>(index);
  std::shuffle(order.begin(), order.end(), std::mt19937(4));
  hair::StrandSet shuffled;
  for (const int64_t strand : order) shuffled.append_strand(strands.strand(strand));
  const hair::StrandSet resampled = hair::resample_by_count(strands, 12);
  const hair::StrandSet resampled_shuffled = hair::resample_by_count(shuffled, 12);
  const hair::Points3f tangents = hair::strand_tangents(strands);
  const hair::Points3f tangents_shuffled = hair::strand_tangents(shuffled);
  const std::vector<float> lengths_m = hair::strand_lengths(strands);
  const std::vector<float> lengths_shuffled_m = hair::strand_lengths(shuffled);
  for (size_t position = 0; position < order.size(); ++position) {
    const int64_t strand = order[position];
    const auto shuffled_position = static_cast<int64_t>(position);
    EXPECT_EQ(resampled.strand(strand), resampled_shuffled.strand(shuffled_position));
    EXPECT_EQ(tangents.middleRows(strands.offsets[strand], strands.strand_size(strand)),
              tangents_shuffled.middleRows(shuffled.offsets[shuffled_position],
                                           shuffled.strand_size(shuffled_position)));
    EXPECT_EQ(lengths_m[static_cast<size_t>(strand)], lengths_shuffled_m[position]);
  }
}

TEST(ResampleByCount, EachStrandAloneGivesTheSameResult) {
  const hair::StrandSet strands = random_strands(10, 5);
  const hair::StrandSet resampled = hair::resample_by_count(strands, 6);
  for (int64_t strand = 0; strand < strands.strand_count(); ++strand) {
    expect_same_strand_sets(hair::resample_by_count(single_strand(strands, strand), 6),
                            single_strand(resampled, strand));
  }
}

TEST(ResampleByCount, SameResultWhateverTheThreadCount) {
  const hair::StrandSet strands = random_strands(2000, 6);
  const int threads_before = omp_get_max_threads();
  omp_set_num_threads(1);
  const hair::StrandSet one_thread = hair::resample_by_count(strands, 17);
  const hair::StrandSet one_thread_spacing = hair::resample_by_spacing(strands, 0.003f);
  const hair::Points3f one_thread_tangents = hair::strand_tangents(strands);
  omp_set_num_threads(4);
  const hair::StrandSet four_threads = hair::resample_by_count(strands, 17);
  const hair::StrandSet four_threads_spacing = hair::resample_by_spacing(strands, 0.003f);
  const hair::Points3f four_threads_tangents = hair::strand_tangents(strands);
  omp_set_num_threads(threads_before);
  expect_same_strand_sets(one_thread, four_threads);
  expect_same_strand_sets(one_thread_spacing, four_threads_spacing);
  EXPECT_EQ(one_thread_tangents, four_threads_tangents);
}

TEST(ResampleByCount, RefusesBadInput) {
  const hair::StrandSet line = strand_set({rows({{0, 0, 0}, {1, 0, 0}})});
  try {
    hair::resample_by_count(line, 1);
    FAIL() << "one point per strand accepted";
  } catch (const hair::Error& error) {
    EXPECT_EQ(error.kind(), hair::ErrorKind::usage);
    EXPECT_STREQ(error.what(), "points_per_strand = 1 must be at least 2");
  }
  const hair::StrandSet with_empty =
      strand_set({rows({{0, 0, 0}, {1, 0, 0}}), hair::Points3f(0, 3)});
  EXPECT_THROW(hair::resample_by_count(with_empty, 3), hair::Error);
  hair::StrandSet with_nan = line;
  with_nan.points(1, 0) = std::nanf("");
  EXPECT_THROW(hair::resample_by_count(with_nan, 3), hair::Error);
}

TEST(ResampleBySpacing, PointCountFollowsLength) {
  const hair::StrandSet strands = strand_set({
      rows({{0, 0, 0}, {1, 0, 0}}),                   // 1 m: 4 segments of 0.25 m
      rows({{0, 0, 0}, {0, 0.5f, 0}, {0, 1.2f, 0}}),  // 1.2 m: ceil(4.8) = 5 segments
      rows({{0, 0, 0}, {0.1f, 0, 0}}),                // 0.1 m: 1 segment
      rows({{2, 2, 2}, {2, 2, 2}}),                   // degenerate: 2 points
  });
  const hair::StrandSet resampled = hair::resample_by_spacing(strands, 0.25f);
  EXPECT_EQ(resampled.offsets, (std::vector<int64_t>{0, 5, 11, 13, 15}));
  EXPECT_EQ(resampled.strand(0),
            rows({{0, 0, 0}, {0.25f, 0, 0}, {0.5f, 0, 0}, {0.75f, 0, 0}, {1, 0, 0}}));
  EXPECT_TRUE(resampled.points.allFinite());
}

TEST(ResampleBySpacing, FloatRoundingAddsNoPoint) {
  // 0.1 m in float is not exactly ten times 0.01 m in float.
  const hair::StrandSet strands = strand_set({rows({{0, 0, 0}, {0, -0.03f, 0}, {0, -0.1f, 0}})});
  EXPECT_EQ(hair::resample_by_spacing(strands, 0.01f).point_count(), 11);
}

TEST(ResampleBySpacing, ConsecutivePointsAreAtMostTheSpacingApart) {
  const hair::StrandSet strands = random_strands(100, 8);
  const float spacing_m = 0.004f;
  const hair::StrandSet resampled = hair::resample_by_spacing(strands, spacing_m);
  EXPECT_NO_THROW(hair::check_strand_set(resampled));
  for (Eigen::Index row = 1; row < resampled.point_count(); ++row) {
    const bool same_strand = std::find(resampled.offsets.begin(), resampled.offsets.end(), row) ==
                             resampled.offsets.end();
    if (same_strand) {
      EXPECT_LE((resampled.points.row(row) - resampled.points.row(row - 1)).norm(),
                spacing_m * 1.0001f);
    }
  }
}

TEST(ResampleBySpacing, RefusesBadSpacing) {
  const hair::StrandSet line = strand_set({rows({{0, 0, 0}, {1, 0, 0}})});
  for (const float spacing_m :
       {0.0f, -1.0f, std::nanf(""), std::numeric_limits<float>::infinity(), 1e-12f}) {
    try {
      hair::resample_by_spacing(line, spacing_m);
      ADD_FAILURE() << "spacing " << spacing_m << " accepted";
    } catch (const hair::Error& error) {
      EXPECT_EQ(error.kind(), hair::ErrorKind::usage) << error.what();
    }
  }
}

}  // namespace
