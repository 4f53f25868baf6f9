#include "model/turntable.h"

#include <cmath>

#include "common/units.h"
#include "model/sim_config.h"

namespace fog::model {

double Turntable::Segment::angleDeg(double t) const {
  const double tt = std::min(t, endS);  // after the swing the axis holds its last angle
  return centreDeg + amplitudeDeg * (std::sin(omega * (tt - startS) + phaseRad) - std::sin(phaseRad));
}

Turntable::Turntable(const TestPlan& plan, const TurntableParams& params) {
  // The run starts with the table at rest for restBetweenS, so that the first
  // status and IMU frames precede any motion.
  double t = plan.restBetweenS;
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    const TestPoint& p = plan.points[i];
    TestPointSchedule s;
    s.index = static_cast<int>(i);
    s.point = p;
    s.swingStartS = t;
    s.recordStartS = t + p.settleS;
    s.recordEndS = s.recordStartS + p.durationS;
    s.angularFrequencyRadPerS = kTwoPi * p.frequencyHz * (1.0 + params.frequencyErrorPpm * 1e-6);
    schedule_.push_back(s);

    // Swing about the angle the axis holds when the point starts, so the
    // motion is continuous between points: angle = centre + A*(sin(w*t + p0) - sin(p0)).
    double centre = 0.0;
    for (auto it = segments_.rbegin(); it != segments_.rend(); ++it)
      if (it->axis == p.axis) {
        centre = it->angleDeg(it->endS);
        break;
      }
    segments_.push_back({p.axis, s.swingStartS, s.recordEndS, centre, p.amplitudeDeg,
                         s.angularFrequencyRadPerS, p.startPhaseDeg * kRadPerDeg});
    t = s.recordEndS + plan.restBetweenS;
  }
  endS_ = t;
}

std::array<double, kAxisCount> Turntable::anglesDeg(double timeS) const {
  std::array<double, kAxisCount> out{};
  std::array<bool, kAxisCount> done{};
  // The latest segment on an axis that has started decides its angle.
  for (auto it = segments_.rbegin(); it != segments_.rend(); ++it) {
    const int a = static_cast<int>(it->axis);
    if (done[a] || timeS < it->startS) continue;
    out[a] = it->angleDeg(timeS);
    done[a] = true;
  }
  return out;
}

}  // namespace fog::model
