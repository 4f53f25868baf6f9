#pragma once
// Turntable motion: the test plan turned into an exact (analytic) angle for
// every axis at any instant. At most one axis moves at a time: a point's
// swing, or one axis of a move between points (docs/simulator.md, "Table
// motion"). The run starts with every axis at zero; before each point the
// table moves to where the point starts (its position, the swing axis at
// position + A sin(start phase)), one axis after the other in the rest
// before it; after the last point it returns to zero.

#include <array>
#include <vector>

#include "core/common/test_plan.h"

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
  // One axis moving over [startS, endS]: a swing about centreDeg, or a
  // raised-cosine move from fromDeg to toDeg. Every other axis holds the
  // angle it has in `held`.
  struct Piece {
    Axis axis = Axis::kX;
    double startS = 0.0, endS = 0.0;
    bool swing = false;
    double centreDeg = 0.0, amplitudeDeg = 0.0, omega = 0.0, phaseRad = 0.0;  // swing
    double fromDeg = 0.0, toDeg = 0.0;                                         // move
    std::array<double, kAxisCount> held{};
    double angleDeg(double t) const;
  };
  void addMoves(double startS, double durationS, std::array<double, kAxisCount>& angles,
                const std::array<double, kAxisCount>& target);

  std::vector<TestPointSchedule> schedule_;
  std::vector<Piece> pieces_;  // in time order, not overlapping
  double endS_ = 0.0;
};

}  // namespace fog::model
