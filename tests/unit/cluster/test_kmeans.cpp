// k-means on point sets whose clustering is known.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include "hair/cluster/adjusted_rand_index.h"
#include "hair/cluster/kmeans.h"
#include "hair/core/error.h"
#include "unit/feature_blobs.h"

namespace hair {
namespace {

/// Points of isotropic Gaussian blobs (standard deviation `sigma`) around `centres`,
/// the blobs interleaved (point i belongs to blob i mod #blobs) so that no blob is a
/// block of rows.
struct Blobs {
  Eigen::MatrixXd points;
  std::vector<int32_t> truth;
};

Blobs blobs(const Eigen::MatrixXd& centres, int per_blob, double sigma, uint64_t seed) {
  test::NormalDraws normal(seed);
  auto count = static_cast<int>(centres.rows());
  Blobs result;
  result.points.resize(count * per_blob, centres.cols());
  for (int i = 0; i < count * per_blob; ++i) {
    int blob = (i * 7 + 5) % count;  // not in order of first appearance either
    for (Eigen::Index d = 0; d < centres.cols(); ++d)
      result.points(i, d) = centres(blob, d) + sigma * normal();
    result.truth.push_back(blob);
  }
  return result;
}

Eigen::MatrixXd three_centres() {
  Eigen::MatrixXd centres(3, 2);
  centres << 0, 0, 10, 0, 5, 8;
  return centres;
}

TEST(KMeans, RecoversWellSeparatedBlobs) {
  Blobs data = blobs(three_centres(), 60, 0.5, 3);
  KMeansResult result = kmeans(data.points, 3, {});
  EXPECT_DOUBLE_EQ(adjusted_rand_index(result.label, data.truth), 1.0);
  // Each centre is the mean of its points, and near the blob's true centre.
  ASSERT_EQ(result.centres.rows(), 3);
  ASSERT_EQ(result.centres.cols(), 2);
  double inertia = 0;
  for (int c = 0; c < 3; ++c) {
    Eigen::RowVector2d sum = Eigen::RowVector2d::Zero();
    int count = 0, blob = -1;
    for (size_t i = 0; i < result.label.size(); ++i)
      if (result.label[i] == c) {
        sum += data.points.row(static_cast<Eigen::Index>(i));
        ++count;
        blob = data.truth[i];
      }
    ASSERT_GT(count, 0);
    EXPECT_LT((result.centres.row(c) - sum / count).norm(), 1e-12);
    EXPECT_LT((result.centres.row(c) - three_centres().row(blob)).norm(), 0.25);
  }
  for (size_t i = 0; i < result.label.size(); ++i)
    inertia += (data.points.row(static_cast<Eigen::Index>(i)) - result.centres.row(result.label[i]))
                   .squaredNorm();
  EXPECT_NEAR(result.inertia, inertia, 1e-9 * inertia);
}

TEST(KMeans, LabelsNumberedByFirstAppearance) {
  Blobs data = blobs(three_centres(), 20, 0.5, 4);
  ASSERT_NE(data.truth[0], 0);  // the generator's own numbering does not start at row 0
  KMeansResult result = kmeans(data.points, 3, {});
  int32_t next = 0;
  for (int32_t label : result.label) {
    ASSERT_LE(label, next);
    if (label == next) ++next;
  }
  EXPECT_EQ(next, 3);
}

TEST(KMeans, SameSeedSameResult) {
  Blobs data = blobs(three_centres(), 40, 3.0, 5);  // overlapping: restarts matter
  KMeansParams params;
  params.seed = 77;
  KMeansResult first = kmeans(data.points, 4, params), second = kmeans(data.points, 4, params);
  EXPECT_EQ(first.label, second.label);
  EXPECT_EQ(first.centres, second.centres);
  EXPECT_EQ(first.inertia, second.inertia);
}

TEST(KMeans, MoreRestartsNeverRaiseInertia) {
  Blobs data = blobs(three_centres(), 40, 3.0, 6);
  KMeansParams one, many;
  one.restarts = 1;
  many.restarts = 20;  // its first run is the single run above (same seed)
  EXPECT_LE(kmeans(data.points, 5, many).inertia, kmeans(data.points, 5, one).inertia);
}

TEST(KMeans, AsManyClustersAsPointsGivesSingletons) {
  Blobs data = blobs(three_centres(), 3, 1.0, 7);
  auto n = static_cast<int>(data.points.rows());
  KMeansResult result = kmeans(data.points, n, {});
  for (int i = 0; i < n; ++i) EXPECT_EQ(result.label[static_cast<size_t>(i)], i);
  EXPECT_EQ(result.centres, data.points);
  EXPECT_EQ(result.inertia, 0.0);
}

TEST(KMeans, OneClusterIsTheMean) {
  Blobs data = blobs(three_centres(), 10, 1.0, 8);
  KMeansResult result = kmeans(data.points, 1, {});
  EXPECT_EQ(result.label, std::vector<int32_t>(data.truth.size(), 0));
  EXPECT_LT((result.centres.row(0) - data.points.colwise().mean()).norm(), 1e-12);
}

TEST(KMeans, EmptyClustersAreReseeded) {
  // Ten copies of one point and one other: k-means++ runs out of distinct points for
  // the third centre, which starts on a copy and leaves a cluster empty.
  Eigen::MatrixXd points = Eigen::MatrixXd::Zero(11, 2);
  points(10, 0) = 1;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    KMeansParams params;
    params.seed = seed;
    KMeansResult result = kmeans(points, 3, params);
    EXPECT_EQ(std::set<int32_t>(result.label.begin(), result.label.end()),
              (std::set<int32_t>{0, 1, 2}));
    EXPECT_EQ(result.inertia, 0.0);
    EXPECT_NE(result.label[10], result.label[0]);
  }
}

TEST(KMeans, BadArgumentsThrow) {
  Eigen::MatrixXd points = Eigen::MatrixXd::Random(5, 3);
  auto kind_of = [&](int k, KMeansParams params) {
    try {
      kmeans(points, k, params);
    } catch (const Error& error) {
      return static_cast<int>(error.kind());
    }
    return -1;
  };
  EXPECT_EQ(kind_of(0, {}), static_cast<int>(ErrorKind::usage));
  EXPECT_EQ(kind_of(6, {}), static_cast<int>(ErrorKind::usage));
  EXPECT_EQ(kind_of(5, {}), -1);
  KMeansParams no_restarts;
  no_restarts.restarts = 0;
  EXPECT_EQ(kind_of(2, no_restarts), static_cast<int>(ErrorKind::usage));
  points(2, 1) = std::nan("");
  EXPECT_EQ(kind_of(2, {}), static_cast<int>(ErrorKind::bad_input));
  EXPECT_THROW(kmeans(Eigen::MatrixXd(0, 2), 1, {}), Error);
}

}  // namespace
}  // namespace hair
