#pragma once
// How much of a test point's record the data cover, and whether what is
// missing still allows a delay (docs/serial.md, "What the analysis says").
//
// Gaps are found from the samples themselves, so they are seen whatever the
// source: table frames missing from the 1 ms stamp grid (an interval longer
// than 1.5 median intervals), IMU frames missing by their sequence gap
// (ImuSample::lostBefore). The stream's own counters for the test point
// (duplicates, checksum failures, skipped bytes) come from
// TestPointData::health where the source knows them.
//
// A delay is refused, with the reason, when
//  - the data cover fewer than two whole swing periods (gaps excluded), or
//  - a gap in either channel is longer than one swing period: across such an
//    outage neither the per-period track nor the assumption that the table and
//    the IMU kept running undisturbed can be checked, so the bench asks for the
//    point to be recorded again instead of fitting across it, or
//  - more than kMaxMissingFraction of the record span is missing.

#include <cstddef>
#include <string>

#include "core/common/recording.h"

namespace fog::analysis {

inline constexpr double kMaxMissingFraction = 0.2;

struct DataCoverage {
  double spanS = 0.0;            // first to last sample common to both channels
  std::size_t lostTableFrames = 0;
  std::size_t lostImuFrames = 0;
  double missingS = 0.0;         // time without data, the worse of the two channels
  double largestGapS = 0.0;      // longest single stretch without data, either channel
  double coveredS() const { return spanS - missingS; }
  double coveredFraction() const { return spanS > 0.0 ? coveredS() / spanS : 0.0; }
};

DataCoverage measureCoverage(const TestPointData& data);

// Empty when the coverage supports a delay at swing frequency `frequencyHz`;
// otherwise why not, for a person ("a gap of 3.10 s without data is longer
// than one swing period ..."; the caller names the test point).
std::string coverageRefusal(const DataCoverage& coverage, double frequencyHz);

}  // namespace fog::analysis
