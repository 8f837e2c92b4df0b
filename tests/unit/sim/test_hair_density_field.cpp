// HairDensityField: the splat grid behind hair-hair repulsion (hair_density_field.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "hair/sim/hair_density_field.h"

namespace {

using hair::HairDensityField;
using Vec3 = Eigen::Vector3d;

constexpr double kCell = 0.01;

/// `count` particles about the origin, normally spread by `sigma_m` on each axis.
std::vector<Vec3> gaussian_crowd(unsigned seed, double sigma_m, int count) {
  std::mt19937 random(seed);
  std::normal_distribution<double> spread(0, sigma_m);
  std::vector<Vec3> crowd;
  for (int i = 0; i < count; ++i)
    crowd.emplace_back(spread(random), spread(random), spread(random));
  return crowd;
}

TEST(HairDensityField, OneSplatIsOneParticleWhereItIs) {
  HairDensityField field(kCell);
  Vec3 p(0.0123, -0.0456, 0.0789);
  field.build({p});
  // The grid starts two cells below the lowest particle, so a lone particle sits on a
  // grid node and reads its whole weight there.
  EXPECT_NEAR(field.density(p), 1.0, 1e-9);
  // Half a cell off along x, the trilinear sample reads half.
  EXPECT_NEAR(field.density(p + Vec3(0.5 * kCell, 0, 0)), 0.5, 1e-9);
  EXPECT_EQ(field.density(p + Vec3(0.5, 0, 0)), 0.0);  // outside the grid
  // Its own splat removed, nothing is left.
  std::vector<Vec3> own{p};
  EXPECT_NEAR(field.density_without(p, own), 0.0, 1e-12);
  EXPECT_NEAR(field.density_without(p + Vec3(0.004, -0.003, 0.002), own), 0.0, 1e-12);
  EXPECT_LT(field.gradient_per_cell_without(p, own).norm(), 1e-12);
}

TEST(HairDensityField, GradientPointsTowardTheCrowd) {
  // A crowd of particles around the origin; the density falls away from it, so the
  // gradient at a point beside the crowd points back at it.
  const std::vector<Vec3> crowd = gaussian_crowd(3, 0.01, 2000);
  HairDensityField field(kCell);
  field.build(crowd);
  for (const Vec3& beside : {Vec3(0.02, 0, 0), Vec3(0, -0.015, 0.01), Vec3(-0.01, 0.01, -0.01)}) {
    Vec3 gradient = field.gradient_per_cell(beside);
    EXPECT_LT(gradient.normalized().dot(beside.normalized()), -0.8) << beside.transpose();
    EXPECT_GT(field.density(Vec3::Zero()), field.density(beside));
  }
  EXPECT_GT(field.mean_occupied_density(), 1.0);
}

TEST(HairDensityField, OwnSplatsAreTakenOutExactly) {
  // The density without a particle's splat equals the density of a grid built without it,
  // wherever it is sampled within reach (the same grid lattice: the far particles fix the
  // box).
  std::vector<Vec3> others{Vec3(-0.05, -0.05, -0.05), Vec3(0.05, 0.05, 0.05),
                           Vec3(0.003, 0.001, 0.002)};
  std::vector<Vec3> with = others;
  Vec3 mine(0.0071, 0.0042, -0.0013);
  with.push_back(mine);
  HairDensityField all(kCell), without(kCell);
  all.build(with);
  without.build(others);
  std::vector<Vec3> own{mine};
  for (const Vec3& sample : {mine, Vec3(0.005, 0.002, 0.0), Vec3(0.01, 0.0, -0.004)}) {
    EXPECT_NEAR(all.density_without(sample, own), without.density(sample), 1e-12);
    EXPECT_LT(
        (all.gradient_per_cell_without(sample, own) - without.gradient_per_cell(sample)).norm(),
        1e-12);
  }
}

TEST(HairDensityField, OnePassSampleAgreesWithTheTwoCalls) {
  // A crowd, sampled at random points inside it, near and beyond the grid's edge, with a
  // particle's own splats (itself and its neighbours) taken out.
  const std::vector<Vec3> crowd = gaussian_crowd(7, 0.02, 3000);
  std::mt19937 random(7);
  HairDensityField field(kCell);
  field.build(crowd);
  std::uniform_real_distribution<double> anywhere(-0.12, 0.12);
  int inside = 0;
  for (int i = 0; i < 2000; ++i) {
    const size_t k = 1 + static_cast<size_t>(i) % (crowd.size() - 2);
    const std::vector<Vec3> own{crowd[k - 1], crowd[k], crowd[k + 1]};
    const Vec3 point =
        i % 2 ? crowd[k] : Vec3(anywhere(random), anywhere(random), anywhere(random));
    const HairDensityField::SampleWithout sample = field.sample_without(point, own);
    // The density bit for bit; the gradient to rounding.
    ASSERT_EQ(sample.density, field.density_without(point, own)) << point.transpose();
    const Vec3 gradient = field.gradient_per_cell_without(point, own);
    ASSERT_LE((sample.gradient_per_cell - gradient).norm(), 1e-12 * (1 + gradient.norm()))
        << point.transpose() << "\n"
        << sample.gradient_per_cell.transpose() << "\n"
        << gradient.transpose();
    inside += field.density(point) > 0;
  }
  EXPECT_GT(inside, 1000);  // every particle, and some of the random points
  // Outside the grid and at a non-finite point: nothing.
  const std::vector<Vec3> none;
  EXPECT_EQ(field.sample_without(Vec3(1, 0, 0), none).density, 0.0);
  EXPECT_TRUE(field.sample_without(Vec3(std::nan(""), 0, 0), none).gradient_per_cell.isZero());
}

TEST(HairDensityField, EmptyAndNonFiniteInputs) {
  HairDensityField field(kCell);
  field.build({});
  EXPECT_EQ(field.density(Vec3::Zero()), 0.0);
  EXPECT_EQ(field.mean_occupied_density(), 0.0);
  EXPECT_TRUE(field.gradient_per_cell(Vec3::Zero()).isZero());
  // Non-finite particles are left out of the grid.
  field.build({Vec3(0, 0, 0), Vec3(std::nan(""), 0, 0)});
  EXPECT_GT(field.density(Vec3::Zero()), 0.0);
  EXPECT_EQ(field.density(Vec3(std::nan(""), 0, 0)), 0.0);
  // A spread beyond 4096 cells is refused rather than allocated.
  EXPECT_THROW(field.build({Vec3::Zero(), Vec3(100, 0, 0)}), std::runtime_error);
}

}  // namespace
