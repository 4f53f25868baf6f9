#pragma once
// Steady-swing windows in a continuous recording that carries no test-point
// markers (another bench's export, a board without markers): where the table
// swings one axis steadily, between rests and the ramps into and out of them.
//
// Method: the table rests where its angle stays within a narrow band for a
// second or more (the band: 20 times the angle's step noise, at least 1e-4 of
// its whole range); the stretches between rests are candidate swings. In each,
// the swing frequency comes from the periodogram (validity.h) and the window
// is the longest run of whole periods whose amplitude is within 1 % of the
// stretch's median amplitude, less its first and last period (ramps up and
// down are left out). Windows with fewer than two whole periods are dropped.

#include <string>
#include <vector>

#include "core/common/recording.h"
#include "core/common/status.h"

namespace fog::analysis {

struct SwingWindow {
  double startS = 0.0, endS = 0.0;  // on the recording's time axis
  double frequencyHz = 0.0;         // 0 when given by the user and not measured
  double amplitudeDeg = 0.0;
};

// Finds the windows on `axis`. Fails with a reason when there is none.
Result<std::vector<SwingWindow>> findSwingWindows(const std::vector<TableSample>& table, Axis axis);

// "12.5-42,50-80.25": windows given by the user (seconds, ascending, not
// overlapping).
Result<std::vector<SwingWindow>> parseSwingWindows(const std::string& text);

// One test point per window: table and IMU rows whose times fall inside it,
// on the whole record's axis; index from 0, nominal frequency and amplitude
// from the window (0 when not measured).
std::vector<TestPointData> splitIntoWindows(const TestPointData& whole, const std::vector<SwingWindow>& windows);

}  // namespace fog::analysis
