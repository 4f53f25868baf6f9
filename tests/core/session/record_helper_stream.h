#pragma once
// The stream the record helper produces, shared with the kill -9 test so the
// test can regenerate exactly what the helper was recording.

#include "core/common/test_plan.h"
#include "core/model/sim_config.h"

namespace fog::test {

inline TestPlan recordHelperPlan() {
  TestPoint p;
  p.axis = Axis::kY;
  p.frequencyHz = 1.0;
  p.amplitudeDeg = 3.0;
  p.durationS = 20.0;  // far longer than the test lets it run
  p.settleS = 0.3;
  TestPlan plan;
  // Recording starts 0.5 s into the stream, well before the kill at ~1.5 s:
  // the interrupted session must hold a test point with samples, not one
  // that had only just begun.
  plan.restBetweenS = 0.2;
  plan.points.push_back(p);
  return plan;
}

inline model::SimConfig recordHelperConfig() {
  model::SimConfig c;
  c.seed = 11;
  return c;
}

}  // namespace fog::test
