// Whether streamlines traced over a tube are hair (a shell meshed as a tube) or strokes
// painted round a braid piece.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hair/extract/tube_streamlines.h"

namespace hair {
namespace {

/// A polyline of `count` points from `f(t)`, t from 0 to 1.
template <typename F>
PaintedStreamline streamline(int count, F f) {
  PaintedStreamline s;
  s.points.resize(count, 3);
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d p = f(static_cast<double>(i) / (count - 1));
    s.points.row(i) = p.cast<float>().transpose();
  }
  return s;
}

// A braid piece: 1 cm round, 5 cm long (extent about 5.7 cm), rails 5 cm.
constexpr double kPieceRadiusM = 0.01, kPieceLengthM = 0.05;
const double kPieceExtentM = std::sqrt(2 * 0.02 * 0.02 + 0.05 * 0.05);

TEST(TubeStreamlines, StrokesWoundRoundABraidPieceAreNotHair) {
  // Along the paint of a braid's lobe, a streamline winds round the piece ten times while
  // it goes along it: 63 cm on a piece 5.7 cm across.
  std::vector<PaintedStreamline> wound;
  for (int k = 0; k < 6; ++k)
    wound.push_back(streamline(400, [&](double t) -> Eigen::Vector3d {
      const double angle = 2 * std::numbers::pi * (10 * t + k / 6.0);
      return Eigen::Vector3d(kPieceRadiusM * std::cos(angle), kPieceRadiusM * std::sin(angle),
                             kPieceLengthM * t);
    }));
  EXPECT_FALSE(tube_streamlines_are_hair(wound, kPieceExtentM, kPieceLengthM, {}));
}

TEST(TubeStreamlines, StrokesThatStopAtEveryLobeAreNotHair) {
  // The lobes turn the strokes within a few faces: streamlines of 8 mm on rails of 5 cm.
  std::vector<PaintedStreamline> short_ones;
  for (int k = 0; k < 20; ++k)
    short_ones.push_back(streamline(5, [&](double t) -> Eigen::Vector3d {
      return Eigen::Vector3d(kPieceRadiusM, 0.0, 0.0025 * k) + Eigen::Vector3d(0, 0.008 * t, 0);
    }));
  EXPECT_FALSE(tube_streamlines_are_hair(short_ones, kPieceExtentM, kPieceLengthM, {}));
  EXPECT_FALSE(tube_streamlines_are_hair({}, kPieceExtentM, kPieceLengthM, {}));
}

TEST(TubeStreamlines, HairCombedOverAShellMeshedInRingsIsHair) {
  // A short cut's shell, 30 cm across, meshed in rings whose rails are 4 cm long; the
  // paint runs from the crown to the hairline, 12-20 cm over the head.
  std::vector<PaintedStreamline> combed;
  for (int k = 0; k < 30; ++k) {
    const double azimuth = 2 * std::numbers::pi * k / 30, length_m = 0.12 + 0.08 * (k % 3) / 2;
    combed.push_back(streamline(40, [&](double t) -> Eigen::Vector3d {
      const double polar = 0.2 + (length_m / 0.1) * t;  // over a head 10 cm round
      return Eigen::Vector3d(0.1 * std::sin(polar) * std::cos(azimuth), 0.1 * std::cos(polar),
                             0.1 * std::sin(polar) * std::sin(azimuth));
    }));
  }
  EXPECT_TRUE(tube_streamlines_are_hair(combed, 0.3, 0.04, {}));
  // The limits are the caller's: the same hair is refused where streamlines must be
  // no longer than the patch is across, or as long as five times its rails.
  TubeStreamlineLimits tight;
  tight.max_extent_ratio = 0.5;
  EXPECT_FALSE(tube_streamlines_are_hair(combed, 0.3, 0.04, tight));
  TubeStreamlineLimits long_rails;
  long_rails.min_length_share = 5;
  EXPECT_FALSE(tube_streamlines_are_hair(combed, 0.3, 0.04, long_rails));
}

}  // namespace
}  // namespace hair
