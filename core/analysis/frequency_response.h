#pragma once
// Frequency response of the gyro (issue 32, docs/method.md "Frequency
// response"): the complex gain gyro angle / table angle at each test point of
// one axis, computed from the delay analysis' joint fits (nothing is fitted
// to the samples again), and three transfer-function models fitted to all
// points by weighted least squares on magnitude and phase:
//
//   delay         H(s) = K e^(-s tau)
//   first_order   H(s) = K e^(-s tau) / (1 + s T)
//   second_order  H(s) = K e^(-s tau) wn^2 / (s^2 + 2 zeta wn s + wn^2)
//
// Each with its parameters' standard uncertainties and correlations, chi^2,
// AIC and BIC. Each model is judged before any is chosen (issue 40): it is
// adequate when its chi^2 p-value is at least kModelAdequacyP, admissible
// when its parameters are physical (no delay or time constant negative beyond
// 3 sigma, no damping or natural frequency at its bound 0). Among the
// adequate, admissible models the one with the lowest AIC is chosen (a larger
// model over a simpler one it nests only when it lowers chi^2 by 9 for one
// more parameter, 11.83 for two: 3 sigma); when there is none, none is
// chosen and noModelReason says why. The chosen model's -3 dB bandwidth
// and its group delay at a chosen frequency carry uncertainties propagated
// from the parameters' covariance.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/analysis/delay_analysis.h"
#include "core/common/status.h"

namespace fog::analysis {

// The complex gain at one test point. Phase > 0 would be a lead; a lagging
// gyro has phase < 0 and lagMs = -phase / omega > 0.
struct ResponsePoint {
  int index = 0;  // the test point's index in the report
  double frequencyHz = 0.0;  // the joint fit's frequency
  double magnitude = 0.0, magnitudeStd = 0.0;      // gyro amplitude / table amplitude
  double magnitudeDb = 0.0, magnitudeDbStd = 0.0;  // 20 log10(magnitude)
  double phaseDeg = 0.0, phaseStdDeg = 0.0;
  double lagMs = 0.0, lagStdMs = 0.0;              // the point's reported lag and its uncertainty
  // Covariance of magnitude (ratio) and phase (deg): the point's gain-lag
  // covariance (TestPointResult::gainLagCovMs) with the sign and scale
  // phase = -omega lag gives.
  double magnitudePhaseCovDeg = 0.0;
  double harmonicFraction = 0.0;  // harmonics 2..5 of the table / amplitude (the point's)
};

// The points of `axis` whose validity checks passed (passedItsChecks), in
// order of frequency. The phase uncertainty is omega * lagStdMs (the point's
// reported lag uncertainty, which may exceed the fit's), the magnitude's the
// point's gainStd: both with the allowance for errors that repeat every
// period (delay_analysis.h).
std::vector<ResponsePoint> responsePoints(const DelayReport& report, Axis axis);

enum class ResponseModelKind { kDelay = 0, kFirstOrder = 1, kSecondOrder = 2 };
const char* responseModelName(ResponseModelKind kind);  // "delay", "first_order", "second_order"

struct ResponseParameter {
  std::string name;  // "K", "tau_ms", "T_ms", "fn_hz", "zeta"
  double value = 0.0, stdDev = 0.0;
};

// How a reader sees a parameter: the JSON and the text report name it by
// its key, the GUI and the PDF by its symbol (UTF-8), in every language.
struct ResponseParameterSymbol {
  const char* key;     // "tau_ms"
  const char* symbol;  // "τ"
  const char* unit;    // "ms"; "" when dimensionless
};
// Every parameter of the three models, K first.
const std::vector<ResponseParameterSymbol>& responseParameterSymbols();

// A derived quantity with its propagated standard uncertainty.
struct DerivedValue {
  double value = 0.0, stdDev = 0.0;
};

struct ResponseModelFit {
  ResponseModelKind kind = ResponseModelKind::kDelay;
  std::vector<ResponseParameter> parameters;
  Eigen::MatrixXd correlation;  // of the parameters, in their order
  double chiSquare = 0.0;
  int dof = 0;
  double aic = 0.0, bic = 0.0;  // chi^2 + 2k, chi^2 + k ln(n), n = 2 x points
  // The -3 dB bandwidth (|H| / K = 1/sqrt(2)); none for the pure delay.
  std::optional<DerivedValue> bandwidthHz;
  DerivedValue lowFrequencyDelayMs;  // group delay at 0 Hz: tau, tau + T, tau + 2 zeta / wn
  DerivedValue groupDelayMs;         // -d phase / d omega at ResponseAnalysis::groupDelayAtHz
  // What the points cannot tell apart: parameter pairs correlated beyond 0.95.
  std::vector<std::string> notes;
  // The goodness of fit: P(chi^2_dof >= chiSquare), the probability of a fit
  // this poor or poorer were the model true and the points' sigma right.
  // adequate: pValue >= kModelAdequacyP.
  double pValue = 1.0;
  bool adequate = true;
  // Why the parameters are outside physics, one reason each; empty when the
  // model is admissible.
  std::vector<std::string> inadmissible;
  bool admissible() const { return inadmissible.empty(); }
  // Adequate and admissible: only such a model may be chosen.
  bool eligible() const { return adequate && admissible(); }

  // Model value at f: magnitude (ratio) and phase (rad, continuous).
  double magnitudeAt(double frequencyHz) const;
  double phaseRadAt(double frequencyHz) const;
  Eigen::VectorXd values;  // the parameters in the solver's units (K, tau s, T s | wn rad/s, zeta)
};

// A test point of the axis that has a delay but is not in the response: its
// validity checks failed (the response stands only on points the analysis
// vouches for).
struct LeftOutPoint {
  int index = 0;  // the test point's index in the report
  double frequencyHz = 0.0;
  std::string reason;  // "failed <check>: <its detail>", one per failed check, "; "-joined
};

struct ResponseAnalysis {
  Axis axis = Axis::kX;
  std::vector<ResponsePoint> points;
  // The bench constants the analysis was made with (DelayReport::constants,
  // analyzeResponses sets them): the table read delay and its standard
  // uncertainty, for the phase against the table's motion (certifiedPhase).
  double tableReadDelayMs = 0.0, tableReadDelayStdMs = 0.0;
  std::vector<LeftOutPoint> leftOut;  // set by analyzeResponses; the text and JSON list them
  std::vector<ResponseModelFit> models;  // those with enough points, in kind order
  std::vector<std::string> skipped;      // models left out and why (too few points)
  // Index into models, among the eligible ones only (adequate and
  // admissible): the lowest AIC, except that a larger model is chosen over a
  // simpler eligible one it nests only when it lowers chi^2 by the 3-sigma
  // point for its extra parameters (9 for one, 11.83 for two; a note on it
  // says so otherwise). -1 when no model is eligible ("no model fits": the
  // views show the points alone) or none could be fitted.
  int chosen = -1;
  // When chosen is -1: why, naming each model's p-value or inadmissibility
  // (one line, "no model fits: ..."); empty when a model is chosen.
  std::string noModelReason;
  double groupDelayAtHz = 0.0;
};

// The coverage factor of the expanded uncertainties the response states
// (GUM, JCGM 100 6.2: U = k u; k = 2, about 95 % for a normal distribution,
// as calibration certificates state them).
inline constexpr double kResponseCoverageK = 2.0;

// A point's phase as a calibration certificate states it (issue 40,
// docs/method.md "The standard plan"): the gyro's phase against the table's
// motion, and its expanded uncertainty at k = kResponseCoverageK. The point's
// phase is against the stamped table angle, which was latched the table read
// delay d earlier than its stamp (docs/method.md "The measurement"); against
// the motion the gyro is d later:
//   phase   = phaseDeg - omega d                  (= -omega (lag + d): the IMU delay's phase)
//   u       = sqrt(phaseStdDeg^2 + (omega u_d)^2) (the point's phase sigma, the read delay's uncertainty)
//   U       = k u, in degrees and as a time, U / omega = k sqrt(lagStdMs^2 + u_d^2) ms
// with d and u_d the bench constants (tableReadDelayMs, tableReadDelayStdMs),
// independent of the fit. The models are fitted to phaseDeg (a delay d is a
// part of every model's tau); this is the figure per point.
struct CertifiedPhase {
  double phaseDeg = 0.0;            // against the table's motion
  double standardDeg = 0.0;         // u, k = 1
  double fitStdDeg = 0.0;           // the point's phaseStdDeg: its share of u
  double readDelayStdDeg = 0.0;     // omega u_d: the read delay's share of u
  double coverageK = kResponseCoverageK;
  double expandedDeg = 0.0;         // U = k u
  double expandedMs = 0.0;          // U as a time: U / omega
};
CertifiedPhase certifiedPhase(const ResponsePoint& point, double tableReadDelayMs, double tableReadDelayStdMs,
                              double coverageK = kResponseCoverageK);
// The same with the response's own constants.
CertifiedPhase certifiedPhase(const ResponsePoint& point, const ResponseAnalysis& response);

// A model whose chi^2 p-value is below this is rejected as inadequate
// (docs/method.md "Frequency response"): about 3.1 sigma one-sided, the
// bench's 3-sigma claim level, so that a true model with honest sigma is
// refused in 1 analysis of 1000.
inline constexpr double kModelAdequacyP = 1e-3;

// Fits every model with enough points (2 x points > parameters: the delay and
// the first-order model need 2 frequencies, the second-order model 3).
// Errors: kInvalidArgument for a groupDelayAtHz outside (0, kMaxGroupDelayAtHz]; kInsufficientData
// naming the count when fewer than two points are given; kInvalidArgument for
// a point without a positive magnitude and positive uncertainties.
// Uncertainties: the inverse of the weighted normal matrix, raised by
// sqrt(chi^2/dof) when that exceeds 1 (the points scatter more than stated).
// tableReadDelayMs: the bench constant d the points' phase is measured
// against (the stamped table angle is d late), kept in the result. It sets
// what is physical: tau is the lag behind the stamped angle, so the IMU's
// own delay is tau + d, and a model is not admissible when tau + d (or the
// low-frequency delay + d) is negative beyond 3 sigma; a negative tau above
// -d is a gyro faster than the table's read-out, not a lead.
Result<ResponseAnalysis> analyzeResponse(std::vector<ResponsePoint> points, Axis axis, double groupDelayAtHz,
                                         double tableReadDelayMs = 0.0);

// The frequency at which the views (CLI without --at-hz, GUI, report) give
// the model's group delay.
inline constexpr double kDefaultGroupDelayAtHz = 5.0;
// The highest frequency the group delay is given at: a model's delay is an
// extrapolation beyond the measured band, and a gyro's output rate puts its
// Nyquist frequency below 1 kHz on every bench this serves (500 Hz output:
// 250 Hz); beyond it the model's phase is not a property of the gyro.
inline constexpr double kMaxGroupDelayAtHz = 1000.0;

// Every axis of the report with at least two passed points, each with the
// axis's points left out and why (leftOut).
std::vector<ResponseAnalysis> analyzeResponses(const DelayReport& report,
                                               double groupDelayAtHz = kDefaultGroupDelayAtHz);

// B - A of two responses of one axis (two sessions, Compare) at the
// frequencies both have (within 0.5 % of each other), in frequency order:
// magnitude as the ratio B/A (magnitudeDb the dB difference), phase and lag
// as differences, index B's. A's phase is taken to B's frequency (scaled by
// f_B / f_A, exact for a delay) before the difference. The two sessions' fits share no noise, so the
// uncertainties combine as independent (ratio: relative ones in quadrature).
std::vector<ResponsePoint> responseDifference(const ResponseAnalysis& a, const ResponseAnalysis& b);

std::string formatResponseText(const std::vector<ResponseAnalysis>& responses);
std::string formatResponseJson(const std::vector<ResponseAnalysis>& responses);

}  // namespace fog::analysis
