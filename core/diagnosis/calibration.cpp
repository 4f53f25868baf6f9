// The diagnosis' calibration (diagnosis_stages.h): the session as analysed,
// the replay calibrated to it, the Earth rate and the gyro biases, and the
// memory budget of the replays.
#include "core/diagnosis/diagnosis_stages.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>

#include "core/common/parallel.h"
#include "core/common/units.h"
#include "core/model/simulator.h"

namespace fog::diagnosis::detail {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// The sample period of a stream as recorded: the span of each test point's
// stamps over the number of periods in it (the median interval rounds the
// count, so lost frames do not bias it); the median over the test points.
// 0 when no test point has two samples.
template <typename Samples>
double recordedPeriodS(const std::vector<TestPointData>& points, Samples TestPointData::*member) {
  std::vector<double> periods;
  for (const auto& tp : points) {
    const auto& v = tp.*member;
    if (v.size() < 2) continue;
    std::vector<double> dt;
    dt.reserve(v.size() - 1);
    for (std::size_t k = 1; k < v.size(); ++k) dt.push_back(v[k].timeS - v[k - 1].timeS);
    const double typical = median(std::move(dt));
    const double span = v.back().timeS - v.front().timeS;
    if (typical > 0.0 && span > 0.0) periods.push_back(span / std::max(1.0, std::round(span / typical)));
  }
  return median(std::move(periods));
}

// Sets the replay's chain so that its lag equals lagS, preferring the gyro's
// own delay, then the board's processing time, then the table read delay.
void setLag(model::SimConfig& c, double lagS, std::vector<std::string>& notes) {
  const double loop = c.fog.loopDelayS(), update = c.fog.pulseUpdatePeriodS;
  double own = lagS + c.encoder.readDelayS - c.imuBoard.boardDelayS();
  double extra = 0.0;
  if (own >= loop + 0.95 * update) {
    extra = own - (loop + 0.5 * update);
    own = loop + 0.5 * update;
  } else if (own < loop) {
    extra = own - loop;
    own = loop;
  }
  c.fog.setOwnDelayS(own);
  c.imuBoard.processingS += extra;
  // The board must finish a frame within the frame period: a longer lag (a
  // slow first-order lag) is left to the fitted session delay (nuisance).
  c.imuBoard.processingS = std::min(c.imuBoard.processingS, 0.9 * c.imuBoard.framePeriodS - c.imuBoard.serialS());
  if (c.imuBoard.processingS < 0.0) {
    c.encoder.readDelayS = std::min(0.9 * c.encoder.samplePeriodS, c.encoder.readDelayS - c.imuBoard.processingS);
    c.imuBoard.processingS = 0.0;
  }
  if (std::abs(c.trueLagS() - lagS) > 1e-9) notes.push_back("the replay cannot reach the measured lag exactly");
}

// The encoder's quantum as the readings show it. Every step between
// consecutive readings is a whole number n of quanta, give or take the
// transport's rounding to a micro-degree: the steps under 1.5x the
// smallest (one quantum) give a first value q1, and the steps within a
// quarter quantum of n q1 give sum(steps) / sum(n), where the rounding is
// spread over every quantum moved (a swing of 3 deg at 1 Hz moves ~160 a
// sample). 0 when fewer than 100 steps of one quantum are found.
double readingQuantumDeg(const Recording& used) {
  auto forEachStep = [&](auto&& f) {
    for (const auto& tp : used.testPoints)
      for (std::size_t k = 1; k < tp.table.size(); ++k)
        for (int a = 0; a < kAxisCount; ++a)
          if (const double d = std::abs(tp.table[k].angleDeg[a] - tp.table[k - 1].angleDeg[a]); d > 0.0) f(d);
  };
  double smallest = 0.0;
  forEachStep([&](double d) { smallest = smallest == 0.0 ? d : std::min(smallest, d); });
  double sum = 0.0;
  std::size_t count = 0;
  forEachStep([&](double d) {
    if (d < 1.5 * smallest) sum += d, ++count;
  });
  if (count < 100) return 0.0;
  const double q1 = sum / static_cast<double>(count);
  double steps = 0.0, quanta = 0.0;
  forEachStep([&](double d) {
    const double n = std::round(d / q1);
    if (n <= 1000.0 && std::abs(d / q1 - n) < 0.25) steps += d, quanta += n;
  });
  return steps / quanta;
}

// ---- The stages of calibrateEarthRateAndBias() (its method is described
// there, below) --------------------------------------------------------------

// The features of the kCalibrationReplays replays, all with zero bias:
// headings 0, 90 and 180 deg (common random numbers), heading 0 with a
// second seed (the cells' spread) and heading 0 at the opposite latitude
// (the vertical's column).
struct EarthRateReplays {
  std::vector<double> f0, f0b, f90, f180, otherLatitude;
};

Result<EarthRateReplays> runEarthRateReplays(const Replay& replay, std::size_t cells, const DiagnosisOptions& options) {
  Replay base = replay;
  base.cal.config.fog.biasDegPerH = {0.0, 0.0, 0.0};
  const std::uint64_t seedA = options.seed + 1000, seedB = options.seed + 1001;
  const double latitude = base.cal.config.earth.latitudeDeg;
  struct Run {
    double headingDeg, latitudeDeg;
    std::uint64_t seed;
  };
  const std::vector<Run> runs = {
      {0.0, latitude, seedA}, {0.0, latitude, seedB}, {90.0, latitude, seedA}, {180.0, latitude, seedA},
      {0.0, -latitude, seedA}};
  static_assert(kCalibrationReplays == 5);
  std::vector<Result<FeatureSet>> out(runs.size(), Status(StatusCode::kInternal, "not run"));
  parallelFor(runs.size(), options.threads, [&](std::size_t i) {
    Replay r = base;
    r.cal.config.earth.headingDeg = runs[i].headingDeg;
    r.cal.config.earth.latitudeDeg = runs[i].latitudeDeg;
    out[i] = r.run(runs[i].seed, {});
  });
  if (replay.progress && replay.progress->cancelled()) return cancelledByCaller();
  for (auto& o : out) {
    if (!o) return Status(o.status().code(), "replay (Earth-rate calibration): " + o.status().message());
    if (o->values.size() != cells)
      return Status(StatusCode::kInternal, "the replay's features do not line up with the session's");
  }
  return EarthRateReplays{std::move(out[0]->values), std::move(out[1]->values), std::move(out[2]->values),
                          std::move(out[3]->values), std::move(out[4]->values)};
}

// The weighted least-squares problem on the gyro cells the Earth rate
// reaches, one row a cell, each over the cell's spread: columns 0 and 1 are
// the horizontal Earth rate's parts times cos h and times -sin h, columns 2
// to 4 each gyro's bias (deg/h; trend cells only); y is the session's
// features less the replays' mean, vertical the configured vertical's part.
struct EarthRateDesign {
  std::vector<std::size_t> rows;  // the cells (indices into the features)
  Eigen::MatrixXd a;
  Eigen::VectorXd y, vertical;
  Eigen::VectorXd isTrend, inScan, inFrameCheck;  // 1 or 0 a row
  std::vector<Eigen::Index> biasCols;              // the bias columns some row sees

  // What of `target` is left once the horizontal Earth rate at hDeg is taken out.
  Eigen::VectorXd rest(const Eigen::VectorXd& target, double hDeg) const {
    const double h = hDeg * kRadPerDeg;
    return target - std::cos(h) * a.col(0) + std::sin(h) * a.col(1);
  }
};

// Nothing (with a note) when the plan gives too few cells to check the frame.
std::optional<EarthRateDesign> earthRateDesign(const std::vector<FeatureKey>& keys, const std::vector<double>& real,
                                               const EarthRateReplays& f, std::vector<std::string>& notes) {
  std::map<GroupKey, std::pair<double, double>> spread;  // sum of squares, count
  for (std::size_t i = 0; i < keys.size(); ++i) {
    auto& g = spread[groupKey(keys[i])];
    g.first += 0.5 * (f.f0[i] - f.f0b[i]) * (f.f0[i] - f.f0b[i]);
    g.second += 1.0;
  }
  EarthRateDesign d;
  for (std::size_t i = 0; i < keys.size(); ++i)
    // The Earth rate a swing modulates is a rate in phase with the angle, an
    // angle in quadrature with it (and a trend); the in-phase cross cells are
    // where misalignment shows, so they are left to the effect fit.
    if (keys[i].channel == Channel::kGyro && (keys[i].quantity == Quantity::kTrend || keys[i].quantity == Quantity::kCrossQuadrature))
      d.rows.push_back(i);
  if (d.rows.size() < 6) {
    notes.push_back("the IMU's frame was not checked: the plan gives too few gyro trend and cross-axis cells");
    return std::nullopt;
  }
  const auto m = static_cast<Eigen::Index>(d.rows.size());
  d.a = Eigen::MatrixXd::Zero(m, 5);
  d.y.resize(m);
  d.vertical.resize(m);
  for (Eigen::Index r = 0; r < m; ++r) {
    const std::size_t i = d.rows[static_cast<std::size_t>(r)];
    const auto& g = spread[groupKey(keys[i])];
    const double b = 0.5 * (f.f0[i] + f.f180[i]);
    const double sigma = std::sqrt(g.first / std::max(1.0, g.second) + 1e-6 + 1e-6 * b * b);
    d.a(r, 0) = 0.5 * (f.f0[i] - f.f180[i]) / sigma;  // times cos h
    d.a(r, 1) = (b - f.f90[i]) / sigma;               // times -sin h
    if (keys[i].quantity == Quantity::kTrend) d.a(r, 2 + keys[i].axis) = 1.0 / sigma;  // bias, deg/h
    d.y(r) = (real[i] - b) / sigma;
    d.vertical(r) = 0.5 * (f.f0[i] - f.otherLatitude[i]) / sigma;  // the configured vertical's part
  }
  for (Eigen::Index j = 2; j < 5; ++j)
    if (d.a.col(j).squaredNorm() > 0.0) d.biasCols.push_back(j);
  // Only cells the heading moves by more than their spread take part: where
  // it does not (gyro y in a swing about X), its columns hold only the
  // replays' re-drawn quantisation, which a large unmodelled signal there
  // (g-sensitivity) would turn into a heading. The frame check takes those
  // cells and the ones turning the vertical over moves by more than theirs.
  d.isTrend.resize(m);
  d.inScan.resize(m);
  d.inFrameCheck.resize(m);
  for (Eigen::Index r = 0; r < m; ++r) {
    d.isTrend(r) = keys[d.rows[static_cast<std::size_t>(r)]].quantity == Quantity::kTrend ? 1.0 : 0.0;
    d.inScan(r) = d.isTrend(r) == 0.0 && std::hypot(d.a(r, 0), d.a(r, 1)) > 2.0 ? 1.0 : 0.0;
    d.inFrameCheck(r) = d.isTrend(r) == 0.0 && (d.inScan(r) > 0.0 || 2.0 * std::abs(d.vertical(r)) > 2.0) ? 1.0 : 0.0;
  }
  if (d.inScan.sum() < 2.0 || d.a.col(0).squaredNorm() + d.a.col(1).squaredNorm() <= 0.0) {
    notes.push_back("the IMU's frame was not checked: the plan's swings do not turn the Earth rate between the gyros");
    return std::nullopt;
  }
  return d;
}

// One vertical's heading: the best on the scanned cells, its chi^2's
// curvature there (per deg^2) and the frame check's cells' chi^2 there.
struct HeadingScan {
  double headingDeg = 0.0, curvature = 0.0, frameChiSquare = 0.0;
};

// Both verticals' headings, and whether the scanned cells see cos h and sin h.
struct HeadingScans {
  bool cosSeen = false, sinSeen = false;
  Eigen::VectorXd yOther;  // y for the other vertical
  HeadingScan configured, other;
};

HeadingScan scanHeading(const EarthRateDesign& d, const Eigen::VectorXd& target, bool cosSeen, bool sinSeen) {
  auto allowed = [&](int k) {
    const double h = k * kRadPerDeg;
    return (cosSeen || std::cos(h) >= -1e-12) && (sinSeen || std::sin(h) >= -1e-12);
  };
  std::vector<double> chi(360);
  for (int k = 0; k < 360; ++k)
    chi[static_cast<std::size_t>(k)] = d.rest(target, k).cwiseProduct(d.inScan).squaredNorm();
  int best = -1;
  for (int k = 0; k < 360; ++k)
    if (allowed(k) && (best < 0 || chi[static_cast<std::size_t>(k)] < chi[static_cast<std::size_t>(best)])) best = k;
  const double cm = chi[static_cast<std::size_t>((best + 359) % 360)], c0 = chi[static_cast<std::size_t>(best)],
               cp = chi[static_cast<std::size_t>((best + 1) % 360)];
  HeadingScan s;
  s.curvature = cm - 2.0 * c0 + cp;  // per deg^2
  const double offset = s.curvature > 0.0 ? std::clamp(0.5 * (cm - cp) / s.curvature, -0.5, 0.5) : 0.0;
  s.headingDeg = best + offset;
  if (s.headingDeg > 180.0) s.headingDeg -= 360.0;
  s.frameChiSquare = d.rest(target, s.headingDeg).cwiseProduct(d.inFrameCheck).squaredNorm();
  return s;
}

// The horizontal Earth rate's size is the stated latitude's; its
// direction is searched (1-deg grid, then a parabola through the best
// three) on the quadrature cross cells alone, where the biases do not
// reach; then the biases are the trend cells' least-squares part at that
// heading (setHeadingAndBiases()). (Fitting both on all cells let an
// effect's trend pattern, e.g. g-sensitivity's -k cos(angle) on the
// vertical gyro, pull the heading.)
HeadingScans scanHeadings(const EarthRateDesign& d) {
  HeadingScans s;
  // A component the scanned cells do not see (less than 1 chi^2 between
  // none and all of the horizontal Earth rate along it) leaves the heading
  // two-fold: only X swings see sin h alone, so h and 180 - h fit alike,
  // and the tie used to go to whichever rounded lower (180 deg for a table
  // at 0). The convention is then cos h >= 0 (or sin h >= 0), and the note
  // says so.
  s.cosSeen = d.a.col(0).cwiseProduct(d.inScan).squaredNorm() >= 1.0;
  s.sinSeen = d.a.col(1).cwiseProduct(d.inScan).squaredNorm() >= 1.0;
  s.yOther = d.y + 2.0 * d.vertical;
  s.configured = scanHeading(d, d.y, s.cosSeen, s.sinSeen);
  s.other = scanHeading(d, s.yOther, s.cosSeen, s.sinSeen);
  return s;
}

// The frame check. The vertical Earth rate the data show, as a multiple
// alpha of the configured vertical's (+1: as configured, -1: turned over),
// at the configured vertical's best heading (the heading scan's cells do
// not see the vertical). An isotropic g-sensitivity k shifts alpha by
// k g / (Omega sin lat) and cannot be told from it, so the frame is turned
// over only when the data need alpha < -1/2 (a k beyond 1.5 Omega sin(lat)
// / g in the configured frame, 14.5 deg/h/g at 40 deg), 5 sigma clear of
// that boundary; a decision needs sigma(alpha) <= 0.3. Sets `frame` but its
// zUp, with a note; true when the replays are to use the other vertical.
bool checkFrame(FrameCheck& frame, bool configuredUp, const ImuFrame& stated, const EarthRateDesign& d,
                const HeadingScans& s, std::vector<std::string>& notes) {
  const Eigen::VectorXd v = d.vertical.cwiseProduct(d.inFrameCheck);
  const double information = v.squaredNorm();
  frame.checked = information > 0.0 && 1.0 / std::sqrt(information) <= 0.3;
  bool useOther = false;
  // What the replays use when the data cannot decide the vertical.
  const std::string fallback =
      stated.stated() ? "the stated frame is used" : "z down is assumed: state the IMU's frame";
  if (frame.checked) {
    frame.verticalRatio = 1.0 + d.rest(d.y, s.configured.headingDeg).cwiseProduct(d.inFrameCheck).dot(v) / information;
    frame.verticalRatioStd = 1.0 / std::sqrt(information);
    frame.chiSquareDown = configuredUp ? s.other.frameChiSquare : s.configured.frameChiSquare;
    frame.chiSquareUp = configuredUp ? s.configured.frameChiSquare : s.other.frameChiSquare;
    constexpr double kBoundary = -0.5;
    frame.decisive = std::abs(frame.verticalRatio - kBoundary) > 5.0 * frame.verticalRatioStd;
    useOther = frame.decisive && frame.verticalRatio < kBoundary;
    const bool dataUp = useOther != configuredUp;
    frame.contradicted = stated.stated() && frame.decisive && dataUp != stated.zUp();
    const std::string ratio = "vertical Earth rate " + fmt("%+.2f", frame.verticalRatio) + " +- " +
                              fmt("%.2f", frame.verticalRatioStd) + " of the z-" + (configuredUp ? "up" : "down") +
                              " frame's";
    const std::string shown = std::string("the data show the IMU's z axis ") + (dataUp ? "up" : "down") + " (" +
                              ratio + ")";
    if (!frame.decisive)
      notes.push_back("the data cannot tell the IMU's z axis up from down (" + ratio + "); " + fallback);
    else if (frame.contradicted)
      notes.push_back(shown + "; the bench constants state " + describeImuFrame(stated) +
                      ": the replays use the frame the data show; a latitude of the wrong sign looks the same");
    else if (!stated.stated())
      notes.push_back(shown + "; the bench constants do not state the IMU's frame, so the replays use the one found: "
                              "state it in the bench constants (a latitude of the wrong sign looks the same)");
    else
      notes.push_back(shown + ", as the bench constants state");
  } else {
    notes.push_back("the IMU's frame was not checked: the plan's swings do not turn the vertical Earth rate between "
                    "the gyros; " + fallback);
  }
  return useOther;
}

// Sets the replays' vertical (the other one when useOther), the heading
// (and its spread) and the biases fitted at it, with notes; then validates
// the calibrated chain. Refuses (kInternal) a heading or bias that is not
// finite.
Status setHeadingAndBiases(Calibration& cal, const ImuFrame& stated, const EarthRateDesign& d, const HeadingScans& s,
                           bool useOther, std::vector<std::string>& notes) {
  const bool configuredUp = cal.config.earth.zUp;
  // The other vertical is the configured frame with y and z turned over:
  // its heading is the scan's, negated.
  const HeadingScan& chosen = useOther ? s.other : s.configured;
  const Eigen::VectorXd& target = useOther ? s.yOther : d.y;
  cal.frame.zUp = useOther ? !configuredUp : configuredUp;
  cal.config.earth.zUp = cal.frame.zUp;
  // (When sin h is unseen, h and -h fit alike: the one with sin h >= 0.)
  double heading = useOther && s.sinSeen ? -chosen.headingDeg : chosen.headingDeg;
  // The biases at the heading used, in the configured frame's terms (the
  // other frame's heading is the configured one's negated).
  const double configuredHeading = useOther ? -heading : heading;
  Eigen::MatrixXd t(d.a.rows(), static_cast<Eigen::Index>(d.biasCols.size()));
  for (std::size_t j = 0; j < d.biasCols.size(); ++j) t.col(static_cast<Eigen::Index>(j)) = d.a.col(d.biasCols[j]);
  const auto qr = t.colPivHouseholderQr();
  Eigen::VectorXd biases = d.biasCols.empty()
                               ? Eigen::VectorXd()
                               : Eigen::VectorXd(qr.solve(d.rest(target, configuredHeading).cwiseProduct(d.isTrend)));
  // From finite features the scan is finite; a replay's NaN would otherwise
  // surface as "heading must be within [-360, 360] deg".
  if (!std::isfinite(heading) || !biases.allFinite())
    return Status(StatusCode::kInternal, "the Earth-rate calibration gave a heading of " + fmt("%g", heading) +
                                             " deg or biases that are not finite numbers; nothing was concluded");
  cal.headingDeg = heading;
  cal.headingStdDeg = chosen.curvature > 0.0 ? std::sqrt(2.0 / chosen.curvature) : 180.0;
  cal.config.earth.headingDeg = heading;
  notes.push_back("heading " + fmt("%.1f", heading) + " +- " + fmt("%.1f", cal.headingStdDeg) +
                  " deg, from the Earth rate the gyros see as the table turns" +
                  (s.cosSeen && s.sinSeen ? std::string()
                                          : std::string("; ") + (s.cosSeen ? "sin h" : "cos h") +
                                                " is taken >= 0: the plan's swings do not show its sign"));
  if (const auto statedHeading = stated.xHeadingDeg();
      statedHeading && s.cosSeen && s.sinSeen && !cal.frame.contradicted) {
    const double off = std::remainder(heading - *statedHeading, 360.0);
    if (std::abs(off) > std::max(10.0, 3.0 * cal.headingStdDeg))
      notes.push_back("the heading the data show, " + fmt("%.1f", heading) + " deg, is " + fmt("%.1f", off) +
                      " deg from the stated frame's (" + fmt("%.1f", *statedHeading) +
                      " deg for x): check the bench's heading; the replays use the one found");
  }
  Eigen::VectorXd x = Eigen::VectorXd::Zero(5);
  for (std::size_t j = 0; j < d.biasCols.size(); ++j) x(d.biasCols[j]) = biases(static_cast<Eigen::Index>(j));
  // The biases were fitted at the heading the columns describe; the trend
  // cells of the calibrated replay then match on average.
  for (int ax = 0; ax < kAxisCount; ++ax) {
    cal.biasDegPerH[static_cast<std::size_t>(ax)] = x(2 + ax);
    cal.config.fog.biasDegPerH[static_cast<std::size_t>(ax)] = std::clamp(x(2 + ax), -3000.0, 3000.0);
  }
  return cal.config.validate();
}

}  // namespace

// The table's heading is not in a session, and the Earth rate it turns into
// the body frame shows in every gyro's trend and cross-axis cells as the
// geometry changes between points (a swing about X modulates what z senses
// by Omega cos(lat) sin(h) sin(angle)). Its horizontal part in the table
// frame, Omega cos(lat) (cos h, -sin h), enters the features linearly, as
// does each gyro's bias: replays with zero bias at headings 0, 90 and 180
// deg (common random numbers) give the columns, a second seed the cells'
// spread, and weighted least squares on the trend and cross-axis cells
// gives the heading and the three biases. When the plan leaves cos h or
// sin h unseen (only X swings: sin h), the other is taken with cos h >= 0.
//
// The vertical part, -Omega sin(lat) along down, is the frame check's
// (FrameCheck): a replay at the opposite latitude (same seed) gives its
// column v, and the other vertical is the same frame with y and z turned
// over: its features are the configured ones plus 2 v with the heading
// negated. Each vertical gets its own heading scan; the quadrature cross
// cells either moves by more than its spread decide between them.
Status calibrateEarthRateAndBias(Replay& replay, const std::vector<FeatureKey>& keys, const std::vector<double>& real,
                                 const ImuFrame& stated, const DiagnosisOptions& options,
                                 std::vector<std::string>& notes) {
  Calibration& cal = replay.cal;
  cal.frame = FrameCheck{};
  cal.frame.stated = stated;
  cal.frame.zUp = cal.config.earth.zUp;
  FOG_ASSIGN_OR_RETURN(const EarthRateReplays replays, runEarthRateReplays(replay, real.size(), options));
  const std::optional<EarthRateDesign> design = earthRateDesign(keys, real, replays, notes);
  if (!design) return Status::ok();
  const HeadingScans scans = scanHeadings(*design);
  const bool useOther = checkFrame(cal.frame, cal.config.earth.zUp, stated, *design, scans, notes);
  return setHeadingAndBiases(cal, stated, *design, scans, useOther, notes);
}

Result<AnalysedSession> analyseSession(const Recording& recording, const BenchConstants& constants,
                                       std::vector<std::string>& notes) {
  auto report = analysis::analyzeRecording(recording, constants);
  if (!report) return report.status();

  AnalysedSession s;
  s.used = recording;
  s.used.testPoints.clear();
  for (const auto& tp : recording.testPoints)
    for (const auto& r : report->points)
      if (r.index == tp.index && r.axis == tp.axis) {
        s.used.testPoints.push_back(tp);
        s.results.push_back(r);
        break;
      }
  if (s.used.testPoints.empty()) return insufficientData("no test point gave a delay: nothing to diagnose");
  for (const auto& f : report->failedPoints) notes.push_back("left out: " + f);
  return s;
}

Result<CalibratedReplay> calibrate(const AnalysedSession& session, const SessionInfo* info,
                                   const DiagnosisOptions& options, Progress& progress,
                                   std::vector<std::string>& notes) {
  const Recording& used = session.used;
  CalibratedReplay out;
  Replay& replay = out.replay;
  replay.progress = &progress;
  Calibration& cal = replay.cal;
  model::SimConfig& c = cal.config;
  c.samplingBoard.counterHz = used.counterHz > 0 ? used.counterHz : c.samplingBoard.counterHz;
  c.samplingBoard.counterBits = used.counterBits >= 16 ? used.counterBits : c.samplingBoard.counterBits;
  c.fog.pulseEquivalentDeg = used.pulseEquivalentDeg;
  if (info) c.earth.latitudeDeg = info->bench.latitudeDeg;
  replay.context.earth = c.earth;
  replay.context.expectedDrops = true;
  // The replay samples as the recording did (its own table and IMU periods:
  // an IMU crystal off by ppm, a board at other rates) and moves the table
  // between points as fast as it must: it is not a real table, so the
  // limits do not apply to it.
  if (const double t = recordedPeriodS(used.testPoints, &TestPointData::table); t > 0.0) c.encoder.samplePeriodS = t;
  if (const double t = recordedPeriodS(used.testPoints, &TestPointData::imu); t > 0.0) c.imuBoard.framePeriodS = t;
  c.imuBoard.clockErrorPpm = 0.0;
  c.encoder.readDelayS = std::min(c.encoder.readDelayS, 0.5 * c.encoder.samplePeriodS);
  c.imuBoard.firstSampleS = std::min(c.imuBoard.firstSampleS, 0.5 * c.imuBoard.framePeriodS);
  c.turntable.limits = {kMaxPositionDeg, 1e6, 1e9, 1e12};
  cal.plan.restBetweenS = 1.0;
  std::vector<double> ppm, arw;
  double wsum = 0.0, lagSum = 0.0;
  for (std::size_t i = 0; i < used.testPoints.size(); ++i) {
    const auto& tp = used.testPoints[i];
    const auto& r = session.results[i];
    const double fitHz = r.tableFit.frequencyHz > 0 ? r.tableFit.frequencyHz : r.joint.frequencyHz;
    const double nominalHz = tp.nominalFrequencyHz > 0 ? tp.nominalFrequencyHz : fitHz;
    ppm.push_back((fitHz / nominalHz - 1.0) * 1e6);
    arw.push_back(r.noise.gyroArwDegPerSqrtH);
    const double w = 1.0 / std::max(r.lagStdMs * r.lagStdMs, 1e-12);
    wsum += w;
    lagSum += w * r.lagMs;
    TestPoint p;
    p.axis = tp.axis;
    p.frequencyHz = nominalHz;
    p.amplitudeDeg = std::abs(r.tableFit.amplitudeDeg);
    p.durationS = tp.table.back().timeS - tp.table.front().timeS + 0.5 * c.encoder.samplePeriodS;
    // The replay swings 2 s before it records (longer when the plan says so):
    // a recorded test point is a steady swing, and an imported one states no
    // settle time (0) although its table was swinging before the record.
    p.settleS = 2.0;
    // The table's geometry as recorded: the swing about its fitted centre,
    // the other axes where they were held (a swing about X sees the Earth
    // rate and gravity as the other axes' angles turn them).
    for (int a = 0; a < kAxisCount; ++a) {
      double sum = 0.0;
      for (const auto& sample : tp.table) sum += sample.angleDeg[static_cast<std::size_t>(a)];
      p.positionDeg[static_cast<std::size_t>(a)] = sum / static_cast<double>(tp.table.size());
    }
    p.positionDeg[static_cast<std::size_t>(tp.axis)] = r.tableFit.offsetDeg;
    if (info)
      for (const auto& q : info->plan.points)
        if (&q - info->plan.points.data() == tp.index)
          p.settleS = std::max(p.settleS, q.settleS), p.startPhaseDeg = q.startPhaseDeg;
    cal.plan.points.push_back(p);
    PointReference pr;
    pr.omegaRadPerS = kTwoPi * fitHz;
    pr.segments = segmentsFor(p.durationS, fitHz);
    pr.swingAxis = static_cast<int>(tp.axis);
    replay.ref.points.push_back(pr);
  }
  replay.ref.tablePeriodS = c.encoder.samplePeriodS;
  replay.ref.imuPeriodS = c.imuBoard.framePeriodS;
  cal.tableFrequencyErrorPpm = std::accumulate(ppm.begin(), ppm.end(), 0.0) / static_cast<double>(ppm.size());
  c.turntable.frequencyErrorPpm = std::clamp(cal.tableFrequencyErrorPpm, -999.0, 999.0);
  cal.arwDegPerSqrtH = median(arw);
  c.fog.arwDegPerSqrtH = cal.arwDegPerSqrtH;
  // The bias instability is the IMU's, from its static noise test: within one
  // recording a wander of the bias and a drift or step look alike.
  if (options.biasInstabilityDegPerH) c.fog.biasInstabilityDegPerH = *options.biasInstabilityDegPerH;
  if (options.biasCorrelationS) c.fog.biasCorrelationS = *options.biasCorrelationS;
  cal.biasInstabilityStated = options.biasInstabilityDegPerH.has_value();
  if (!cal.biasInstabilityStated)
    notes.push_back("bias instability " + fmt("%.3g", c.fog.biasInstabilityDegPerH) + " deg/h over " +
                    fmt("%.0f", c.fog.biasCorrelationS) +
                    " s assumed (the simulator's default): a bias drift or step within such a wander is not "
                    "resolved; state the IMU's own (its static noise test) for a sharper test of the gyro trends");
  cal.lagMs = lagSum / wsum;
  // The replay is built from these numbers: a NaN lag or rate would make an
  // invalid chain whose message names the wrong cause.
  for (const auto& [value, what] : {std::pair{cal.lagMs, "lag"}, std::pair{cal.tableFrequencyErrorPpm, "table frequency error"},
                                    std::pair{cal.arwDegPerSqrtH, "angle random walk"}})
    if (!std::isfinite(value))
      return corruptData(std::string("the session's analysis gave a ") + what + " that is not a finite number (" +
                         fmt("%g", value) + "): no replay can be calibrated to it; nothing was concluded");
  setLag(c, cal.lagMs * 1e-3, notes);

  auto realFeatures = extractFeatures(used, replay.ref);
  if (!realFeatures) return realFeatures.status();
  out.real = std::move(*realFeatures);
  // Before anything is calibrated from them (a NaN cell would turn into a
  // NaN bias, refused under a name that hides the cause).
  for (std::size_t i = 0; i < out.real.values.size(); ++i) FOG_RETURN_IF_ERROR(checkFinite(out.real, i));
  const auto& keys = out.real.keys;
  const std::vector<double>& real = out.real.values;
  {
    std::vector<double> tableMs;
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i].channel == Channel::kTable && keys[i].quantity == Quantity::kResidualMeanSquare) tableMs.push_back(real[i]);
    // White encoder noise sigma^2 = q^2 / 12 for a quantising encoder.
    cal.encoderNoiseDeg = std::sqrt(median(tableMs)) * 1e-6;
    if (!std::isfinite(cal.encoderNoiseDeg))
      return corruptData("the session's table residual is not a finite number (" + fmt("%g", cal.encoderNoiseDeg) +
                         " deg): no replay can be calibrated to it; nothing was concluded");
    c.encoder.quantumDeg = std::sqrt(12.0) * cal.encoderNoiseDeg;
    // The quantisation of a swing leaves harmonics in the readings that
    // depend on the amplitude in quanta (A / q ~ 25 700 for 3 deg at
    // 0.42 arcsec) to better than 0.1 %, and the replays, which redraw only
    // the start phase, reproduce their own: sqrt(12) sigma gave 0.4208
    // arcsec for a reference encoder of 0.4216 and left the table channel
    // of two clean sessions at 5.4 and 5.8 sigma (answered "unexplained");
    // the readings' own quantum brought them to 3.4 and -0.1. It is used
    // when the residual is that quantisation (within 10 %).
    if (const double q = readingQuantumDeg(used); q > 0.0 && std::abs(q / c.encoder.quantumDeg - 1.0) < 0.1)
      c.encoder.quantumDeg = q;
  }
  if (Status s = c.validate(); !s.isOk())
    return invalidArgument("the calibrated replay is not a valid chain: " + s.message());
  return out;
}

// Memory: the session's samples, at most one copy of them, and one replay's
// samples per thread at a time with the recording builder's growth: about
// (1.5 + 1.5 threads) times the samples' size (907 MB measured for an hour
// at 1 kHz / 500 Hz on 2 threads, whose samples take 200 MB). Fewer threads
// when that is over the budget; a refusal when even one is.
std::string megabytes(double bytes) { return std::to_string(static_cast<long long>(bytes / 1e6)) + " MB"; }

namespace {
double sampleBytesOf(const Recording& recording) {
  double sampleBytes = 0.0;
  for (const auto& tp : recording.testPoints)
    sampleBytes += static_cast<double>(tp.table.size()) * sizeof(TableSample) +
                   static_cast<double>(tp.imu.size()) * sizeof(ImuSample);
  return sampleBytes;
}
}  // namespace

Result<int> threadsWithinMemory(const Recording& recording, int requested) {
  const double sampleBytes = sampleBytesOf(recording);
  const auto peak = [&](int threads) { return sampleBytes * (1.5 + 1.5 * threads); };
  int threads = std::max(1, requested);
  while (threads > 1 && peak(threads) > kDiagnosisSampleBudgetBytes) --threads;
  if (peak(threads) > kDiagnosisSampleBudgetBytes)
    return outOfRange("the session holds " + megabytes(sampleBytes) + " of samples; its diagnosis would need about " +
                      megabytes(peak(1)) + " of samples, over the " + megabytes(kDiagnosisSampleBudgetBytes) + " they may take of the " +
                      megabytes(kDiagnosisMemoryBudgetBytes) +
                      " limit; diagnose a session of fewer or shorter test points (up to an hour at 1 kHz / 500 Hz "
                      "fits)");
  return threads;
}

// The replays' share of the budget, once the calibrated replay is known and
// before any runs. A replay's stream is not the session's: it settles 2 s
// before each point and rests between points, at the session's own sample
// periods. Each replay holds the recording it builds, at most
// Simulator::frameCounts() table and IMU samples, with the builder's growth
// (1.5x), one replay per thread. Fewer threads when that is over the
// budget; a refusal (kOutOfRange) when even one is. Sets replay.maxFrames
// to the calibrated replay's own bound, which every replay's simulator then
// enforces (they differ from it only in seed, heading, bias and effects,
// none of which can add a frame).
Status budgetReplays(const Recording& input, Replay& replay, DiagnosisOptions& options,
                     std::vector<std::string>& notes) {
  const double sessionPeak = 1.5 * sampleBytesOf(input);
  auto sim = model::Simulator::create(replay.cal.config, replay.cal.plan);
  if (!sim) return outOfRange("the calibrated replay cannot run: " + sim.status().message());
  const auto frames = (*sim)->frameCounts();
  const double perReplay = 1.5 * (frames.table * static_cast<double>(sizeof(TableSample)) +
                                  frames.imu * static_cast<double>(sizeof(ImuSample)));
  int threads = std::max(1, options.threads);
  while (threads > 1 && sessionPeak + threads * perReplay > kDiagnosisSampleBudgetBytes) --threads;
  if (sessionPeak + threads * perReplay > kDiagnosisSampleBudgetBytes)
    return outOfRange("the replay of this session would hold up to " +
                      std::to_string(static_cast<long long>(frames.total())) + " frames (" + megabytes(perReplay) +
                      ": " + fmt("%.0f", (*sim)->endS()) + " s at a table period of " +
                      fmt("%.4g", replay.cal.config.encoder.samplePeriodS * 1e3) + " ms and an IMU period of " +
                      fmt("%.4g", replay.cal.config.imuBoard.framePeriodS * 1e3) +
                      " ms, as calibrated from the stamps), over the " + megabytes(kDiagnosisSampleBudgetBytes) +
                      " that samples may take of the " + megabytes(kDiagnosisMemoryBudgetBytes) +
                      " limit with the session's own " + megabytes(sessionPeak));
  if (threads < options.threads)
    notes.push_back("ran the replays on " + std::to_string(threads) + " of " + std::to_string(options.threads) +
                    " threads, to stay within the " + megabytes(kDiagnosisMemoryBudgetBytes) + " memory limit");
  options.threads = threads;
  replay.maxFrames = frames.total();
  // The motion tape the signature replays share (one sensed instant per IMU
  // frame at most, and the first; one reading per table frame): taken when
  // it fits beside them, else every replay computes its stages, with the
  // same answers.
  const double senses = frames.imu + 2.0, readings = frames.table + 1.0;
  // With the first replay's features' sums, which keep its table samples
  // and IMU stamps (FeatureSums).
  const double tapeBytes = senses * static_cast<double>(sizeof(model::MotionTape::Sense)) +
                           readings * static_cast<double>(sizeof(model::MotionTape::Reading)) +
                           frames.table * static_cast<double>(sizeof(TableSample)) +
                           frames.imu * static_cast<double>(sizeof(double) + sizeof(std::uint64_t));
  const bool tapeFits = sessionPeak + threads * perReplay + tapeBytes <= kDiagnosisSampleBudgetBytes;
  replay.tapeSenses = tapeFits ? static_cast<std::size_t>(senses) : 0;
  replay.tapeReadings = tapeFits ? static_cast<std::size_t>(readings) : 0;
  return Status::ok();
}

}  // namespace fog::diagnosis::detail
