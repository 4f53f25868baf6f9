#pragma once
// Passes over a test point's samples, counted so that a test can fail when a
// stage starts walking the samples again (tests/core/analysis/
// sample_passes_test.cpp): the analysis' time is the number of passes times
// the samples, and a pass added quietly (residuals computed twice, a check
// re-fitting) is how it grew from 46 to 95 ms before.
//
// Every loop in core/analysis that visits each table sample or each gyro
// increment (or an array of one value per sample, such as residuals) counts
// one pass when it starts: one relaxed atomic add per pass, never per
// sample, so it is always compiled in. A loop split over two threads is one
// pass. The counts are process-wide: analyses running at the same time add
// to the same counts, so read them only where one analysis runs.

#include <cstdint>

namespace fog::analysis {

enum class SampleStream { kTable, kGyro };

struct SamplePassCounts {
  std::uint64_t table = 0, gyro = 0;
};

void countPass(SampleStream stream, unsigned passes = 1);
// The counts since the program started.
SamplePassCounts samplePassCounts();

}  // namespace fog::analysis
