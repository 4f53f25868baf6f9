#include "core/diagnosis/features.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/analysis/sin_cos_series.h"
#include "core/common/units.h"
#include "core/diagnosis/replay_passes.h"

namespace fog::diagnosis {

namespace {

constexpr int kHarmonics = 5;
constexpr int kTableCols = 2 * kHarmonics + 2;  // harmonics, offset, trend
constexpr int kGyroCols = 2 * kHarmonics + 1;   // harmonics, trend (the offset cancels in increments)

using TableMatrix = Eigen::Matrix<double, kTableCols, kTableCols>;
using TableVector = Eigen::Matrix<double, kTableCols, 1>;
using GyroMatrix = Eigen::Matrix<double, kGyroCols, kGyroCols>;
using GyroRhs = Eigen::Matrix<double, kGyroCols, kAxisCount>;
using GyroVector = Eigen::Matrix<double, kGyroCols, 1>;

// sin(h x), cos(h x) for h = 1..5 by the angle-addition recurrence from
// s1 = sin x, c1 = cos x.
void harmonics(double s1, double c1, double* out) {
  double s = s1, c = c1;
  for (int h = 0; h < kHarmonics; ++h) {
    out[2 * h] = s;
    out[2 * h + 1] = c;
    const double sn = s * c1 + c * s1;
    c = c * c1 - s * s1;
    s = sn;
  }
}

void harmonics(double x, double* out) { harmonics(std::sin(x), std::cos(x), out); }

void gyroBasis(double w, double tau, double* out) {
  harmonics(w * tau, out);
  out[kGyroCols - 1] = tau;
}

// Calls f(k, dx) for every increment k with its row of the exact difference
// model, dx = Phi(t_k) - Phi(t_k-1) (times relative to mid; after a lost
// frame, and for the first, the start is one frame before t_k).
template <typename F>
void forEachIncrementRow(const std::vector<ImuSample>& imu, double w, double frame, double mid, const F& f) {
  countRecordingPass(analysis::SampleStream::kGyro);
  // The stamps' sin and cos by rotation (analysis::SinCosStream: within a
  // 0.1-ns timing error of a sincos per stamp, which took 12 % of a diagnosis).
  analysis::SinCosStream phase(w, mid);
  double phiEnd[kGyroCols], phiStart[kGyroCols], dx[kGyroCols];
  for (std::size_t k = 0; k < imu.size(); ++k) {
    const ImuSample& m = imu[k];
    if (k > 0 && m.lostBefore == 0)
      std::copy(phiEnd, phiEnd + kGyroCols, phiStart);
    else
      gyroBasis(w, m.timeS - frame - mid, phiStart);
    double s1, c1;
    phase.next(m.timeS, s1, c1);
    harmonics(s1, c1, phiEnd);
    phiEnd[kGyroCols - 1] = m.timeS - mid;
    for (int c = 0; c < kGyroCols; ++c) dx[c] = phiEnd[c] - phiStart[c];
    f(k, static_cast<const double*>(dx));
  }
}

struct Interval {
  double sum = 0.0, sumSq = 0.0;
  std::size_t n = 0;
  void add(double v) {
    sum += v;
    sumSq += v * v;
    ++n;
  }
  double mean() const { return n ? sum / static_cast<double>(n) : 0.0; }
  double variance() const {
    if (n < 2) return 0.0;
    const double m = mean();
    return std::max(0.0, (sumSq - static_cast<double>(n) * m * m) / static_cast<double>(n - 1));
  }
};

struct SegmentSums {
  TableMatrix tXtX = TableMatrix::Zero();
  TableVector tXty = TableVector::Zero();
  double tyty = 0.0;
  std::size_t tn = 0;
  GyroMatrix gXtX = GyroMatrix::Zero();
  GyroRhs gXty = GyroRhs::Zero();
  std::array<double, kAxisCount> gyty{};
  std::size_t gn = 0;
  Interval tableIntervalUs, imuIntervalUs;
  double lost = 0.0;
  double tableLost = 0.0;  // table samples missing: the interval cells skip their gaps

  void operator+=(const SegmentSums& o) {
    tXtX += o.tXtX, tXty += o.tXty, tyty += o.tyty, tn += o.tn;
    gXtX += o.gXtX, gXty += o.gXty, gn += o.gn;
    for (int a = 0; a < kAxisCount; ++a) gyty[a] += o.gyty[a];
  }
};

// Rows of one segment gathered 64 at a time, added to its normal equations
// as one blocked product instead of a rank-one update per row (those were a
// tenth of a replay's time in the diagnosis).
template <int Cols, int Rhs>
class RowBlock {
 public:
  // Without X'X: the rows' normal matrix is known already (FeatureSums).
  explicit RowBlock(bool withXtX = true) : withXtX_(withXtX) {}
  // Adds a row to the block; a row of another segment, or a full block,
  // sends the block to its own segment's sums first.
  template <typename Sums>
  void add(int segment, const double* x, const double* y, Sums& sums) {
    if (n_ == kRows || (n_ > 0 && segment != segment_)) flush(sums);
    segment_ = segment;
    for (int c = 0; c < Cols; ++c) x_(n_, c) = x[c];
    for (int c = 0; c < Rhs; ++c) y_(n_, c) = y[c];
    ++n_;
  }
  template <typename Sums>
  void flush(Sums& sums) {
    if (n_ == 0) return;
    auto [xtx, xty] = sums(segment_);  // references into the segment
    if (withXtX_) xtx.template selfadjointView<Eigen::Upper>().rankUpdate(x_.topRows(n_).transpose());
    xty.noalias() += x_.topRows(n_).transpose() * y_.topRows(n_);
    n_ = 0;
  }

 private:
  static constexpr int kRows = 64;
  Eigen::Matrix<double, kRows, Cols> x_;
  Eigen::Matrix<double, kRows, Rhs> y_;
  int n_ = 0, segment_ = 0;
  bool withXtX_ = true;
};

struct SegmentFit {
  TableVector table;
  GyroRhs gyro;  // one column per axis
  double tableMs = 0.0, gyroMs = 0.0;  // residual mean square, deg^2 (swing axis for the gyro)
  TableVector tableVar;                // formal variances of the coefficients
  GyroRhs gyroVar;
  std::size_t tableN = 0;
};

Result<SegmentFit> solve(const SegmentSums& s, int swingAxis) {
  if (s.tn < 4 * kTableCols || s.gn < 4 * kGyroCols)
    return insufficientData("a segment has too few samples for the harmonic fit");
  SegmentFit f;
  Eigen::LDLT<TableMatrix> tl(s.tXtX);
  Eigen::LDLT<GyroMatrix> gl(s.gXtX);
  if (tl.info() != Eigen::Success || gl.info() != Eigen::Success)
    return insufficientData("a segment's harmonic fit is singular (under one swing period?)");
  f.table = tl.solve(s.tXty);
  f.gyro = gl.solve(s.gXty);
  // rss = y'y - b'X'y for the least-squares b; the cancellation leaves ample
  // digits for angles of degrees and residuals of micro-degrees.
  const double trss = s.tyty - f.table.dot(s.tXty);
  const double grss = s.gyty[swingAxis] - f.gyro.col(swingAxis).dot(s.gXty.col(swingAxis));
  f.tableMs = std::max(0.0, trss) / static_cast<double>(s.tn - kTableCols);
  f.gyroMs = std::max(0.0, grss) / static_cast<double>(s.gn - kGyroCols);
  f.tableN = s.tn;
  f.tableVar = tl.solve(TableMatrix::Identity()).diagonal() * f.tableMs;
  const GyroVector ginv = gl.solve(GyroMatrix::Identity()).diagonal();
  for (int a = 0; a < kAxisCount; ++a) {
    const double rss = s.gyty[static_cast<std::size_t>(a)] - f.gyro.col(a).dot(s.gXty.col(a));
    f.gyroVar.col(a) = ginv * (std::max(0.0, rss) / static_cast<double>(s.gn - kGyroCols));
  }
  return f;
}

double wrapPi(double x) {
  x = std::remainder(x, kTwoPi);
  return x;
}

// Harmonic h of (ah, bh) relative to the fundamental (a1, b1): in phase and in
// quadrature with the fundamental's phase carried to harmonic h, ppm.
void relative(double ah, double bh, double a1, double b1, int h, double& inPhase, double& quadrature) {
  const double amp = std::hypot(a1, b1);
  const double phi1 = std::atan2(b1, a1);
  const double bAmp = std::hypot(ah, bh), phih = std::atan2(bh, ah);
  const double d = phih - h * phi1;
  inPhase = amp > 0.0 ? bAmp / amp * std::cos(d) * 1e6 : 0.0;
  quadrature = amp > 0.0 ? bAmp / amp * std::sin(d) * 1e6 : 0.0;
}

struct Emitter {
  FeatureSet& out;
  int point = 0, segment = 0;
  void add(Channel c, Quantity quantity, Unit unit, int harmonic, int axis, double value, double formal = 0.0) {
    out.keys.push_back({c, quantity, unit, harmonic, axis, point, segment});
    out.values.push_back(value);
    out.formalStd.push_back(formal);
  }
};

void emitSegment(Emitter& e, const SegmentFit& f, const SegmentSums& s, const PointReference& ref,
                 const FeatureReference& fr) {
  const int ax = ref.swingAxis;
  const double ta = f.table(0), tb = f.table(1);
  const double ga = f.gyro(0, ax), gb = f.gyro(1, ax);
  const double tAmp0 = std::hypot(ta, tb);
  // Relative standard error (ppm) of harmonic h of the table.
  auto tRel = [&](int h) { return std::sqrt(0.5 * (f.tableVar(2 * (h - 1)) + f.tableVar(2 * (h - 1) + 1))) / tAmp0 * 1e6; };
  // Table channel: harmonics 2..5 of the motion as the encoder reports it.
  for (int h = 2; h <= kHarmonics; ++h) {
    double i = 0, q = 0;
    relative(f.table(2 * (h - 1)), f.table(2 * (h - 1) + 1), ta, tb, h, i, q);
    e.add(Channel::kTable, Quantity::kInPhase, Unit::kPpm, h, -1, i, tRel(h));
    e.add(Channel::kTable, Quantity::kQuadrature, Unit::kPpm, h, -1, q, tRel(h));
  }
  // Mean square of uniform quantisation noise: variance 0.8 sigma^4 / N.
  e.add(Channel::kTable, Quantity::kResidualMeanSquare, Unit::kMicroDegSquared, -1, -1, f.tableMs * 1e12,
        f.tableMs * 1e12 * std::sqrt(0.8 / static_cast<double>(f.tableN)));
  // Gyro minus table: the fundamental's gain and delay, and how the gyro's
  // harmonics differ from the table's.
  const double tAmp = std::hypot(ta, tb), gAmp = std::hypot(ga, gb);
  // Formal errors: the table's only. The gyro's white-noise formal error
  // overstates its spread several times over (its increments carry the
  // pulse quantisation as a difference, which telescopes), and the gyro has
  // a true seed-to-seed spread that the replays measure.
  const double rel1 = tRel(1);  // ppm of the fundamental
  e.add(Channel::kGyroMinusTable, Quantity::kGain, Unit::kPpm, 1, ax, (gAmp / tAmp - 1.0) * 1e6, rel1);
  e.add(Channel::kGyroMinusTable, Quantity::kDelay, Unit::kMicroseconds, 1, ax,
        wrapPi(std::atan2(tb, ta) - std::atan2(gb, ga)) / ref.omegaRadPerS * 1e6, rel1 / ref.omegaRadPerS);
  for (int h = 2; h <= kHarmonics; ++h) {
    double ti = 0, tq = 0, gi = 0, gq = 0;
    relative(f.table(2 * (h - 1)), f.table(2 * (h - 1) + 1), ta, tb, h, ti, tq);
    relative(f.gyro(2 * (h - 1), ax), f.gyro(2 * (h - 1) + 1, ax), ga, gb, h, gi, gq);
    const double fs = tRel(h);
    e.add(Channel::kGyroMinusTable, Quantity::kInPhase, Unit::kPpm, h, ax, gi - ti, fs);
    e.add(Channel::kGyroMinusTable, Quantity::kQuadrature, Unit::kPpm, h, ax, gq - tq, fs);
  }
  // Gyro channel: trend (harmonic 0) and residual of the swing axis; what the
  // other two gyros see of the swing, and their trends.
  e.add(Channel::kGyro, Quantity::kResidualMeanSquare, Unit::kMicroDegSquared, -1, ax, f.gyroMs * 1e12,
        f.gyroMs * 1e12 * std::sqrt(2.0 / static_cast<double>(s.gn)));
  for (int a = 0; a < kAxisCount; ++a) {
    e.add(Channel::kGyro, Quantity::kTrend, Unit::kDegPerHour, 0, a, f.gyro(kGyroCols - 1, a) * kSecondsPerHour);
    if (a == ax) continue;
    double i = 0, q = 0;
    relative(f.gyro(0, a), f.gyro(1, a), ta, tb, 1, i, q);
    e.add(Channel::kGyro, Quantity::kCrossInPhase, Unit::kPpm, 1, a, i);
    e.add(Channel::kGyro, Quantity::kCrossQuadrature, Unit::kPpm, 1, a, q);
  }
  // Timing of both streams inside the segment. The mean interval's formal
  // error is what white stamp jitter leaves of it: the intervals telescope,
  // so the mean moves by the first and last stamps' jitter only,
  // sqrt(variance) / n (a 2-us-rms jitter: 0.38 ppm over a 7.5-s segment at
  // 500 Hz; a clean stream's counter tick: 1e-5 ppm, far below the floor).
  auto meanPpmError = [](const Interval& i, double periodS) {
    return i.n ? std::sqrt(i.variance()) / static_cast<double>(i.n) / (periodS * 1e6) * 1e6 : 0.0;
  };
  e.add(Channel::kTiming, Quantity::kTableInterval, Unit::kPpm, -1, -1,
        (s.tableIntervalUs.mean() * 1e-6 / fr.tablePeriodS - 1.0) * 1e6, meanPpmError(s.tableIntervalUs, fr.tablePeriodS));
  e.add(Channel::kTiming, Quantity::kTableIntervalVariance, Unit::kMicrosecondsSquared, -1, -1, s.tableIntervalUs.variance());
  e.add(Channel::kTiming, Quantity::kImuInterval, Unit::kPpm, -1, -1, (s.imuIntervalUs.mean() * 1e-6 / fr.imuPeriodS - 1.0) * 1e6,
        meanPpmError(s.imuIntervalUs, fr.imuPeriodS));
  e.add(Channel::kTiming, Quantity::kImuIntervalVariance, Unit::kMicrosecondsSquared, -1, -1, s.imuIntervalUs.variance());
  e.add(Channel::kTiming, Quantity::kImuLost, Unit::kFrames, -1, -1, s.lost);
  e.add(Channel::kTiming, Quantity::kTableLost, Unit::kFrames, -1, -1, s.tableLost);
}

double medianInterval(const std::vector<ImuSample>& imu) {
  countRecordingPass(analysis::SampleStream::kGyro);
  std::vector<double> d;
  d.reserve(imu.size());
  for (std::size_t k = 1; k < imu.size(); ++k) d.push_back(imu[k].timeS - imu[k - 1].timeS);
  if (d.empty()) return 0.0;
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

bool sameTable(const std::vector<TableSample>& a, const std::vector<TableSample>& b, int axis) {
  if (a.size() != b.size()) return false;
  const auto ax = static_cast<std::size_t>(axis);
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].timeS != b[i].timeS || a[i].angleDeg[ax] != b[i].angleDeg[ax]) return false;
  return true;
}

struct ImuStamp {
  double timeS;
  std::uint32_t lostBefore;
};

bool sameStamps(const std::vector<ImuSample>& a, const std::vector<ImuStamp>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].timeS != b[i].timeS || a[i].lostBefore != b[i].lostBefore) return false;
  return true;
}

}  // namespace

// Per test point: the samples the sums came from, the segments' sums (the
// table's whole, the gyro's normal matrix only; before the lower triangles
// are filled) and the IMU frame interval.
struct FeatureSums::Point {
  std::vector<TableSample> table;
  std::vector<ImuStamp> imu;
  std::vector<SegmentSums> seg;
  double frame = 0.0;
};
FeatureSums::FeatureSums() = default;
FeatureSums::~FeatureSums() = default;

std::string quantityName(const FeatureKey& key) {
  switch (key.quantity) {
    // (std::string(1, 'h') +, not "h" +: GCC 12 warns -Wrestrict on the latter.)
    case Quantity::kInPhase: return std::string(1, 'h') + std::to_string(key.harmonic) + "_in_phase";
    case Quantity::kQuadrature: return std::string(1, 'h') + std::to_string(key.harmonic) + "_quadrature";
    case Quantity::kResidualMeanSquare: return "residual_ms";
    case Quantity::kGain: return "gain";
    case Quantity::kDelay: return "delay";
    case Quantity::kTrend: return "trend";
    case Quantity::kCrossInPhase: return "cross_in_phase";
    case Quantity::kCrossQuadrature: return "cross_quadrature";
    case Quantity::kTableInterval: return "table_interval";
    case Quantity::kTableIntervalVariance: return "table_interval_var";
    case Quantity::kImuInterval: return "imu_interval";
    case Quantity::kImuIntervalVariance: return "imu_interval_var";
    case Quantity::kImuLost: return "imu_lost";
    case Quantity::kTableLost: return "table_lost";
  }
  return "?";
}

std::string quantityTitle(const FeatureKey& key) {
  switch (key.quantity) {
    case Quantity::kInPhase: return "harmonic " + std::to_string(key.harmonic) + ", in phase";
    case Quantity::kQuadrature: return "harmonic " + std::to_string(key.harmonic) + ", quadrature";
    case Quantity::kResidualMeanSquare: return "residual mean square";
    case Quantity::kGain: return "gain";
    case Quantity::kDelay: return "delay";
    case Quantity::kTrend: return "trend";
    case Quantity::kCrossInPhase: return "cross-axis, in phase";
    case Quantity::kCrossQuadrature: return "cross-axis, quadrature";
    case Quantity::kTableInterval: return "table stamp interval";
    case Quantity::kTableIntervalVariance: return "table stamp-interval variance";
    case Quantity::kImuInterval: return "IMU stamp interval";
    case Quantity::kImuIntervalVariance: return "IMU stamp-interval variance";
    case Quantity::kImuLost: return "IMU frames lost";
    case Quantity::kTableLost: return "table samples lost";
  }
  return "?";
}

const char* unitName(Unit unit) {
  switch (unit) {
    case Unit::kPpm: return "ppm";
    case Unit::kMicroseconds: return "us";
    case Unit::kDegPerHour: return "deg/h";
    case Unit::kMicroDegSquared: return "udeg^2";
    case Unit::kMicrosecondsSquared: return "us^2";
    case Unit::kFrames: return "frames";
  }
  return "?";
}

const char* channelName(Channel c) {
  switch (c) {
    case Channel::kTable: return "table";
    case Channel::kGyro: return "gyro";
    case Channel::kGyroMinusTable: return "gyro-table";
    case Channel::kTiming: return "timing";
  }
  return "?";
}

int segmentsFor(double durationS, double frequencyHz) {
  const double periods = durationS * frequencyHz;
  return std::clamp(static_cast<int>(std::floor(periods / 2.0)), 1, 4);
}

Result<FeatureSet> extractFeatures(const Recording& recording, const FeatureReference& reference,
                                   ResidualView residual, FeatureSums* record, const FeatureSums* reuse) {
  if (record) record->points.assign(recording.testPoints.size(), {});
  if (recording.testPoints.size() != reference.points.size())
    return invalidArgument("the recording has " + std::to_string(recording.testPoints.size()) +
                           " test points, the feature reference " + std::to_string(reference.points.size()));
  FeatureSet out;
  for (std::size_t p = 0; p < recording.testPoints.size(); ++p) {
    const TestPointData& tp = recording.testPoints[p];
    const PointReference& ref = reference.points[p];
    if (tp.table.size() < 100 || tp.imu.size() < 50)
      return insufficientData("test point " + std::to_string(p + 1) + " has too few samples for the gap map");
    const double w = ref.omegaRadPerS;
    const double start = tp.table.front().timeS, end = tp.table.back().timeS;
    const double mid = 0.5 * (start + end), span = end - start;
    const int nSeg = std::max(1, ref.segments);
    auto segmentOf = [&](double t) {
      return std::clamp(static_cast<int>(std::floor((t - start) / span * nSeg)), 0, nSeg - 1);
    };
    std::vector<SegmentSums> seg(static_cast<std::size_t>(nSeg));

    auto tableSums = [&](int i) {
      SegmentSums& s = seg[static_cast<std::size_t>(i)];
      return std::tie(s.tXtX, s.tXty);
    };
    auto gyroSums = [&](int i) {
      SegmentSums& s = seg[static_cast<std::size_t>(i)];
      return std::tie(s.gXtX, s.gXty);
    };
    const FeatureSums::Point* known =
        reuse && p < reuse->points.size() && reuse->points[p].seg.size() == seg.size() ? &reuse->points[p] : nullptr;
    // One pass over the table samples and one over the IMU stamps either
    // way: a comparison that holds stands for the sums (the median) it
    // spares; one that fails stops at the first difference (within the first
    // second for every effect of the library that moves a stamp or a
    // reading) and is not counted.
    const bool tableKnown = known && sameTable(tp.table, known->table, ref.swingAxis);
    const bool imuKnown = known && sameStamps(tp.imu, known->imu);
    countRecordingPass(analysis::SampleStream::kTable);
    if (imuKnown) countRecordingPass(analysis::SampleStream::kGyro);
    if (tableKnown)
      for (std::size_t i = 0; i < seg.size(); ++i) {
        const SegmentSums& k = known->seg[i];
        seg[i].tXtX = k.tXtX, seg[i].tXty = k.tXty, seg[i].tyty = k.tyty, seg[i].tn = k.tn;
        seg[i].tableIntervalUs = k.tableIntervalUs, seg[i].tableLost = k.tableLost;
      }
    RowBlock<kTableCols, 1> tableRows;
    RowBlock<kGyroCols, kAxisCount> gyroRows(!imuKnown);

    double row[kTableCols];
    analysis::SinCosStream tablePhase(w, mid);
    for (std::size_t i = 0; i < tp.table.size() && !tableKnown; ++i) {
      const double tau = tp.table[i].timeS - mid;
      double s1, c1;
      tablePhase.next(tp.table[i].timeS, s1, c1);
      harmonics(s1, c1, row);
      row[kTableCols - 2] = 1.0;
      row[kTableCols - 1] = tau;
      const int segment = segmentOf(tp.table[i].timeS);
      SegmentSums& s = seg[static_cast<std::size_t>(segment)];
      const double y = tp.table[i].angleDeg[static_cast<std::size_t>(ref.swingAxis)];
      tableRows.add(segment, row, &y, tableSums);
      s.tyty += y * y;
      ++s.tn;
      if (i > 0) {
        const double dUs = (tp.table[i].timeS - tp.table[i - 1].timeS) * 1e6;
        const double periodUs = reference.tablePeriodS * 1e6;
        if (dUs > 0.0 && dUs < 1.5 * periodUs) s.tableIntervalUs.add(dUs);
        else if (dUs >= 1.5 * periodUs) s.tableLost += std::round(dUs / periodUs) - 1.0;
      }
    }

    // The stamps' pass above stands for the median's when they are known.
    const double frame = imuKnown ? known->frame : medianInterval(tp.imu);
    forEachIncrementRow(tp.imu, w, frame, mid, [&](std::size_t k, const double* dx) {
      const ImuSample& m = tp.imu[k];
      const int segment = segmentOf(m.timeS);
      SegmentSums& s = seg[static_cast<std::size_t>(segment)];
      gyroRows.add(segment, dx, m.incrementDeg.data(), gyroSums);
      for (int a = 0; a < kAxisCount; ++a)
        s.gyty[static_cast<std::size_t>(a)] += m.incrementDeg[static_cast<std::size_t>(a)] * m.incrementDeg[static_cast<std::size_t>(a)];
      ++s.gn;
      s.lost += m.lostBefore;
      if (k > 0) {
        const double dUs = (m.timeS - tp.imu[k - 1].timeS) * 1e6;
        if (dUs > 0.0 && dUs < 1.5 * reference.imuPeriodS * 1e6) s.imuIntervalUs.add(dUs);
      }
    });

    tableRows.flush(tableSums);
    gyroRows.flush(gyroSums);
    if (imuKnown)
      for (std::size_t i = 0; i < seg.size(); ++i) seg[i].gXtX = known->seg[i].gXtX;
    if (record) {  // a copy of the samples' stamps: one pass over each stream
      countRecordingPass(analysis::SampleStream::kTable);
      countRecordingPass(analysis::SampleStream::kGyro);
      FeatureSums::Point& r = record->points[p];
      r.table = tp.table;
      r.imu.reserve(tp.imu.size());
      for (const auto& m : tp.imu) r.imu.push_back({m.timeS, m.lostBefore});
      r.seg = seg;
      r.frame = frame;
    }
    SegmentSums whole;
    for (auto& s : seg) {
      s.tXtX = s.tXtX.selfadjointView<Eigen::Upper>();
      s.gXtX = s.gXtX.selfadjointView<Eigen::Upper>();
      whole += s;
    }
    for (int s = 0; s < nSeg; ++s) {
      auto fit = solve(seg[static_cast<std::size_t>(s)], ref.swingAxis);
      if (!fit) return Status(fit.status().code(), "test point " + std::to_string(p + 1) + ": " + fit.status().message());
      Emitter e{out, static_cast<int>(p), s};
      emitSegment(e, *fit, seg[static_cast<std::size_t>(s)], ref, reference);
    }

    // Whole-record view for plots: spectra and the cumulative gyro residual.
    auto wf = solve(whole, ref.swingAxis);
    if (!wf) return wf.status();
    PointSpectrum sp;
    const int ax = ref.swingAxis;
    const double tAmp = std::hypot(wf->table(0), wf->table(1)), gAmp = std::hypot(wf->gyro(0, ax), wf->gyro(1, ax));
    sp.tableHarmonicPpm.push_back(0.0);
    sp.gyroHarmonicPpm.push_back(wf->gyro(kGyroCols - 1, ax) * kSecondsPerHour);
    for (int h = 1; h <= kHarmonics; ++h) {
      sp.tableHarmonicPpm.push_back(std::hypot(wf->table(2 * (h - 1)), wf->table(2 * (h - 1) + 1)) / tAmp * 1e6);
      sp.gyroHarmonicPpm.push_back(std::hypot(wf->gyro(2 * (h - 1), ax), wf->gyro(2 * (h - 1) + 1, ax)) / gAmp * 1e6);
    }
    sp.gainPpm = (gAmp / tAmp - 1.0) * 1e6;
    sp.delayUs = wrapPi(std::atan2(wf->table(1), wf->table(0)) - std::atan2(wf->gyro(1, ax), wf->gyro(0, ax))) / w * 1e6;
    if (residual == ResidualView::kSkip) {
      out.spectra.push_back(std::move(sp));
      continue;
    }
    const std::size_t stride = std::max<std::size_t>(1, tp.imu.size() / 400);
    double cumulative = 0.0;
    const GyroVector beta = wf->gyro.col(ax);
    forEachIncrementRow(tp.imu, w, frame, mid, [&](std::size_t k, const double* dx) {
      const ImuSample& m = tp.imu[k];
      double model = 0.0;
      for (int c = 0; c < kGyroCols; ++c) model += dx[c] * beta(c);
      cumulative += m.incrementDeg[static_cast<std::size_t>(ax)] - model;
      if (k % stride == 0) {
        sp.residualTimeS.push_back(m.timeS - mid);
        sp.gyroResidualDeg.push_back(cumulative);
      }
    });
    out.spectra.push_back(std::move(sp));
  }
  return out;
}

TimingAudit auditTiming(const Recording& recording, double tablePeriodS, double imuPeriodS) {
  TimingAudit a;
  Interval t, m;
  auto scan = [](const auto& samples, double nominal, Interval& iv, StreamTiming& st) {
    st.samples += samples.size();
    for (std::size_t i = 1; i < samples.size(); ++i) {
      const double d = samples[i].timeS - samples[i - 1].timeS;
      if (d <= 0.0)
        ++st.duplicates;
      else if (d > 1.5 * nominal)
        ++st.gaps;
      else
        iv.add(d * 1e6);
    }
  };
  for (const auto& tp : recording.testPoints) {
    countRecordingPass(analysis::SampleStream::kTable);
    countRecordingPass(analysis::SampleStream::kGyro);
    scan(tp.table, tablePeriodS, t, a.table);
    scan(tp.imu, imuPeriodS, m, a.imu);
  }
  a.table.intervalMeanPpm = t.n ? (t.mean() * 1e-6 / tablePeriodS - 1.0) * 1e6 : 0.0;
  a.table.intervalStdUs = std::sqrt(t.variance());
  a.imu.intervalMeanPpm = m.n ? (m.mean() * 1e-6 / imuPeriodS - 1.0) * 1e6 : 0.0;
  a.imu.intervalStdUs = std::sqrt(m.variance());
  a.lostFrames = recording.health.lostFrames;
  a.duplicateFrames = recording.health.duplicateFrames;
  a.counterWraps = recording.health.counterWraps;
  a.checksumFailures = recording.health.checksumFailures;
  a.outOfOrderFrames = recording.health.outOfOrderFrames;
  return a;
}

}  // namespace fog::diagnosis
