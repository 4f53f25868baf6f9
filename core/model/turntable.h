#pragma once
// Turntable motion: the test plan turned into an exact (analytic) angle for
// every axis at any instant. One axis swings at a time; the others hold.

#include <array>
#include <vector>

#include "common/test_plan.h"

namespace fog::model {

struct TurntableParams;

// When each test point settles, records and ends, in true seconds from the
// start of the run.
struct TestPointSchedule {
  int index = 0;
  TestPoint point;
  double swingStartS = 0.0;
  double recordStartS = 0.0;
  double recordEndS = 0.0;
  double angularFrequencyRadPerS = 0.0;  // including the table's rate error
};

class Turntable {
 public:
  Turntable(const TestPlan& plan, const TurntableParams& params);

  // Table angles at timeS (any order of calls; pure).
  std::array<double, kAxisCount> anglesDeg(double timeS) const;
  const std::vector<TestPointSchedule>& schedule() const { return schedule_; }
  double endS() const { return endS_; }

 private:
  struct Segment {  // one axis swinging around centreDeg
    Axis axis;
    double startS, endS, centreDeg, amplitudeDeg, omega, phaseRad;
    double angleDeg(double t) const;
  };
  std::vector<TestPointSchedule> schedule_;
  std::vector<Segment> segments_;
  double endS_ = 0.0;
};

}  // namespace fog::model
