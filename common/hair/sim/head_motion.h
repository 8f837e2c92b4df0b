#pragma once
// The rigid motion of the body and head that the simulate stage gives the hair roots:
// built-in presets or keyframes, one world-from-rest transform per time.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace hair {

/// A rigid transform x -> rotation * x + translation_m (world from rest). The rotation
/// must be a unit quaternion (apply_inverse() uses its conjugate).
struct RigidTransform {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< unit quaternion
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();       ///< metres

  /// The world position of the rest position `point_m`.
  Eigen::Vector3d apply(const Eigen::Vector3d& point_m) const;
  /// The rest position of the world position `point_m` (the inverse of apply()).
  Eigen::Vector3d apply_inverse(const Eigen::Vector3d& point_m) const;
  /// The world direction of the rest direction `direction` (rotation only, no translation).
  Eigen::Vector3d rotate(const Eigen::Vector3d& direction) const;
  /// The 4 x 4 homogeneous matrix [R t; 0 1] of the transform.
  Eigen::Matrix4d matrix() const;
};

/// One keyframe: a time and the pose of the head about the pivot. Angles in degrees,
/// the rotation R = Ry(yaw) * Rx(pitch) * Rz(roll): yaw about +Y (up), pitch about +X
/// (positive tips the face, which looks along +Z, down), roll about +Z.
struct HeadKeyframe {
  double time_s = 0;                                   ///< seconds, >= 0
  double yaw_deg = 0;                                  ///< about +Y
  double pitch_deg = 0;                                ///< about +X
  double roll_deg = 0;                                 ///< about +Z
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();  ///< translation of the pivot, metres
};

/// The rigid motion of the body and head over time: at time t the rest position x goes to
/// pivot + offset(t) + R(t) (x - pivot). Coordinates in metres, +Y up, the face looking
/// along +Z (MakeHuman).
///
/// The presets are deterministic closed forms. Each starts at the identity pose with zero
/// velocity and zero acceleration at t = 0 (turn: zero velocity, see below), so that a
/// simulation starting from rest gets no jolt. An oscillation A sin(2 pi f t) is
/// multiplied by the ramp r(t) = q(min(t / T, 1)), q(u) = 6u^5 - 15u^4 + 10u^3 (smootherstep,
/// C^2), T being half the period 1 / (2 f) unless stated otherwise; so the motion is C^2
/// and reaches its full amplitude A after T. The presets:
///   - still: the identity at every time. Natural duration 1 s.
///   - nod: pitch 20 deg r(t) sin(2 pi 1 Hz t), T = 0.5 s; peaks of +20 deg (face down) at
///     t = 1.25 s, 2.25 s, ... Natural duration 2 s (two nods).
///   - shake: yaw 30 deg r(t) sin(2 pi 1.5 Hz t), T = 1/3 s. Natural duration 2 s (three
///     shakes).
///   - turn: yaw 30 deg (1 - cos(2 pi t / 4 s)), from 0 to 60 deg at t = 2 s and back to 0 at
///     4 s; zero velocity at t = 0, acceleration 30 deg (2 pi / 4 s)^2 = 1.29 rad/s^2 there.
///     Natural duration 4 s (one cycle).
///   - walk: forward along +Z at 1.2 m/s, the speed 1.2 m/s r(t) with T = 0.5 s, so the
///     offset is z = 0.6 m at t = 1 s and 1.2 m/s (t - 0.25 s) from t = 0.5 s on; vertical
///     bob y = 0.015 m r(t) sin(2 pi 2 Hz t); lateral sway x = 0.02 m r(t) sin(2 pi 1 Hz t);
///     pitch 3 deg r(t) sin(2 pi 2 Hz t); all with T = 0.5 s. Natural duration 2 s (two
///     strides of both feet).
///   - violent_shake: yaw 45 deg r(t) sin(2 pi 4 Hz t), T = 0.125 s. Natural duration 1 s
///     (four shakes).
///
/// Keyframes: between two keyframes the rotation is the quaternion slerp of theirs (the
/// shorter way round: keyframes more than 180 deg apart need keyframes between them) and
/// the offset is linear; before the first keyframe the first pose holds, after the last
/// the last. One keyframe is a constant pose.
///
/// Times before 0 give the pose at 0 (the head rests before the motion starts).
class HeadMotion {
 public:
  /// Names of the built-in presets: still, nod, shake, turn, walk, violent_shake.
  static const std::vector<std::string>& preset_names();

  /// The preset `name` about `pivot_m` (the base of the head, metres).
  /// Throws Error::usage for an unknown name (listing the names) or a non-finite pivot.
  static HeadMotion preset(const std::string& name, const Eigen::Vector3d& pivot_m);

  /// Keyframes from the CSV file `path`, about `pivot_m`. The file: a header line naming
  /// columns in any order among time_s, yaw_deg, pitch_deg, roll_deg, offset_x_m,
  /// offset_y_m, offset_z_m (only time_s required, a missing column reads as 0), then one
  /// keyframe a line with as many comma-separated numbers; lines starting with '#' and
  /// blank lines are skipped, whitespace around cells is trimmed.
  /// Throws Error bad_input naming the file (and the line, where there is one) for a file
  /// that cannot be read, no header, a header without time_s or with an unknown or repeated
  /// column, a line with another number of cells, a cell that is not a finite number, no
  /// keyframe, a negative first time or times not strictly increasing; Error::usage for a
  /// non-finite pivot.
  static HeadMotion from_keyframes_csv(const std::string& path, const Eigen::Vector3d& pivot_m);

  /// Keyframes given in code, about `pivot_m`; `source` names them in errors and is the
  /// name(). Throws Error usage ("<source>:keyframe <i>: <reason>") for the same faults as
  /// from_keyframes_csv(): a non-finite value, no keyframe, a negative first time or times
  /// not strictly increasing; and for a non-finite pivot.
  static HeadMotion from_keyframes(std::vector<HeadKeyframe> keyframes,
                                   const Eigen::Vector3d& pivot_m, const std::string& source);

  /// The world-from-rest transform at `time_s`: x_world = pivot + offset + R (x_rest - pivot).
  /// Times below 0 give the transform at 0. Throws Error::usage for a non-finite time.
  RigidTransform at(double time_s) const;

  /// Whether the transform is the same at every time: the still preset, or keyframes that
  /// all have the same pose (rotations within 1e-12 rad, offsets within 1e-12 m). The
  /// constant transform of keyframes need not be the identity.
  bool is_still() const;

  /// The preset's name, the CSV path, or the `source` of from_keyframes().
  const std::string& name() const;

  /// The length of one natural cycle of a preset (see the class comment), so that a default
  /// duration can be chosen; the last keyframe's time for keyframes.
  double natural_duration_s() const;

  /// The pivot the motion turns about, metres.
  const Eigen::Vector3d& pivot_m() const { return pivot_m_; }

 private:
  /// A preset's pose at a time >= 0 (time_s of the result unused).
  using PresetPose = HeadKeyframe (*)(double time_s);

  HeadMotion() = default;

  std::string name_;
  Eigen::Vector3d pivot_m_ = Eigen::Vector3d::Zero();
  PresetPose preset_pose_ = nullptr;              // null for keyframes
  std::vector<double> key_time_s_;                // keyframe times, strictly increasing
  std::vector<Eigen::Quaterniond> key_rotation_;  // keyframe rotations
  std::vector<Eigen::Vector3d> key_offset_m_;     // keyframe offsets
  double natural_duration_s_ = 0;
  bool still_ = false;
};

}  // namespace hair
