#include "core/analysis/frequency_response.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/analysis/least_squares.h"
#include "core/analysis/statistics.h"
#include "core/common/units.h"

namespace fog::analysis {

namespace {

constexpr double kStrongCorrelation = 0.95;
// The 3-sigma points (p = 0.27 %) of chi^2 with 1 and 2 degrees of freedom.
constexpr double kFilterClaimChiSquareDrop = 9.0;
constexpr double kTwoParameterClaimChiSquareDrop = 11.83;

// How a note names a model.
const char* modelTitle(ResponseModelKind kind) {
  switch (kind) {
    case ResponseModelKind::kDelay: return "the pure delay";
    case ResponseModelKind::kFirstOrder: return "the first-order lag";
    case ResponseModelKind::kSecondOrder: return "the second-order response";
  }
  return "";
}

int parameterCount(ResponseModelKind kind) {
  switch (kind) {
    case ResponseModelKind::kDelay: return 2;
    case ResponseModelKind::kFirstOrder: return 3;
    case ResponseModelKind::kSecondOrder: return 4;
  }
  return 0;
}

std::vector<std::string> parameterNames(ResponseModelKind kind) {
  switch (kind) {
    case ResponseModelKind::kDelay: return {"K", "tau_ms"};
    case ResponseModelKind::kFirstOrder: return {"K", "tau_ms", "T_ms"};
    case ResponseModelKind::kSecondOrder: return {"K", "tau_ms", "fn_hz", "zeta"};
  }
  return {};
}

// Model magnitude and continuous phase (rad) at f for parameters x in the
// units of parameterNames().
double modelMagnitude(ResponseModelKind kind, const Eigen::VectorXd& x, double f) {
  const double w = kTwoPi * f;
  switch (kind) {
    case ResponseModelKind::kDelay: return x[0];
    case ResponseModelKind::kFirstOrder: {
      const double wt = w * x[2] * 1e-3;
      return x[0] / std::sqrt(1.0 + wt * wt);
    }
    case ResponseModelKind::kSecondOrder: {
      const double r = f / x[2], z = x[3];
      return x[0] / std::sqrt((1.0 - r * r) * (1.0 - r * r) + (2.0 * z * r) * (2.0 * z * r));
    }
  }
  return 0.0;
}

double modelPhase(ResponseModelKind kind, const Eigen::VectorXd& x, double f) {
  const double w = kTwoPi * f;
  double phase = -w * x[1] * 1e-3;
  if (kind == ResponseModelKind::kFirstOrder) phase -= std::atan(w * x[2] * 1e-3);
  if (kind == ResponseModelKind::kSecondOrder) {
    const double r = f / x[2];
    phase -= std::atan2(2.0 * x[3] * r, 1.0 - r * r);
  }
  return phase;
}

double wrapPi(double a) {
  a = std::remainder(a, kTwoPi);
  return a;
}

// Group delay -d phase / d omega at f, s (central difference; at f = 0 one-sided from 0).
double groupDelayS(ResponseModelKind kind, const Eigen::VectorXd& x, double f) {
  const double h = std::max(1e-6, f * 1e-5);
  const double lo = std::max(0.0, f - h), hi = f + h;
  return -(modelPhase(kind, x, hi) - modelPhase(kind, x, lo)) / (kTwoPi * (hi - lo));
}

// -3 dB bandwidth in Hz relative to K; NaN when the model has none.
double bandwidthHz(ResponseModelKind kind, const Eigen::VectorXd& x) {
  if (kind == ResponseModelKind::kFirstOrder) {
    const double t = std::abs(x[2]) * 1e-3;
    return t > 0.0 ? 1.0 / (kTwoPi * t) : std::numeric_limits<double>::quiet_NaN();
  }
  if (kind == ResponseModelKind::kSecondOrder) {
    const double a = 1.0 - 2.0 * x[3] * x[3];
    return std::abs(x[2]) * std::sqrt(a + std::sqrt(a * a + 1.0));
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// The second order in its polynomial form H = K e^(-s tau) / (1 + b s + a s^2),
// x = (K, tau_ms, b_ms, a_ms2) with b = 2 zeta / wn and a = 1 / wn^2 (fitModel
// says why).
double polynomialMagnitude(const Eigen::VectorXd& x, double f) {
  const double w = kTwoPi * f * 1e-3;  // rad per ms
  return x[0] / std::hypot(1.0 - x[3] * w * w, x[2] * w);
}
double polynomialPhase(const Eigen::VectorXd& x, double f) {
  const double w = kTwoPi * f * 1e-3;
  return -w * x[1] - std::atan2(x[2] * w, 1.0 - x[3] * w * w);
}

// Whitened residuals (model - data) of every point: 2 per point. The second
// order in (f_n, zeta) or, `polynomial`, in (b, a) (above).
class ResponseProblem : public LeastSquaresProblem {
 public:
  ResponseProblem(ResponseModelKind kind, const std::vector<ResponsePoint>& points, bool polynomial = false)
      : kind_(kind), polynomial_(polynomial && kind == ResponseModelKind::kSecondOrder), points_(points) {
    for (const auto& p : points) {
      const double sm = p.magnitudeStd, sp = p.phaseStdDeg * kRadPerDeg;
      const double c = p.magnitudePhaseCovDeg * kRadPerDeg;
      // C = L L^T; whitening is L^-1.
      const double l11 = sm, l21 = c / sm, l22 = std::sqrt(std::max(sp * sp - l21 * l21, 1e-30 * sp * sp));
      Eigen::Matrix2d inv;
      inv << 1.0 / l11, 0.0, -l21 / (l11 * l22), 1.0 / l22;
      whiten_.push_back(inv);
    }
  }
  std::size_t numResiduals() const override { return 2 * points_.size(); }
  int numParameters() const override { return parameterCount(kind_); }
  Eigen::VectorXd residuals(const Eigen::VectorXd& x) const {
    Eigen::VectorXd r(numResiduals());
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const auto& p = points_[i];
      const double magnitude = polynomial_ ? polynomialMagnitude(x, p.frequencyHz)
                                           : modelMagnitude(kind_, x, p.frequencyHz);
      const double phase = polynomial_ ? polynomialPhase(x, p.frequencyHz) : modelPhase(kind_, x, p.frequencyHz);
      const Eigen::Vector2d d(magnitude - p.magnitude, wrapPi(phase - p.phaseDeg * kRadPerDeg));
      r.segment<2>(2 * i) = whiten_[i] * d;
    }
    return r;
  }
  double accumulate(const double* xp, Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) const override {
    const int n = numParameters();
    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(xp, n);
    const Eigen::VectorXd r = residuals(x);
    if (jtj && jtr) {
      Eigen::MatrixXd j(r.size(), n);
      for (int k = 0; k < n; ++k) {
        const double h = 1e-6 * std::max(1.0, std::abs(x[k]));
        Eigen::VectorXd up = x, down = x;
        up[k] += h;
        down[k] -= h;
        j.col(k) = (residuals(up) - residuals(down)) / (2.0 * h);
      }
      *jtj += j.transpose() * j;
      *jtr += j.transpose() * r;
    }
    return r.squaredNorm();
  }

 private:
  ResponseModelKind kind_;
  bool polynomial_;
  const std::vector<ResponsePoint>& points_;
  std::vector<Eigen::Matrix2d> whiten_;
};

// sigma of g(x) from the covariance, by a central-difference gradient.
template <class G>
double propagate(const G& g, const Eigen::VectorXd& x, const Eigen::MatrixXd& cov) {
  Eigen::VectorXd grad(x.size());
  for (int k = 0; k < x.size(); ++k) {
    const double h = 1e-6 * std::max(1.0, std::abs(x[k]));
    Eigen::VectorXd up = x, down = x;
    up[k] += h;
    down[k] -= h;
    grad[k] = (g(up) - g(down)) / (2.0 * h);
  }
  return std::sqrt(std::max(0.0, grad.dot(cov * grad)));
}

std::string fmt(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

// A fitted value to the decimal of its uncertainty's second significant
// digit (GUM 7.2.6), as that uncertainty is printed (two digits), at most 7
// significant digits: the digits a fit does not determine (a time constant
// of 0.0106 ± 0.020 ms, nearly degenerate with the delay) are not printed,
// for they change with the order in which the points' sums were added. A
// value below that decimal prints as 0. Without a usable uncertainty,
// `fallbackDigits` significant digits. The JSON keeps every digit.
std::string fmtToUncertainty(double v, double stdDev, int fallbackDigits = 7) {
  const double printedStd = std::strtod(fmt(stdDev, 2).c_str(), nullptr);
  if (!std::isfinite(v) || v == 0.0 || !std::isfinite(printedStd) || !(printedStd > 0.0))
    return fmt(v, fallbackDigits);
  const int digits = static_cast<int>(std::floor(std::log10(std::abs(v))) - std::floor(std::log10(printedStd))) + 2;
  return digits < 1 ? std::string("0") : fmt(v, std::min(digits, 7));
}

std::vector<Eigen::VectorXd> startingPoints(ResponseModelKind kind, const std::vector<ResponsePoint>& points) {
  double wk = 0.0, k = 0.0, wt = 0.0, tau = 0.0;
  for (const auto& p : points) {
    const double a = 1.0 / (p.magnitudeStd * p.magnitudeStd), b = 1.0 / (p.lagStdMs * p.lagStdMs);
    wk += a, k += a * p.magnitude, wt += b, tau += b * p.lagMs;
  }
  k /= wk, tau /= wt;
  const double fMax = points.back().frequencyHz;
  std::vector<Eigen::VectorXd> starts;
  switch (kind) {
    case ResponseModelKind::kDelay: starts.push_back(Eigen::Vector2d(k, tau)); break;
    case ResponseModelKind::kFirstOrder:
      for (double share : {0.05, 0.5, 0.95}) starts.push_back(Eigen::Vector3d(k, tau * (1.0 - share), tau * share));
      break;
    case ResponseModelKind::kSecondOrder:
      // In (f_n, zeta): resonances above the points (fitModel adds two from the nested models).
      for (double fn : {2.0 * fMax, 5.0 * fMax, 20.0 * fMax})
        for (double zeta : {0.15, 0.7, 1.5}) {
          const double filter = 2.0 * zeta / (kTwoPi * fn) * 1e3;
          starts.push_back(Eigen::Vector4d(k, tau - filter, fn, zeta));
        }
      break;
  }
  return starts;
}

// The model's goodness of fit and physical admissibility (docs/method.md
// "Frequency response"): adequate when P(chi^2_dof >= chi^2) >= kModelAdequacyP;
// not admissible, with the reason, when the IMU's delay tau + d (d the table
// read delay: tau is the lag behind the stamped angle) or the low-frequency
// delay + d is negative beyond 3 sigma, a time constant is negative beyond 3
// sigma, or a second order's zeta or f_n sits at its bound 0 (within 3 sigma
// of it, or the fit ran past it: `unstable`).
void judgeModel(ResponseModelFit& fit, bool unstable, double readDelayMs) {
  fit.pValue = fit.dof > 0 ? chiSquareSurvival(fit.chiSquare, fit.dof) : 1.0;
  fit.adequate = fit.pValue >= kModelAdequacyP;
  auto valueText = [](const ResponseParameter& p, const char* unit) {
    return p.name + " = " + fmt(p.value, 4) + " ± " + fmt(p.stdDev, 2) + unit;
  };
  // Below -d beyond 3 sigma: said as the bench has always said it when d is
  // 0, and with d named otherwise.
  auto belowFloor = [readDelayMs](const std::string& what) {
    return readDelayMs == 0.0 ? what + " is negative beyond 3 sigma: the gyro would answer before the table moves"
                              : what + " is below -" + fmt(readDelayMs, 4) +
                                    " ms (minus the table read delay) beyond 3 sigma: the gyro would answer before "
                                    "the table moves";
  };
  for (const auto& p : fit.parameters) {
    if (p.name == "tau_ms" && p.value + readDelayMs + 3.0 * p.stdDev < 0.0)
      fit.inadmissible.push_back(belowFloor(valueText(p, " ms")));
    if (p.name == "T_ms" && p.value + 3.0 * p.stdDev < 0.0)
      fit.inadmissible.push_back(valueText(p, " ms") + " is negative beyond 3 sigma: a lead, not a lag");
    if ((p.name == "zeta" || p.name == "fn_hz") && !(p.value - 3.0 * p.stdDev > 0.0))
      fit.inadmissible.push_back(valueText(p, p.name == "fn_hz" ? " Hz" : "") +
                                 " sits at its bound 0 within 3 sigma: the points do not place the resonance");
  }
  // tau and T (or 2 zeta / wn) are nearly degenerate when the filter is
  // short: each alone may be vague while their sum, the low-frequency delay,
  // is sharp. A negative sum is the gyro ahead of the table as much.
  const DerivedValue& low = fit.lowFrequencyDelayMs;
  if (fit.kind != ResponseModelKind::kDelay && low.value + readDelayMs + 3.0 * low.stdDev < 0.0)
    fit.inadmissible.push_back(belowFloor("the low-frequency delay " + fmt(low.value, 4) + " ± " + fmt(low.stdDev, 2) +
                                          " ms"));
  if (unstable)
    fit.inadmissible.push_back("the fit ran past zeta = 0: its poles are unstable (a lead that grows to the resonance)");
}

// A second-order solution in (f_n, zeta), from one in (b, a) with a > 0:
// f_n = 1 / (2 pi sqrt(a)), zeta = b / (2 sqrt(a)), the covariance through
// the map's Jacobian.
LeastSquaresSolution toNatural(LeastSquaresSolution s) {
  const double b = s.x[2], a = s.x[3], root = std::sqrt(a);
  const double fn = 1e3 / (kTwoPi * root), zeta = b / (2.0 * root);
  Eigen::Matrix4d j = Eigen::Matrix4d::Identity();
  j(2, 2) = 0.0, j(2, 3) = -fn / (2.0 * a);
  j(3, 2) = 1.0 / (2.0 * root), j(3, 3) = -zeta / (2.0 * a);
  s.covariance = j * s.covariance * j.transpose();
  s.x[2] = fn, s.x[3] = zeta;
  return s;
}

Result<ResponseModelFit> fitModel(ResponseModelKind kind, const std::vector<ResponsePoint>& points,
                                  double groupDelayAtHz, double readDelayMs) {
  const ResponseProblem problem(kind, points);
  std::optional<LeastSquaresSolution> best;
  Status lastError = Status::ok();
  auto keep = [&best](LeastSquaresSolution s) {
    if (!best || s.chiSquare < best->chiSquare) best = std::move(s);
  };
  std::size_t starts = 0;
  for (const auto& x0 : startingPoints(kind, points)) {
    ++starts;
    auto sol = solveLeastSquares(problem, x0);
    if (!sol) {
      lastError = sol.status();
      continue;
    }
    keep(std::move(*sol));
  }
  // The second order also from the nested models, in its polynomial form
  // K e^(-s tau) / (1 + b s + a s^2), b = 2 zeta / wn, a = 1 / wn^2, where
  // the delay (a = b = 0) and the first-order lag (a = 0, b = T) are inner
  // points: in (f_n, zeta) they lie at f_n -> infinity, and on their data
  // every resonant start ran off and never converged. A solution there with
  // a <= 0 has no natural frequency and is not kept (a -> 0 is the nested
  // models; a < 0 beyond its sigma a magnitude droop without a filter's
  // phase: an average, e.g. a boxcar of about sqrt(24 |a|)).
  std::optional<LeastSquaresSolution> noResonance;
  if (kind == ResponseModelKind::kSecondOrder) {
    const ResponseProblem polynomial(kind, points, true);
    const Eigen::VectorXd half = startingPoints(ResponseModelKind::kFirstOrder, points)[1];  // (K, tau/2, tau/2)
    for (const Eigen::Vector4d& x0 : {Eigen::Vector4d(half[0], half[1] + half[2], 0.0, 0.0),
                                     Eigen::Vector4d(half[0], half[1], half[2], 0.0)}) {
      ++starts;
      auto sol = solveLeastSquares(polynomial, x0);
      if (!sol) {
        lastError = sol.status();
        continue;
      }
      if (sol->x[3] > 0.0 && std::isfinite(sol->x[3]))
        keep(toNatural(std::move(*sol)));
      else if (!noResonance || sol->chiSquare < noResonance->chiSquare)
        noResonance = std::move(*sol);
    }
  }
  if (!best && noResonance) {
    const double a = noResonance->x[3], b = noResonance->x[2];
    std::string why = std::string(responseModelName(kind)) + ": its best fit has 1/wn^2 = " + fmt(a, 3) +
                      " ms^2, not above 0: the points hold no resonance";
    const double aStd = std::sqrt(std::max(0.0, noResonance->covariance(3, 3)));
    if (a + 3.0 * aStd < 0.0)  // below 0 beyond 3 sigma: what the points show instead
      why += " (a magnitude droop without a filter's phase, as an average over about " +
             fmt(std::sqrt(24.0 * -a), 3) + " ms would give)";
    else
      why += " (the first-order lag, T = " + fmt(b, 4) + " ms, is its limit)";
    return Status(StatusCode::kNotConverged, why);
  }
  if (!best)
    return Status(lastError.code(), std::string(responseModelName(kind)) + ": no fit from any of its " +
                                        std::to_string(starts) + " starting points (" + lastError.message() +
                                        "); the points may not hold such a filter");

  ResponseModelFit fit;
  fit.kind = kind;
  Eigen::VectorXd x = best->x;
  Eigen::MatrixXd cov = best->covariance;
  // The second order depends on zeta / f_n only through zeta * f / f_n: both
  // negative is the stable model, one negative an unstable one (judged below).
  const bool unstable = kind == ResponseModelKind::kSecondOrder && x[2] * x[3] < 0.0;
  if (kind == ResponseModelKind::kSecondOrder) x[2] = std::abs(x[2]), x[3] = std::abs(x[3]);
  fit.values = x;
  const int k = parameterCount(kind);
  const int n = static_cast<int>(problem.numResiduals());
  fit.chiSquare = best->chiSquare;
  fit.dof = n - k;
  fit.aic = fit.chiSquare + 2.0 * k;
  fit.bic = fit.chiSquare + k * std::log(static_cast<double>(n));
  // The solver scales its covariance by chi^2/dof; undo that, then raise it
  // only when the points scatter more than their stated uncertainties.
  const double birge = fit.chiSquare / fit.dof;
  if (birge > 0.0) cov /= birge;
  if (birge > 1.0) cov *= birge;
  const auto names = parameterNames(kind);
  fit.correlation = Eigen::MatrixXd::Identity(k, k);
  for (int i = 0; i < k; ++i) {
    fit.parameters.push_back({names[i], x[i], std::sqrt(cov(i, i))});
    for (int j = 0; j < k; ++j)
      if (i != j) fit.correlation(i, j) = cov(i, j) / std::sqrt(cov(i, i) * cov(j, j));
  }
  auto lowDelay = [kind](const Eigen::VectorXd& p) { return groupDelayS(kind, p, 0.0) * 1e3; };
  auto atDelay = [kind, groupDelayAtHz](const Eigen::VectorXd& p) {
    return groupDelayS(kind, p, groupDelayAtHz) * 1e3;
  };
  fit.lowFrequencyDelayMs = {lowDelay(x), propagate(lowDelay, x, cov)};
  fit.groupDelayMs = {atDelay(x), propagate(atDelay, x, cov)};
  if (kind != ResponseModelKind::kDelay) {
    auto bw = [kind](const Eigen::VectorXd& p) { return bandwidthHz(kind, p); };
    const double value = bw(x);
    if (std::isfinite(value)) {
      fit.bandwidthHz = DerivedValue{value, propagate(bw, x, cov)};
      if (value > points.back().frequencyHz)
        fit.notes.push_back("the -3 dB bandwidth " + fmt(value, 4) + " Hz lies beyond the highest point (" +
                            fmt(points.back().frequencyHz, 4) + " Hz): an extrapolation of the model");
    }
  }
  for (int i = 0; i < k; ++i)
    for (int j = i + 1; j < k; ++j)
      if (std::abs(fit.correlation(i, j)) > kStrongCorrelation)
        fit.notes.push_back(names[i] + " and " + names[j] + " correlate at " + fmt(fit.correlation(i, j), 3) +
                            ": the points barely separate them (the low-frequency delay " +
                            fmt(fit.lowFrequencyDelayMs.value, 5) + " ± " + fmt(fit.lowFrequencyDelayMs.stdDev, 2) +
                            " ms is better determined than either)");
  for (int i = 1; i < k; ++i)
    if (names[i] != "tau_ms" && std::abs(x[i]) < 2.0 * fit.parameters[i].stdDev)
      fit.notes.push_back(names[i] + " = " + fmt(x[i], 4) + " ± " + fmt(fit.parameters[i].stdDev, 2) +
                          " is not distinguished from 0 by these points");
  judgeModel(fit, unstable, readDelayMs);
  return fit;
}

// Why no model is chosen: each model's inadequacy (its p-value) and
// inadmissibility, as "; "-separated messages after "no model fits: ".
std::string noModelReason(const std::vector<ResponseModelFit>& models) {
  if (models.empty()) return "no model fits: none could be fitted";
  std::string why;
  auto add = [&why](const std::string& reason) { why += (why.empty() ? "" : "; ") + reason; };
  for (const auto& m : models) {
    if (!m.adequate)
      add(std::string(modelTitle(m.kind)) + " is not adequate: chi^2 " + fmt(m.chiSquare, 5) + " on " +
          std::to_string(m.dof) + " dof, p = " + fmt(m.pValue, 2) + " below " + fmt(kModelAdequacyP, 3));
    for (const auto& reason : m.inadmissible) add(std::string(modelTitle(m.kind)) + " is not admissible: " + reason);
  }
  return "no model fits: " + why;
}

// Chooses among the eligible (adequate, admissible) models of `out`.
void chooseModel(ResponseAnalysis& out) {
  for (std::size_t i = 0; i < out.models.size(); ++i)
    if (out.models[i].eligible() && (out.chosen < 0 || out.models[i].aic < out.models[out.chosen].aic))
      out.chosen = static_cast<int>(i);
  if (out.chosen < 0) {
    out.noModelReason = noModelReason(out.models);
    return;
  }
  // A filter is claimed at 3 sigma, as everything the bench names. Each
  // model nests the simpler ones (the first order is the delay at T = 0;
  // the second order holds the delay as f_n -> infinity and the first order
  // as its overdamped limit, one pole fast), and on data of the simpler one
  // AIC prefers the larger model by chance whenever chi^2 drops by more than
  // 2 per parameter (16 % for one). The parameters' sigma cannot judge it
  // near the nesting point (T shows only through (omega T)^2 there: T /
  // sigma(T) is about twice the likelihood ratio's square root); the chi^2
  // drop can. A larger model is chosen over a simpler one only when it
  // lowers chi^2 by the 3-sigma point of chi^2 with its extra parameters'
  // degrees of freedom (9.0 for one, 11.8 for two); otherwise the simplest
  // model it does not beat is chosen, and a note on it says why.
  auto claimAt = [](int extra) { return extra == 1 ? kFilterClaimChiSquareDrop : kTwoParameterClaimChiSquareDrop; };
  auto extraOver = [&out](std::size_t larger, std::size_t smaller) {
    return parameterCount(out.models[larger].kind) - parameterCount(out.models[smaller].kind);
  };
  // notedAbout[i]: the simpler model model i's note says is chosen instead.
  std::vector<std::size_t> notedAbout(out.models.size(), out.models.size());
  auto note = [&](std::size_t larger, std::size_t smaller) {
    notedAbout[larger] = smaller;
    const int extra = extraOver(larger, smaller);
    out.models[larger].notes.push_back(
        "AIC prefers it to " + std::string(modelTitle(out.models[smaller].kind)) + " by " +
        fmt(out.models[smaller].aic - out.models[larger].aic, 3) + ", but it lowers chi^2 by " +
        fmt(out.models[smaller].chiSquare - out.models[larger].chiSquare, 3) + " only (" + std::to_string(extra) +
        " more parameter" + (extra > 1 ? "s" : "") + " claimed at " + fmt(claimAt(extra), 3) +
        ", 3 sigma): " + modelTitle(out.models[smaller].kind) + " is chosen");
  };
  for (bool moved = true; moved && out.chosen >= 0;) {
    moved = false;
    const auto c = static_cast<std::size_t>(out.chosen);
    for (std::size_t i = 0; i < out.models.size(); ++i) {
      const int extra = extraOver(c, i);
      if (extra <= 0 || !out.models[i].eligible()) continue;
      const double drop = out.models[i].chiSquare - out.models[c].chiSquare;
      if (drop >= claimAt(extra)) continue;
      note(c, i);
      out.chosen = static_cast<int>(i);  // the models are in order of size: the simplest first
      moved = true;
      break;
    }
  }
  // Every other larger model AIC prefers to the one chosen says why it is
  // not the answer (the walk above may pass it by: from the second order
  // straight to the delay).
  const auto chosen = static_cast<std::size_t>(out.chosen);
  for (std::size_t i = 0; i < out.models.size(); ++i) {
    const auto& m = out.models[i];
    if (extraOver(i, chosen) > 0 && m.eligible() && m.aic < out.models[chosen].aic && notedAbout[i] != chosen)
      note(i, chosen);
  }
}

}  // namespace

const std::vector<ResponseParameterSymbol>& responseParameterSymbols() {
  static const std::vector<ResponseParameterSymbol> kSymbols = {
      {"K", "K", ""}, {"tau_ms", "τ", "ms"}, {"T_ms", "T", "ms"}, {"fn_hz", "fₙ", "Hz"}, {"zeta", "ζ", ""}};
  return kSymbols;
}

const char* responseModelName(ResponseModelKind kind) {
  switch (kind) {
    case ResponseModelKind::kDelay: return "delay";
    case ResponseModelKind::kFirstOrder: return "first_order";
    case ResponseModelKind::kSecondOrder: return "second_order";
  }
  return "?";
}

double ResponseModelFit::magnitudeAt(double frequencyHz) const { return modelMagnitude(kind, values, frequencyHz); }
double ResponseModelFit::phaseRadAt(double frequencyHz) const { return modelPhase(kind, values, frequencyHz); }

std::vector<ResponsePoint> responsePoints(const DelayReport& report, Axis axis) {
  std::vector<ResponsePoint> out;
  for (const auto& r : report.points) {
    if (r.axis != axis || !passedItsChecks(r)) continue;
    ResponsePoint p;
    p.index = r.index;
    p.frequencyHz = r.joint.frequencyHz;
    const double w = kTwoPi * p.frequencyHz;
    p.magnitude = r.magnitudeRatio;
    p.magnitudeStd = r.gainStd;
    p.magnitudeDb = 20.0 * std::log10(p.magnitude);
    p.magnitudeDbStd = 20.0 / std::log(10.0) * p.magnitudeStd / p.magnitude;
    p.lagMs = r.lagMs;
    p.lagStdMs = r.lagStdMs;
    p.phaseDeg = -w * r.lagMs * 1e-3 * kDegPerRad;
    p.phaseStdDeg = w * r.lagStdMs * 1e-3 * kDegPerRad;
    // phase = -omega lag: the covariance changes sign.
    p.magnitudePhaseCovDeg = -w * 1e-3 * kDegPerRad * r.gainLagCovMs;
    p.harmonicFraction = r.harmonicFraction;
    out.push_back(p);
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.frequencyHz < b.frequencyHz; });
  return out;
}

CertifiedPhase certifiedPhase(const ResponsePoint& p, double readDelayMs, double readDelayStdMs, double k) {
  CertifiedPhase c;
  const double degPerMs = 360.0 * p.frequencyHz * 1e-3;  // omega in deg per ms
  // Within (-180, 180] as the point's own phase.
  c.phaseDeg = -std::remainder(-(p.phaseDeg - degPerMs * readDelayMs), 360.0);
  c.fitStdDeg = p.phaseStdDeg;
  c.readDelayStdDeg = degPerMs * readDelayStdMs;
  c.standardDeg = std::hypot(c.fitStdDeg, c.readDelayStdDeg);
  c.coverageK = k;
  c.expandedDeg = k * c.standardDeg;
  c.expandedMs = c.expandedDeg / degPerMs;  // k sqrt(lagStdMs^2 + u_d^2) when phaseStdDeg = omega lagStdMs
  return c;
}

CertifiedPhase certifiedPhase(const ResponsePoint& p, const ResponseAnalysis& r) {
  return certifiedPhase(p, r.tableReadDelayMs, r.tableReadDelayStdMs);
}

Result<ResponseAnalysis> analyzeResponse(std::vector<ResponsePoint> points, Axis axis, double groupDelayAtHz,
                                         double tableReadDelayMs) {
  if (!(groupDelayAtHz > 0.0 && groupDelayAtHz <= kMaxGroupDelayAtHz))
    return invalidArgument("the group delay's frequency must be in (0, " +
                           std::to_string(static_cast<int>(kMaxGroupDelayAtHz)) + "] Hz, got " +
                           fmt(groupDelayAtHz, 6));
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.frequencyHz < b.frequencyHz; });
  if (points.size() < 2)
    return Status(StatusCode::kInsufficientData,
                  std::string("a frequency response of axis ") + axisLabel(axis) +
                      " needs at least two test points that passed their checks, got " +
                      std::to_string(points.size()) + " (run --preset response gives 20)");
  for (const auto& p : points)
    if (!(p.magnitudeStd > 0.0) || !(p.phaseStdDeg > 0.0) || !std::isfinite(p.magnitude) || !(p.magnitude > 0.0))
      return invalidArgument("test point " + std::to_string(p.index + 1) +
                             " has no positive magnitude and uncertainties to weight it with");
  ResponseAnalysis out;
  out.axis = axis;
  out.points = std::move(points);
  out.tableReadDelayMs = tableReadDelayMs;
  out.groupDelayAtHz = groupDelayAtHz;
  const int n = 2 * static_cast<int>(out.points.size());
  for (auto kind : {ResponseModelKind::kDelay, ResponseModelKind::kFirstOrder, ResponseModelKind::kSecondOrder}) {
    const int k = parameterCount(kind);
    if (n <= k) {
      out.skipped.push_back(std::string(responseModelName(kind)) + ": " + std::to_string(k) +
                            " parameters need more than " + std::to_string(k) + " values, " +
                            std::to_string(out.points.size()) + " points give " + std::to_string(n));
      continue;
    }
    auto fit = fitModel(kind, out.points, groupDelayAtHz, tableReadDelayMs);
    if (!fit) {
      out.skipped.push_back(fit.status().message());
      continue;
    }
    out.models.push_back(std::move(*fit));
  }
  chooseModel(out);
  return out;
}

std::vector<ResponseAnalysis> analyzeResponses(const DelayReport& report, double groupDelayAtHz) {
  std::vector<ResponseAnalysis> out;
  for (int a = 0; a < kAxisCount; ++a) {
    auto points = responsePoints(report, static_cast<Axis>(a));
    if (points.size() < 2) continue;
    auto r = analyzeResponse(std::move(points), static_cast<Axis>(a), groupDelayAtHz,
                             report.constants.tableReadDelayMs);
    if (!r) continue;
    r->tableReadDelayStdMs = report.constants.tableReadDelayStdMs;
    for (const auto& tp : report.points) {
      if (tp.axis != static_cast<Axis>(a) || passedItsChecks(tp)) continue;
      LeftOutPoint left{tp.index, tp.joint.frequencyHz, {}};
      for (const auto& c : tp.checks)
        if (c.judged && !c.passed)
          left.reason += (left.reason.empty() ? "" : "; ") + ("failed " + c.id + ": " + c.detail);
      r->leftOut.push_back(std::move(left));
    }
    out.push_back(std::move(*r));
  }
  return out;
}

std::vector<ResponsePoint> responseDifference(const ResponseAnalysis& a, const ResponseAnalysis& b) {
  constexpr double kSameFrequency = 0.005;
  std::vector<ResponsePoint> out;
  for (const auto& pb : b.points) {
    const auto pa = std::find_if(a.points.begin(), a.points.end(), [&](const ResponsePoint& p) {
      return std::abs(p.frequencyHz - pb.frequencyHz) <= kSameFrequency * pb.frequencyHz;
    });
    if (pa == a.points.end()) continue;
    ResponsePoint d;
    d.index = pb.index;
    d.frequencyHz = pb.frequencyHz;
    d.magnitude = pb.magnitude / pa->magnitude;
    const double relA = pa->magnitudeStd / pa->magnitude, relB = pb.magnitudeStd / pb.magnitude;
    d.magnitudeStd = d.magnitude * std::hypot(relA, relB);
    d.magnitudeDb = pb.magnitudeDb - pa->magnitudeDb;
    d.magnitudeDbStd = std::hypot(pa->magnitudeDbStd, pb.magnitudeDbStd);
    // A's phase at B's frequency: the two points may be up to 0.5 % apart,
    // and a delay's phase -omega tau scales with the frequency (at 11 Hz a
    // 2.5-ms lag would otherwise give 0.05 deg of false difference, 500 sigma).
    const double toB = pb.frequencyHz / pa->frequencyHz;
    d.phaseDeg = pb.phaseDeg - pa->phaseDeg * toB;
    d.phaseStdDeg = std::hypot(pa->phaseStdDeg * toB, pb.phaseStdDeg);
    d.lagMs = pb.lagMs - pa->lagMs;
    d.lagStdMs = std::hypot(pa->lagStdMs, pb.lagStdMs);
    // r = mB/mA, dr = r (dmB/mB - dmA/mA), dphi = dphiB - dphiA.
    d.magnitudePhaseCovDeg =
        d.magnitude * (pb.magnitudePhaseCovDeg / pb.magnitude + toB * pa->magnitudePhaseCovDeg / pa->magnitude);
    d.harmonicFraction = std::max(pa->harmonicFraction, pb.harmonicFraction);
    out.push_back(d);
  }
  return out;
}

std::string formatResponseText(const std::vector<ResponseAnalysis>& responses) {
  std::ostringstream o;
  char line[256];
  for (const auto& r : responses) {
    o << "Frequency response, " << axisLabel(r.axis) << " axis (gyro angle / table angle), " << r.points.size()
      << " points\n";
    std::snprintf(line, sizeof line, "  %9s %10s %9s %9s %8s %10s %9s %9s %8s %6s\n", "f Hz", "|H|", "± ", "dB",
                  "± ", "phase deg", "± ", "lag ms", "± ", "corr");
    o << line;
    for (const auto& p : r.points) {
      const double corr = p.magnitudePhaseCovDeg / (p.magnitudeStd * p.phaseStdDeg);
      std::snprintf(line, sizeof line, "  %9.4f %10.7f %9.2e %9.5f %8.1e %10.5f %9.2e %9.5f %8.1e %6.2f\n",
                    p.frequencyHz, p.magnitude, p.magnitudeStd, p.magnitudeDb, p.magnitudeDbStd, p.phaseDeg,
                    p.phaseStdDeg, p.lagMs, p.lagStdMs, corr);
      o << line;
    }
    // The certificate's phase (certifiedPhase): against the table's motion,
    // with its expanded uncertainty and the budget behind it.
    o << "  phase against the table's motion (the stamped phase corrected by the table read delay "
      << fmt(r.tableReadDelayMs, 4) << " ± " << fmt(r.tableReadDelayStdMs, 4) << " ms), expanded uncertainty U (k = "
      << fmt(kResponseCoverageK, 2) << "):\n";
    std::snprintf(line, sizeof line, "  %9s %10s %9s %9s   %s\n", "f Hz", "phase deg", "U deg", "U ms",
                  "u: fit deg, read delay deg");
    o << line;
    for (const auto& p : r.points) {
      const CertifiedPhase c = certifiedPhase(p, r);
      std::snprintf(line, sizeof line, "  %9.4f %10.5f %9.2e %9.2e   %8.1e, %8.1e\n", p.frequencyHz, c.phaseDeg,
                    c.expandedDeg, c.expandedMs, c.fitStdDeg, c.readDelayStdDeg);
      o << line;
    }
    if (!(r.tableReadDelayStdMs > 0.0))
      o << "  (the table read delay's uncertainty is not stated, 0 ms: U holds the fit's share only; give it with "
           "--read-delay-std-ms or in the bench constants)\n";
    for (const auto& left : r.leftOut)
      o << "  left out: test point " << left.index + 1 << " (" << fmt(left.frequencyHz, 5) << " Hz): " << left.reason
        << "\n";
    for (std::size_t i = 0; i < r.models.size(); ++i) {
      const auto& m = r.models[i];
      o << "  model " << responseModelName(m.kind) << (static_cast<int>(i) == r.chosen ? " (chosen)" : "")
        << ": chi2 " << fmt(m.chiSquare, 5) << " / " << m.dof << " dof, AIC " << fmt(m.aic, 6) << ", BIC "
        << fmt(m.bic, 6) << "\n";
      o << "    fit: p = " << fmt(m.pValue, 3) << (m.adequate ? " (adequate: p >= " : " (NOT ADEQUATE: p below ")
        << fmt(kModelAdequacyP, 3) << ")\n";
      for (const auto& why : m.inadmissible) o << "    NOT ADMISSIBLE: " << why << "\n";
      for (const auto& p : m.parameters)
        o << "    " << p.name << " = " << fmtToUncertainty(p.value, p.stdDev) << " ± " << fmt(p.stdDev, 2) << "\n";
      for (int a = 0; a < m.correlation.rows(); ++a)
        for (int b = a + 1; b < m.correlation.cols(); ++b)
          o << "    corr(" << m.parameters[a].name << ", " << m.parameters[b].name << ") = "
            << fmt(m.correlation(a, b), 3) << "\n";
      o << "    low-frequency delay " << fmt(m.lowFrequencyDelayMs.value, 6) << " ± "
        << fmt(m.lowFrequencyDelayMs.stdDev, 2) << " ms; group delay at " << fmt(r.groupDelayAtHz, 4) << " Hz "
        << fmt(m.groupDelayMs.value, 6) << " ± " << fmt(m.groupDelayMs.stdDev, 2) << " ms\n";
      if (m.bandwidthHz)
        o << "    -3 dB bandwidth " << fmtToUncertainty(m.bandwidthHz->value, m.bandwidthHz->stdDev, 5) << " ± " << fmt(m.bandwidthHz->stdDev, 2) << " Hz\n";
      else
        o << "    -3 dB bandwidth: none (a pure delay keeps its magnitude)\n";
      for (const auto& n : m.notes) o << "    note: " << n << "\n";
    }
    for (const auto& s : r.skipped) o << "  model left out: " << s << "\n";
    if (r.chosen < 0) o << "  " << r.noModelReason << "\n  (no model is chosen: the points above are the response)\n";
  }
  return o.str();
}

std::string formatResponseJson(const std::vector<ResponseAnalysis>& responses) {
  using nlohmann::json;
  json doc;
  doc["responses"] = json::array();
  for (const auto& r : responses) {
    json axis;
    axis["axis"] = axisName(r.axis);
    axis["group_delay_at_hz"] = r.groupDelayAtHz;
    axis["points"] = json::array();
    axis["table_read_delay_ms"] = r.tableReadDelayMs;
    axis["table_read_delay_std_ms"] = r.tableReadDelayStdMs;
    axis["coverage_factor"] = kResponseCoverageK;
    for (const auto& p : r.points) {
      const CertifiedPhase c = certifiedPhase(p, r);
      axis["points"].push_back({{"test_point", p.index + 1},
                                {"frequency_hz", p.frequencyHz},
                                {"magnitude", p.magnitude},
                                {"magnitude_std", p.magnitudeStd},
                                {"magnitude_db", p.magnitudeDb},
                                {"magnitude_db_std", p.magnitudeDbStd},
                                {"phase_deg", p.phaseDeg},
                                {"phase_std_deg", p.phaseStdDeg},
                                {"lag_ms", p.lagMs},
                                {"lag_std_ms", p.lagStdMs},
                                {"magnitude_phase_cov_deg", p.magnitudePhaseCovDeg},
                                {"harmonic_fraction", p.harmonicFraction},
                                {"phase_vs_table_motion_deg", c.phaseDeg},
                                {"phase_standard_uncertainty_deg", c.standardDeg},
                                {"phase_read_delay_std_deg", c.readDelayStdDeg},
                                {"coverage_factor", c.coverageK},
                                {"phase_expanded_uncertainty_deg", c.expandedDeg},
                                {"phase_expanded_uncertainty_ms", c.expandedMs}});
    }
    axis["left_out"] = json::array();
    for (const auto& left : r.leftOut)
      axis["left_out"].push_back(
          {{"test_point", left.index + 1}, {"frequency_hz", left.frequencyHz}, {"reason", left.reason}});
    axis["models"] = json::array();
    for (const auto& m : r.models) {
      json model{{"model", responseModelName(m.kind)},
                 {"chi_square", m.chiSquare},
                 {"dof", m.dof},
                 {"aic", m.aic},
                 {"bic", m.bic},
                 {"low_frequency_delay_ms", m.lowFrequencyDelayMs.value},
                 {"low_frequency_delay_std_ms", m.lowFrequencyDelayMs.stdDev},
                 {"group_delay_ms", m.groupDelayMs.value},
                 {"group_delay_std_ms", m.groupDelayMs.stdDev},
                 {"notes", m.notes},
                 {"p_value", m.pValue},
                 {"adequate", m.adequate},
                 {"admissible", m.admissible()},
                 {"inadmissible", m.inadmissible}};
      model["bandwidth_hz"] = m.bandwidthHz ? json(m.bandwidthHz->value) : json(nullptr);
      model["bandwidth_std_hz"] = m.bandwidthHz ? json(m.bandwidthHz->stdDev) : json(nullptr);
      json params = json::object();
      for (const auto& p : m.parameters) params[p.name] = {{"value", p.value}, {"std", p.stdDev}};
      model["parameters"] = params;
      json corr = json::array();
      for (int a = 0; a < m.correlation.rows(); ++a) {
        json row = json::array();
        for (int b = 0; b < m.correlation.cols(); ++b) row.push_back(m.correlation(a, b));
        corr.push_back(row);
      }
      model["correlation"] = corr;
      axis["models"].push_back(model);
    }
    axis["chosen_model"] = r.chosen >= 0 ? json(responseModelName(r.models[r.chosen].kind)) : json(nullptr);
    axis["no_model_reason"] = r.chosen >= 0 ? json(nullptr) : json(r.noModelReason);
    axis["adequacy_p_threshold"] = kModelAdequacyP;
    axis["skipped_models"] = r.skipped;
    doc["responses"].push_back(axis);
  }
  return doc.dump(2);
}

}  // namespace fog::analysis
