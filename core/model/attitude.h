#pragma once
// The IMU's attitude on the three-axis table, and what it senses there.
//
// Frames (docs/simulator.md, "Geometry"):
//  - local level frame: north-east-down (NED). Earth rate in it is
//    Omega * (cos(lat), 0, -sin(lat)); gravity points along +down, so the
//    specific force at rest is (0, 0, -1) g.
//  - table frame: the table's axes at zero angles, the local frame turned by
//    the heading about down (heading 0: table x north, y east, z down) and,
//    for a table whose z points up (EarthParams::zUp), half a turn about x:
//    L = R_z(heading) R_x(180) (heading 90: x east, y north, z up).
//  - body frame: the IMU's gyro axes. With the table axes in order outer,
//    middle, inner (default z, y, x) and the IMU mounted on the inner frame:
//        C_bn = L R_outer(a_o) R_middle(a_m) R_inner(a_i) M
//    where R_k(a) is the right-handed rotation by +a about axis k and
//    M = R_z(yaw) R_y(pitch) R_x(roll) the mounting. With zero angles and
//    mounting, gyro x senses table axis x, and so on.
//  - a tilted base (TurntableParams::baseTiltDeg) turns the table frame in
//    the local one: L becomes B L with B the rotation by the tilt about the
//    horizontal axis (cos az, sin az, 0) at the tilt's azimuth.
//  - non-orthogonal axes (TurntableParams::nonOrthogonalityArcsec): the
//    middle axis turns about D e_m, D the rotation by the lean from e_m
//    toward e_outer (about e_m x e_outer), so R_middle(a) becomes
//    D R_middle(a) D^T; the inner axis leans toward the middle one likewise.
//
// Pure functions of their arguments; thread-safe.

#include <array>

#include <Eigen/Core>

#include "core/common/test_plan.h"

namespace fog::model {

struct EarthParams;
struct TurntableParams;

using TableAngles = std::array<double, kAxisCount>;  // deg, indexed by Axis

// Each table axis' rotation, kept while its angle holds: in a swing two of
// the three axes stand still, so a simulator that asks at every sample
// computes one sine and cosine instead of three. Gives exactly what
// axisRotation() gives. One per simulator (not thread-safe).
class AxisRotations {
 public:
  const Eigen::Matrix3d& of(Axis axis, double angleDeg);

 private:
  std::array<double, kAxisCount> angleDeg_{};
  std::array<bool, kAxisCount> known_{};
  std::array<Eigen::Matrix3d, kAxisCount> rotation_;
};

class Attitude {
 public:
  Attitude(const EarthParams& earth, const TurntableParams& table);

  // Body to local-level rotation for the attitude bodyToTable() (adds L).
  Eigen::Matrix3d bodyToLocal(const Eigen::Matrix3d& bodyToTable) const { return tableToLocal_ * bodyToTable; }
  // Body to table-frame rotation (the motion alone, no heading).
  Eigen::Matrix3d bodyToTable(const TableAngles& tableDeg) const;
  // The same, with the axes' rotations from (and kept in) `rotations`.
  Eigen::Matrix3d bodyToTable(const TableAngles& tableDeg, AxisRotations& rotations) const;

  // Earth rate in the body frame, deg/h, for the attitude bodyToTable().
  Eigen::Vector3d earthRateBodyDegPerH(const Eigen::Matrix3d& bodyToTable) const;
  // Specific force of gravity at rest in the body frame, in g (|f| = 1).
  Eigen::Vector3d specificForceBodyG(const Eigen::Matrix3d& bodyToTable) const;
  // Direction, in the body frame, of table axis `axis` (unit vector): a rate
  // about that axis is sensed by the gyros in these proportions.
  Eigen::Vector3d tableAxisInBody(Axis axis, const TableAngles& tableDeg) const;

  // The body's rotation from attitude `from` to attitude `to` as a rotation
  // vector in the body frame, deg. For a motion of one table axis at a time
  // this is exactly the integral of the body rate between the two instants
  // (the rotation axis is fixed in the body); rotations must stay below 180
  // deg between calls.
  Eigen::Vector3d rotationBetweenDeg(const Eigen::Matrix3d& fromBodyToTable,
                                     const Eigen::Matrix3d& toBodyToTable) const;

 private:
  // The rotation about table axis `axis`, leaning when it does.
  Eigen::Matrix3d rotation(Axis axis, double angleDeg) const;

  Eigen::Matrix3d tableToLocal_, mounting_;  // L and M above
  std::array<Eigen::Matrix3d, kAxisCount> lean_;  // D of each leaning axis
  std::array<bool, kAxisCount> leaning_{};
  std::array<Axis, kAxisCount> order_{};  // outer to inner
  Eigen::Vector3d earthLocalDegPerH_;
};

// The proper rotation by +angleDeg about table axis `axis`.
Eigen::Matrix3d axisRotation(Axis axis, double angleDeg);
// The proper rotation by +angleDeg about a unit vector.
Eigen::Matrix3d rotationAbout(const Eigen::Vector3d& unitAxis, double angleDeg);

}  // namespace fog::model
