// The rigid head motion of the simulate stage: the presets (rest at t = 0, amplitudes,
// smoothness, the pivot), keyframe interpolation, the keyframe CSV and its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "unit/file_test.h"
#include "hair/core/error.h"
#include "hair/sim/head_motion.h"

namespace hair {
namespace {

using test::FileTest;

constexpr double kPi = std::numbers::pi;

/// The base of the head of a MakeHuman body, metres.
const Eigen::Vector3d kPivot(0.0, 1.55, 0.02);

/// Points on a head of radius 0.1 m above the pivot, and the pivot itself.
std::vector<Eigen::Vector3d> head_points() {
  Eigen::Vector3d centre = kPivot + Eigen::Vector3d(0, 0.1, 0);
  return {kPivot,
          centre,
          centre + Eigen::Vector3d(0.1, 0, 0),
          centre + Eigen::Vector3d(0, 0.1, 0),
          centre + Eigen::Vector3d(0, 0, 0.1),
          centre + Eigen::Vector3d(-0.07, 0.05, -0.07)};
}

/// The largest distance between where two transforms put the head points.
double largest_difference_m(const RigidTransform& a, const RigidTransform& b) {
  double largest = 0;
  for (const Eigen::Vector3d& point : head_points())
    largest = std::max(largest, (a.apply(point) - b.apply(point)).norm());
  return largest;
}

/// The largest speed of the head points over [time_s, time_s + step_s] (forward difference).
double forward_speed_m_per_s(const HeadMotion& motion, double time_s, double step_s) {
  return largest_difference_m(motion.at(time_s + step_s), motion.at(time_s)) / step_s;
}

/// The largest difference between the backward and the forward velocity of the head points
/// at `time_s`: O(step) where the motion is C^1, O(1) at a kink.
double velocity_jump_m_per_s(const HeadMotion& motion, double time_s, double step_s) {
  RigidTransform before = motion.at(time_s - step_s), now = motion.at(time_s),
                 after = motion.at(time_s + step_s);
  double largest = 0;
  for (const Eigen::Vector3d& point : head_points()) {
    Eigen::Vector3d backward = (now.apply(point) - before.apply(point)) / step_s;
    Eigen::Vector3d forward = (after.apply(point) - now.apply(point)) / step_s;
    largest = std::max(largest, (forward - backward).norm());
  }
  return largest;
}

/// The rotation angle of a transform, degrees.
double angle_deg(const RigidTransform& transform) {
  return Eigen::AngleAxisd(transform.rotation).angle() * 180.0 / kPi;
}

/// The rotation axis of a transform, turned so that the angle is positive.
Eigen::Vector3d axis(const RigidTransform& transform) {
  return Eigen::AngleAxisd(transform.rotation).axis();
}

void expect_identity(const RigidTransform& transform, const std::string& where) {
  EXPECT_LE(transform.rotation.angularDistance(Eigen::Quaterniond::Identity()), 1e-12) << where;
  EXPECT_LE(transform.translation_m.norm(), 1e-12) << where;
}

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance,
                 const std::string& where = "") {
  EXPECT_LE((actual - expected).norm(), tolerance)
      << where << ": " << actual.transpose() << " vs " << expected.transpose();
}

HeadKeyframe keyframe(double time_s, double yaw_deg, double pitch_deg = 0, double roll_deg = 0,
                      Eigen::Vector3d offset_m = Eigen::Vector3d::Zero()) {
  return {time_s, yaw_deg, pitch_deg, roll_deg, offset_m};
}

// --- RigidTransform ---------------------------------------------------------------

TEST(HeadMotionTransform, InverseUndoesApplyAndMatrixAgrees) {
  RigidTransform transform;
  transform.rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -0.5).normalized());
  transform.translation_m = Eigen::Vector3d(0.3, -1.2, 2.5);
  for (const Eigen::Vector3d& point : head_points()) {
    Eigen::Vector3d world = transform.apply(point);
    EXPECT_GT((world - point).norm(), 0.1);  // the transform does move the point
    expect_near(transform.apply_inverse(world), point, 1e-14, "apply_inverse(apply(x))");
    expect_near(transform.apply(transform.apply_inverse(point)), point, 1e-14,
                "apply(apply_inverse(x))");
    Eigen::Vector4d homogeneous = transform.matrix() * point.homogeneous();
    expect_near(homogeneous.head<3>(), world, 1e-14, "matrix()");
    EXPECT_EQ(homogeneous.w(), 1.0);
    // Directions rotate without the translation, and keep their length.
    expect_near(transform.rotate(point), world - transform.translation_m, 1e-14, "rotate()");
  }
}

// --- Presets ----------------------------------------------------------------------

TEST(HeadMotionPresets, NamesAreTheSixPresetsAndEachBuilds) {
  const std::vector<std::string> expected = {"still", "nod",  "shake",
                                             "turn",  "walk", "violent_shake"};
  EXPECT_EQ(HeadMotion::preset_names(), expected);
  for (const std::string& name : HeadMotion::preset_names()) {
    HeadMotion motion = HeadMotion::preset(name, kPivot);
    EXPECT_EQ(motion.name(), name);
    EXPECT_EQ(motion.is_still(), name == "still") << name;
  }
}

TEST(HeadMotionPresets, UnknownNameIsAUsageErrorListingTheNames) {
  try {
    HeadMotion::preset("headbang", kPivot);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::usage);
    std::string message = error.what();
    EXPECT_NE(message.find("headbang"), std::string::npos) << message;
    for (const std::string& name : HeadMotion::preset_names())
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
  EXPECT_THROW(HeadMotion::preset("nod", Eigen::Vector3d(0, NAN, 0)), Error);
}

TEST(HeadMotionPresets, NaturalDurations) {
  EXPECT_EQ(HeadMotion::preset("still", kPivot).natural_duration_s(), 1.0);
  EXPECT_EQ(HeadMotion::preset("nod", kPivot).natural_duration_s(), 2.0);
  EXPECT_EQ(HeadMotion::preset("shake", kPivot).natural_duration_s(), 2.0);
  EXPECT_EQ(HeadMotion::preset("turn", kPivot).natural_duration_s(), 4.0);
  EXPECT_EQ(HeadMotion::preset("walk", kPivot).natural_duration_s(), 2.0);
  EXPECT_EQ(HeadMotion::preset("violent_shake", kPivot).natural_duration_s(), 1.0);
}

TEST(HeadMotionPresets, StillIsTheIdentityAtEveryTime) {
  HeadMotion still = HeadMotion::preset("still", kPivot);
  for (double time_s : {0.0, 0.013, 0.5, 1.0, 2.7, 100.0})
    expect_identity(still.at(time_s), "still at " + std::to_string(time_s));
}

TEST(HeadMotionPresets, EachStartsAtRestWithZeroVelocityThenMoves) {
  for (const std::string& name : HeadMotion::preset_names()) {
    HeadMotion motion = HeadMotion::preset(name, kPivot);
    expect_identity(motion.at(0.0), name + " at t = 0");
    expect_identity(motion.at(-1.0), name + " before t = 0");
    // Forward differences over 1e-5 s: a motion starting with a speed v would show v.
    EXPECT_LE(forward_speed_m_per_s(motion, 0.0, 1e-5), 1e-5) << name;
    if (name == "still") continue;
    // Not vacuous: the head does move, at 0.05 m/s or more (turn, the slowest: 0.08 m/s).
    double fastest = 0;
    for (double time_s = 0; time_s < motion.natural_duration_s(); time_s += 0.01)
      fastest = std::max(fastest, forward_speed_m_per_s(motion, time_s, 1e-4));
    EXPECT_GT(fastest, 0.05) << name;
  }
}

TEST(HeadMotionPresets, VelocityHasNoJumps) {
  // Through the end of every ramp (0.125, 1/3, 0.5 s) and over two natural durations, the
  // velocity from the left and from the right agree to O(step).
  for (const std::string& name : HeadMotion::preset_names()) {
    HeadMotion motion = HeadMotion::preset(name, kPivot);
    std::vector<double> times = {1e-6, 0.125, 1.0 / 3.0, 0.5};
    for (double time_s = 0.005; time_s < 2 * motion.natural_duration_s(); time_s += 0.01)
      times.push_back(time_s);
    for (double time_s : times)
      EXPECT_LE(velocity_jump_m_per_s(motion, time_s, 1e-6), 1e-3) << name << " at " << time_s;
  }
}

TEST(HeadMotionPresets, NodPeaksAtTwentyDegreesAboutX) {
  HeadMotion nod = HeadMotion::preset("nod", kPivot);
  RigidTransform peak = nod.at(1.25);  // sin(2 pi 1.25) = 1, after the 0.5 s ramp
  EXPECT_NEAR(angle_deg(peak), 20.0, 1e-9);
  expect_near(axis(peak), Eigen::Vector3d::UnitX(), 1e-12, "nod axis");
  // +pitch tips the face (looking along +Z) down.
  EXPECT_LT(peak.rotate(Eigen::Vector3d::UnitZ()).y(), -0.3);
  // The opposite peak, and no more than 20 degrees anywhere.
  RigidTransform up = nod.at(1.75);
  EXPECT_NEAR(angle_deg(up), 20.0, 1e-9);
  expect_near(axis(up), -Eigen::Vector3d::UnitX(), 1e-12, "nod axis up");
  for (double time_s = 0; time_s < 3; time_s += 0.01)
    EXPECT_LE(angle_deg(nod.at(time_s)), 20.0 + 1e-9) << time_s;
}

TEST(HeadMotionPresets, PeakAnglesOfTheYawPresets) {
  struct Peak {
    std::string name;
    double time_s;
    double angle_deg;
  };
  for (const Peak& peak : {Peak{"shake", 1.25 / 1.5, 30.0}, Peak{"violent_shake", 1.25 / 4, 45.0},
                           Peak{"turn", 2.0, 60.0}}) {
    RigidTransform transform = HeadMotion::preset(peak.name, kPivot).at(peak.time_s);
    EXPECT_NEAR(angle_deg(transform), peak.angle_deg, 1e-9) << peak.name;
    expect_near(axis(transform), Eigen::Vector3d::UnitY(), 1e-12, peak.name + " axis");
  }
  // turn comes back to rest after its 4 s cycle.
  expect_identity(HeadMotion::preset("turn", kPivot).at(4.0), "turn at 4 s");
}

TEST(HeadMotionPresets, PivotStaysFixedUnderTheRotations) {
  for (const std::string& name :
       std::vector<std::string>{"nod", "shake", "turn", "violent_shake"}) {
    HeadMotion motion = HeadMotion::preset(name, kPivot);
    for (double time_s : {0.3, 0.7, 1.3, 2.2, 3.1}) {  // none where the head is upright
      RigidTransform transform = motion.at(time_s);
      expect_near(transform.apply(kPivot), kPivot, 1e-14, name);
      // while a point above it moves by the chord of the rotation angle on its circle about
      // the axis through the pivot
      Eigen::Vector3d above = kPivot + Eigen::Vector3d(0, 0.2, 0.1);
      Eigen::Vector3d from_axis_m =
          (above - kPivot) - (above - kPivot).dot(axis(transform)) * axis(transform);
      double chord_m = 2 * from_axis_m.norm() * std::sin(angle_deg(transform) * kPi / 360);
      EXPECT_NEAR((transform.apply(above) - above).norm(), chord_m, 1e-12)
          << name << " at " << time_s;
      EXPECT_GT(angle_deg(transform), 1.0) << name << " at " << time_s;
    }
  }
}

TEST(HeadMotionPresets, WalkGoesForwardWithBobAndSway) {
  HeadMotion walk = HeadMotion::preset("walk", kPivot);
  // After the 0.5 s ramp the pivot is 1.2 m/s (t - 0.25 s) ahead; the sway (1 Hz) and the
  // bob (2 Hz) are zero at whole seconds.
  for (double time_s : {1.0, 2.0, 3.0})
    expect_near(walk.at(time_s).apply(kPivot),
                kPivot + Eigen::Vector3d(0, 0, 1.2 * (time_s - 0.25)), 1e-12, "walk pivot");
  // Bob peak: sin(2 pi 2 Hz 2.125 s) = 1, sway sin(2 pi 2.125) = sqrt(1/2).
  expect_near(walk.at(2.125).apply(kPivot),
              kPivot + Eigen::Vector3d(0.02 * std::sqrt(0.5), 0.015, 1.2 * 1.875), 1e-12,
              "walk bob");
  // Sway peak: sin(2 pi 2.25) = 1, bob sin(2 pi 2 2.25) = 0.
  expect_near(walk.at(2.25).apply(kPivot), kPivot + Eigen::Vector3d(0.02, 0, 1.2 * 2.0), 1e-12,
              "walk sway");
  // Pitch of 3 deg at the bob peak.
  RigidTransform bob = walk.at(2.125);
  EXPECT_NEAR(angle_deg(bob), 3.0, 1e-9);
  expect_near(axis(bob), Eigen::Vector3d::UnitX(), 1e-12, "walk pitch axis");
  // The forward speed rises smoothly to 1.2 m/s: half of it at 0.25 s.
  double speed_m_per_s =
      (walk.at(0.25 + 1e-6).apply(kPivot).z() - walk.at(0.25 - 1e-6).apply(kPivot).z()) / 2e-6;
  EXPECT_NEAR(speed_m_per_s, 0.6, 1e-6);
}

TEST(HeadMotionPresets, AreDeterministic) {
  for (const std::string& name : HeadMotion::preset_names()) {
    HeadMotion a = HeadMotion::preset(name, kPivot), b = HeadMotion::preset(name, kPivot);
    for (double time_s : {0.0, 0.123, 0.77, 1.9}) {
      EXPECT_EQ(a.at(time_s).matrix(), b.at(time_s).matrix()) << name;
      EXPECT_EQ(a.at(time_s).matrix(), a.at(time_s).matrix()) << name;
    }
  }
}

// --- Keyframes given in code --------------------------------------------------------

TEST(HeadMotionKeyframes, YawHalfwayIsInterpolatedBySlerp) {
  HeadMotion motion =
      HeadMotion::from_keyframes({keyframe(0, 0, 0, 0, Eigen::Vector3d(0, 0, 0)),
                                  keyframe(2, 90, 0, 0, Eigen::Vector3d(0.2, 0, -0.4))},
                                 kPivot, "two keys");
  EXPECT_EQ(motion.name(), "two keys");
  EXPECT_EQ(motion.natural_duration_s(), 2.0);
  EXPECT_FALSE(motion.is_still());
  RigidTransform half = motion.at(1.0);
  EXPECT_NEAR(angle_deg(half), 45.0, 1e-9);
  expect_near(axis(half), Eigen::Vector3d::UnitY(), 1e-12, "halfway axis");
  expect_near(half.apply(kPivot), kPivot + Eigen::Vector3d(0.1, 0, -0.2), 1e-12, "offset");
  // A quarter of the way: 22.5 degrees (slerp turns at a constant rate).
  EXPECT_NEAR(angle_deg(motion.at(0.5)), 22.5, 1e-9);
}

TEST(HeadMotionKeyframes, HoldTheFirstPoseBeforeAndTheLastAfter) {
  HeadMotion motion = HeadMotion::from_keyframes(
      {keyframe(1, 10, 0, 0, Eigen::Vector3d(0, 0.1, 0)), keyframe(3, 50)}, kPivot, "keys");
  for (double time_s : {0.0, 0.5, 1.0}) {
    RigidTransform transform = motion.at(time_s);
    EXPECT_NEAR(angle_deg(transform), 10.0, 1e-9) << time_s;
    expect_near(transform.apply(kPivot), kPivot + Eigen::Vector3d(0, 0.1, 0), 1e-12, "before");
  }
  for (double time_s : {3.0, 3.5, 100.0}) {
    RigidTransform transform = motion.at(time_s);
    EXPECT_NEAR(angle_deg(transform), 50.0, 1e-9) << time_s;
    expect_near(transform.apply(kPivot), kPivot, 1e-12, "after");
  }
}

TEST(HeadMotionKeyframes, RotationIsYawTimesPitchTimesRoll) {
  // R = Ry(90) Rx(30) Rz(roll): the face (+Z) first tips down by 30 deg, then turns to +X.
  HeadMotion motion = HeadMotion::from_keyframes({keyframe(0, 90, 30, 0)}, kPivot, "one");
  expect_near(motion.at(0).rotate(Eigen::Vector3d::UnitZ()),
              Eigen::Vector3d(std::cos(kPi / 6), -0.5, 0), 1e-12, "face direction");
  // Roll (about +Z) first: Rz(90) takes +Y to -X, Rx(0), Ry(90) takes -X to +Z.
  HeadMotion rolled = HeadMotion::from_keyframes({keyframe(0, 90, 0, 90)}, kPivot, "rolled");
  expect_near(rolled.at(0).rotate(Eigen::Vector3d::UnitY()), Eigen::Vector3d::UnitZ(), 1e-12,
              "up direction");
}

TEST(HeadMotionKeyframes, StillWhenEveryPoseIsTheSame) {
  HeadKeyframe pose = keyframe(0, 20, -5, 3, Eigen::Vector3d(0.01, 0, 0));
  HeadKeyframe later = pose;
  later.time_s = 2;
  HeadMotion same = HeadMotion::from_keyframes({pose, later}, kPivot, "same");
  EXPECT_TRUE(same.is_still());
  EXPECT_TRUE(HeadMotion::from_keyframes({pose}, kPivot, "one").is_still());
  EXPECT_LE(largest_difference_m(same.at(0), same.at(1.3)), 1e-14);
  later.offset_m.y() = 1e-6;
  EXPECT_FALSE(HeadMotion::from_keyframes({pose, later}, kPivot, "moved").is_still());
  later = pose;
  later.time_s = 2;
  later.roll_deg += 1e-4;
  EXPECT_FALSE(HeadMotion::from_keyframes({pose, later}, kPivot, "turned").is_still());
}

TEST(HeadMotionKeyframes, FaultsAreUsageErrorsNamingTheSource) {
  struct Case {
    std::vector<HeadKeyframe> keyframes;
    std::string expected;  // in the message
  };
  const std::vector<Case> cases = {
      {{}, "no keyframes"},
      {{keyframe(-0.5, 0)}, "keyframe 0"},
      {{keyframe(0, 0), keyframe(1, 0), keyframe(1, 5)}, "keyframe 2"},
      {{keyframe(0, 0), keyframe(2, 0), keyframe(1, 5)}, "keyframe 2"},
      {{keyframe(0, 0), keyframe(1, NAN)}, "keyframe 1"},
      {{keyframe(0, 0, 0, 0, Eigen::Vector3d(0, INFINITY, 0))}, "keyframe 0"},
  };
  for (const Case& c : cases) {
    try {
      HeadMotion::from_keyframes(c.keyframes, kPivot, "my-source");
      ADD_FAILURE() << "no error for " << c.expected;
    } catch (const Error& error) {
      EXPECT_EQ(error.kind(), ErrorKind::usage) << error.what();
      EXPECT_EQ(error.file(), "my-source");
      EXPECT_NE(std::string(error.what()).find(c.expected), std::string::npos) << error.what();
    }
  }
}

TEST(HeadMotionKeyframes, NonFiniteTimeIsAUsageError) {
  HeadMotion motion = HeadMotion::preset("nod", kPivot);
  EXPECT_THROW(motion.at(NAN), Error);
  EXPECT_THROW(motion.at(INFINITY), Error);
}

// --- Keyframe CSV -------------------------------------------------------------------

class HeadMotionCsv : public FileTest {
 protected:
  /// Expects reading `text` to fail with bad input naming the file and `line`.
  void expect_bad_input(const std::string& text, int line, const std::string& reason_part) {
    std::string path = write_file("motion.csv", text).string();
    try {
      HeadMotion::from_keyframes_csv(path, kPivot);
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const Error& error) {
      std::string message = error.what();
      EXPECT_EQ(error.kind(), ErrorKind::bad_input) << message;
      EXPECT_NE(message.find(path), std::string::npos) << message;
      EXPECT_NE(message.find("line " + std::to_string(line) + ":"), std::string::npos) << message;
      EXPECT_NE(message.find(reason_part), std::string::npos) << message;
    }
  }
};

TEST_F(HeadMotionCsv, ReadsColumnsInAnyOrderWithCommentsAndMissingColumns) {
  std::string path = write_file("motion.csv",
                                "# a turn while rising\n"
                                "\n"
                                "  pitch_deg , time_s,offset_y_m,yaw_deg\n"
                                "# rest\n"
                                "0, 0, 0, 0\n"
                                "\t\n"
                                " 10 ,\t2.0 , 0.04 , +90  \r\n"
                                "0,3,0.04,90\n")
                         .string();
  HeadMotion motion = HeadMotion::from_keyframes_csv(path, kPivot);
  EXPECT_EQ(motion.name(), path);
  EXPECT_EQ(motion.natural_duration_s(), 3.0);
  EXPECT_FALSE(motion.is_still());
  expect_identity(motion.at(0), "csv at 0");
  // The second keyframe: yaw 90, pitch 10, roll 0 (missing), offset (0, 0.04, 0).
  HeadMotion expected = HeadMotion::from_keyframes(
      {keyframe(0, 90, 10, 0, Eigen::Vector3d(0, 0.04, 0))}, kPivot, "expected");
  EXPECT_LE(largest_difference_m(motion.at(2.0), expected.at(0)), 1e-12);
  // Halfway to it: yaw 45 about Y, offset 0.02 up.
  HeadMotion halfway = HeadMotion::from_keyframes(
      {keyframe(0, 0), keyframe(2, 90, 10, 0, Eigen::Vector3d(0, 0.04, 0))}, kPivot, "code");
  EXPECT_LE(largest_difference_m(motion.at(1.0), halfway.at(1.0)), 1e-12);
  expect_near(motion.at(1.0).apply(kPivot), kPivot + Eigen::Vector3d(0, 0.02, 0), 1e-12,
              "offset halfway");
  // Reading the same file again gives the same transforms.
  HeadMotion again = HeadMotion::from_keyframes_csv(path, kPivot);
  for (double time_s : {0.0, 0.7, 1.5, 2.9, 4.0})
    EXPECT_EQ(again.at(time_s).matrix(), motion.at(time_s).matrix());
}

TEST_F(HeadMotionCsv, TimeOnlyIsStill) {
  std::string path = write_file("still.csv", "time_s\n0\n1.5\n").string();
  HeadMotion motion = HeadMotion::from_keyframes_csv(path, kPivot);
  EXPECT_TRUE(motion.is_still());
  EXPECT_EQ(motion.natural_duration_s(), 1.5);
  expect_identity(motion.at(0.8), "time-only csv");
}

TEST_F(HeadMotionCsv, AllColumns) {
  std::string path =
      write_file("all.csv",
                 "offset_z_m,offset_y_m,offset_x_m,roll_deg,pitch_deg,yaw_deg,time_s\n"
                 "0.3,0.2,0.1,7,-4,12,0.5\n")
          .string();
  HeadMotion motion = HeadMotion::from_keyframes_csv(path, kPivot);
  HeadMotion expected = HeadMotion::from_keyframes(
      {keyframe(0.5, 12, -4, 7, Eigen::Vector3d(0.1, 0.2, 0.3))}, kPivot, "expected");
  EXPECT_LE(largest_difference_m(motion.at(0.0), expected.at(0.0)), 1e-15);
  EXPECT_TRUE(motion.is_still());
}

TEST_F(HeadMotionCsv, MissingFileIsBadInputNamingIt) {
  std::string path = (directory_ / "absent.csv").string();
  try {
    HeadMotion::from_keyframes_csv(path, kPivot);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
}

TEST_F(HeadMotionCsv, NoHeaderIsBadInputNamingTheFile) {
  std::string path = write_file("empty.csv", "# nothing here\n\n").string();
  try {
    HeadMotion::from_keyframes_csv(path, kPivot);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("no header"), std::string::npos) << error.what();
  }
}

TEST_F(HeadMotionCsv, HeaderErrorsNameTheLine) {
  expect_bad_input("# comment\nyaw_deg,pitch_deg\n10,0\n", 2, "no time_s");
  expect_bad_input("time_s,yaw_deg,elbow_deg\n0,0,0\n", 1, "unknown column 'elbow_deg'");
  expect_bad_input("0,10\n1,20\n", 1, "unknown column '0'");
  expect_bad_input("\ntime_s,yaw_deg,time_s\n0,0,0\n", 2, "repeated");
  expect_bad_input("time_s,,yaw_deg\n0,0,0\n", 1, "unknown column ''");
}

TEST_F(HeadMotionCsv, RowErrorsNameTheLine) {
  expect_bad_input("time_s,yaw_deg\n0,0\n1,20,3\n", 3, "expected 2 cells");
  expect_bad_input("time_s,yaw_deg\n0,0\n1\n", 3, "expected 2 cells");
  expect_bad_input("time_s,yaw_deg\n0,0\n# c\n1,twenty\n", 4, "yaw_deg 'twenty' is not a number");
  expect_bad_input("time_s,yaw_deg\n0,0\n1,\n", 3, "yaw_deg '' is not a number");
  expect_bad_input("time_s,yaw_deg\n0,0\n1,20deg\n", 3, "is not a number");
  expect_bad_input("time_s,yaw_deg\n0,nan\n", 2, "not a finite number");
  expect_bad_input("time_s,pitch_deg\n0,0\n1,-inf\n", 3, "not a finite number");
  expect_bad_input("time_s,offset_x_m\n0,1e999\n", 2, "not a finite number");  // out of range
}

TEST_F(HeadMotionCsv, KeyframeErrorsNameTheLine) {
  expect_bad_input("# header next\ntime_s,yaw_deg\n# none\n", 2, "no keyframe");
  expect_bad_input("time_s,yaw_deg\n\n-0.5,0\n1,10\n", 3, "negative");
  expect_bad_input("time_s,yaw_deg\n0,0\n1,10\n# c\n1,20\n", 5, "not after");
  expect_bad_input("time_s,yaw_deg\n0,0\n2,10\n1,20\n", 4, "not after");
}

}  // namespace
}  // namespace hair
