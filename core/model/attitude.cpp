#include "core/model/attitude.h"

#include <cmath>

#include <Eigen/Geometry>

#include "core/common/units.h"
#include "core/model/sim_config.h"

namespace fog::model {

Eigen::Matrix3d axisRotation(Axis axis, double angleDeg) {
  const double a = angleDeg * kRadPerDeg;
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d r;
  switch (axis) {
    case Axis::kX: r << 1, 0, 0, 0, c, -s, 0, s, c; break;
    case Axis::kY: r << c, 0, s, 0, 1, 0, -s, 0, c; break;
    case Axis::kZ: r << c, -s, 0, s, c, 0, 0, 0, 1; break;
  }
  return r;
}

Eigen::Matrix3d rotationAbout(const Eigen::Vector3d& unitAxis, double angleDeg) {
  const double a = angleDeg * kRadPerDeg;
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d cross;
  cross << 0, -unitAxis.z(), unitAxis.y(), unitAxis.z(), 0, -unitAxis.x(), -unitAxis.y(), unitAxis.x(), 0;
  return c * Eigen::Matrix3d::Identity() + s * cross + (1.0 - c) * unitAxis * unitAxis.transpose();
}

Eigen::Matrix3d baseTilt(const TurntableParams& table) {
  const double az = table.baseTiltAzimuthDeg * kRadPerDeg;
  return rotationAbout(Eigen::Vector3d(std::cos(az), std::sin(az), 0.0), table.baseTiltDeg);
}

Attitude::Attitude(const EarthParams& earth, const TurntableParams& table)
    : tableToLocal_(axisRotation(Axis::kZ, earth.headingDeg) *
                    Eigen::Vector3d(1.0, earth.zUp ? -1.0 : 1.0, earth.zUp ? -1.0 : 1.0).asDiagonal()),
      mounting_(axisRotation(Axis::kZ, table.mountingDeg[2]) * axisRotation(Axis::kY, table.mountingDeg[1]) *
                axisRotation(Axis::kX, table.mountingDeg[0])),
      order_(table.axisOrder),
      earthLocalDegPerH_(Eigen::Vector3d::Map(earth.rateLocalDegPerH().data())) {
  if (table.baseTiltDeg != 0.0) tableToLocal_ = baseTilt(table) * tableToLocal_;
  // The middle axis leans toward the outer one, the inner toward the middle.
  for (int k = 1; k < kAxisCount; ++k) {
    const double d = table.nonOrthogonalityArcsec[static_cast<std::size_t>(k - 1)];
    if (d == 0.0) continue;
    const auto self = static_cast<std::size_t>(order_[static_cast<std::size_t>(k)]);
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(static_cast<int>(self));
    const Eigen::Vector3d toward = Eigen::Vector3d::Unit(static_cast<int>(order_[static_cast<std::size_t>(k - 1)]));
    lean_[self] = rotationAbout(e.cross(toward), d / kArcsecPerDeg);
    leaning_[self] = true;
  }
}

Eigen::Matrix3d Attitude::rotation(Axis axis, double angleDeg) const {
  const auto a = static_cast<std::size_t>(axis);
  if (!leaning_[a]) return axisRotation(axis, angleDeg);
  return lean_[a] * axisRotation(axis, angleDeg) * lean_[a].transpose();
}

const Eigen::Matrix3d& AxisRotations::of(Axis axis, double angleDeg) {
  const auto a = static_cast<std::size_t>(axis);
  if (!known_[a] || angleDeg_[a] != angleDeg) {
    rotation_[a] = axisRotation(axis, angleDeg);
    angleDeg_[a] = angleDeg;
    known_[a] = true;
  }
  return rotation_[a];
}

Eigen::Matrix3d Attitude::bodyToTable(const TableAngles& tableDeg) const {
  Eigen::Matrix3d c = Eigen::Matrix3d::Identity();
  for (Axis a : order_) c = c * rotation(a, tableDeg[static_cast<std::size_t>(a)]);
  return c * mounting_;
}

Eigen::Matrix3d Attitude::bodyToTable(const TableAngles& tableDeg, AxisRotations& rotations) const {
  Eigen::Matrix3d c = Eigen::Matrix3d::Identity();
  for (Axis a : order_) {
    const auto k = static_cast<std::size_t>(a);
    if (leaning_[k])
      c = c * lean_[k] * rotations.of(a, tableDeg[k]) * lean_[k].transpose();
    else
      c = c * rotations.of(a, tableDeg[k]);
  }
  return c * mounting_;
}

Eigen::Vector3d Attitude::earthRateBodyDegPerH(const Eigen::Matrix3d& bodyToTable) const {
  return (tableToLocal_ * bodyToTable).transpose() * earthLocalDegPerH_;
}

Eigen::Vector3d Attitude::specificForceBodyG(const Eigen::Matrix3d& bodyToTable) const {
  // At rest the specific force is 1 g up: (0, 0, -1) in north-east-down.
  return (tableToLocal_ * bodyToTable).transpose() * Eigen::Vector3d(0.0, 0.0, -1.0);
}

Eigen::Vector3d Attitude::tableAxisInBody(Axis axis, const TableAngles& tableDeg) const {
  // Axis k turns everything inside it: its direction in the body frame is
  // e_k seen through the rotations of the axes inside it and the mounting.
  Eigen::Matrix3d inner = Eigen::Matrix3d::Identity();
  bool inside = false;
  for (Axis a : order_) {
    if (inside) inner = inner * rotation(a, tableDeg[static_cast<std::size_t>(a)]);
    if (a == axis) inside = true;
  }
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(static_cast<int>(axis));
  const auto k = static_cast<std::size_t>(axis);
  return (inner * mounting_).transpose() * (leaning_[k] ? Eigen::Vector3d(lean_[k] * e) : e);
}

Eigen::Vector3d Attitude::rotationBetweenDeg(const Eigen::Matrix3d& from, const Eigen::Matrix3d& to) const {
  const Eigen::Matrix3d d = from.transpose() * to;  // body(from) -> body(to)
  // Rotation vector of d: sin(theta) * axis from the antisymmetric part,
  // cos(theta) from the trace; atan2 keeps small angles exact.
  const Eigen::Vector3d v(0.5 * (d(2, 1) - d(1, 2)), 0.5 * (d(0, 2) - d(2, 0)), 0.5 * (d(1, 0) - d(0, 1)));
  const double s = v.norm();
  if (s == 0.0) return Eigen::Vector3d::Zero();
  const double theta = std::atan2(s, 0.5 * (d.trace() - 1.0));
  return v * (theta / s * kDegPerRad);
}

}  // namespace fog::model
