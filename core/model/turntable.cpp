#include "core/model/turntable.h"

#include <algorithm>
#include <cmath>

#include "core/common/units.h"
#include "core/model/sim_config.h"

namespace fog::model {

double Turntable::Piece::angleDeg(double t) const {
  const double tt = std::clamp(t, startS, endS);  // after the piece the axis holds its last angle
  if (swing) return centreDeg + amplitudeDeg * std::sin(omega * (tt - startS) + phaseRad);
  if (endS <= startS) return toDeg;
  const double u = (tt - startS) / (endS - startS);
  return fromDeg + (toDeg - fromDeg) * 0.5 * (1.0 - std::cos(kPi * u));
}

void Turntable::addMoves(double startS, double durationS, std::array<double, kAxisCount>& angles,
                         const std::array<double, kAxisCount>& target) {
  int moving = 0;
  for (int a = 0; a < kAxisCount; ++a) moving += target[a] != angles[a];
  if (moving == 0) return;
  // Each axis in its share of the rest, outer axes of the index order first;
  // TestPlan::validate keeps the moves within the table's limits.
  const double share = durationS / moving;
  double t = startS;
  for (int a = 0; a < kAxisCount; ++a) {
    if (target[a] == angles[a]) continue;
    Piece m;
    m.axis = static_cast<Axis>(a);
    m.startS = t;
    m.endS = t + share;
    m.fromDeg = angles[a];
    m.toDeg = target[a];
    m.held = angles;
    pieces_.push_back(m);
    angles[a] = target[a];
    t += share;
  }
}

Turntable::Turntable(const TestPlan& plan, const TurntableParams& params) {
  // The run starts with the table at rest at zero; the first rest moves it
  // to the first point, so the first status and IMU frames precede any swing.
  std::array<double, kAxisCount> angles{};
  double t = 0.0;
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    const TestPoint& p = plan.points[i];
    addMoves(t, plan.restBetweenS, angles, plan.startAnglesDeg(i));
    t += plan.restBetweenS;
    TestPointSchedule s;
    s.index = static_cast<int>(i);
    s.point = p;
    s.swingStartS = t;
    s.recordStartS = t + p.settleS;
    s.recordEndS = s.recordStartS + p.durationS;
    s.angularFrequencyRadPerS =
        p.isStatic() ? 0.0 : kTwoPi * p.frequencyHz * (1.0 + params.frequencyErrorPpm * 1e-6);
    schedule_.push_back(s);
    if (!p.isStatic()) {
      Piece w;
      w.axis = p.axis;
      w.startS = s.swingStartS;
      w.endS = s.recordEndS;
      w.swing = true;
      w.centreDeg = p.positionDeg[static_cast<int>(p.axis)];
      w.amplitudeDeg = p.amplitudeDeg;
      w.omega = s.angularFrequencyRadPerS;
      w.phaseRad = p.startPhaseDeg * kRadPerDeg;
      w.held = angles;
      pieces_.push_back(w);
      angles[static_cast<int>(p.axis)] = w.angleDeg(w.endS);
    }
    t = s.recordEndS;
  }
  addMoves(t, plan.restBetweenS, angles, {});
  endS_ = t + plan.restBetweenS;
}

std::array<double, kAxisCount> Turntable::anglesDeg(double timeS) const {
  // The last piece that has started decides: its axis follows it (or holds
  // its end), every other axis holds what it held then.
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), timeS,
                             [](double t, const Piece& p) { return t < p.startS; });
  if (it == pieces_.begin()) return {};
  const Piece& p = *std::prev(it);
  auto out = p.held;
  out[static_cast<int>(p.axis)] = p.angleDeg(timeS);
  return out;
}

}  // namespace fog::model
