#include "core/noise/noise_terms.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fog::noise {

namespace {

constexpr double kFlickerFactor = 2.0 * std::numbers::ln2 / std::numbers::pi;  // B^2 -> Allan variance

// Noise type of a local log-log slope mu of the Allan variance (tau^mu).
PowerLawNoise noiseOfSlope(double mu) {
  if (mu <= -1.5) return PowerLawNoise::kWhitePhase;
  if (mu <= -0.5) return PowerLawNoise::kWhiteFrequency;
  if (mu <= 0.5) return PowerLawNoise::kFlickerFrequency;
  return PowerLawNoise::kRandomWalkFrequency;
}

struct Fit {
  std::vector<int> active;            // term kinds in the fit
  Eigen::VectorXd coefficient;        // value^2 per active term
  Eigen::MatrixXd covariance;         // of the coefficients
  Eigen::VectorXd logStd;             // standard error of ln(coefficient)
  double chiSquare = std::numeric_limits<double>::infinity();
  int dof = 0;
  double tcS = 0.0;
  double logTcStd = 0.0;              // standard error of ln(Tc) when Tc is free
  PulseQuantisation pulse;            // the curve's; shapes the quantisation term
  double tau0S = 0.0;
  bool ok = false;
  // Levenberg-Marquardt stopped because no step lowers the cost by more
  // than 1e-10 (relative) or none lowers it at all, not at the iteration
  // limit.
  bool converged = false;
};

bool pulseShaped(const PulseQuantisation& pq, double tau0S) { return pq.pulseDeg > 0.0 && tau0S > 0.0; }

// Unit Allan variance of the quantisation term: of the pulse quantisation of
// the angle, dithered by the other terms (coefficient = value^2 of each), or
// white (3 / tau^2) when the pulse is unknown.
template <typename Terms, typename Coefficients>
double quantisationShape(const PulseQuantisation& pq, double tau0S, const Terms& terms, const Coefficients& coefficient,
                         double tcS, double tau) {
  if (!pulseShaped(pq, tau0S)) return unitAllanVariance(NoiseTermKind::kQuantisation, tau);
  double v1 = 0.0, v2 = 0.0;
  for (std::size_t j = 0; j < terms.size(); ++j) {
    const auto kind = static_cast<NoiseTermKind>(terms[j]);
    if (kind == NoiseTermKind::kQuantisation) continue;
    const double c = coefficient[static_cast<Eigen::Index>(j)];
    v1 += c * unitAngleVariance(kind, tau, tcS);
    v2 += c * unitAngleVariance(kind, 2.0 * tau, tcS);
  }
  const double p2 = pq.pulseDeg * pq.pulseDeg;
  return pulseQuantisationUnitVariance(tau, tau0S, pq.stepDeg / pq.pulseDeg, v1 / p2, v2 / p2);
}

double termUnit(const Fit& f, std::size_t j, double tau) {
  const auto kind = static_cast<NoiseTermKind>(f.active[j]);
  if (kind == NoiseTermKind::kQuantisation) return quantisationShape(f.pulse, f.tau0S, f.active, f.coefficient, f.tcS, tau);
  return unitAllanVariance(kind, tau, f.tcS);
}

double modelAt(const Fit& f, double tau) {
  double v = 0.0;
  for (std::size_t j = 0; j < f.active.size(); ++j) v += f.coefficient[static_cast<Eigen::Index>(j)] * termUnit(f, j, tau);
  return v;
}

// Autocovariance (pulses^2) of the sawtooth frac(u) - 1/2 at a mean shift d
// with a Gaussian jitter of variance v of the shift.
double sawtoothCovariance(double d, double v) {
  d -= std::floor(d);
  const double s = std::sqrt(std::max(v, 0.0));
  if (s < 1e-9) return 1.0 / 12.0 - 0.5 * d * (1.0 - d);
  constexpr double kPi = std::numbers::pi;
  if (s >= 0.15) {  // Fourier series: sum cos(2 pi k d) e^(-2 pi^2 k^2 v) / (2 pi^2 k^2)
    double r = 0.0;
    for (int k = 1; k < 64; ++k) {
      const double damp = std::exp(-2.0 * kPi * kPi * k * k * v);
      if (damp < 1e-17) break;
      r += std::cos(2.0 * kPi * k * d) * damp / (2.0 * kPi * kPi * k * k);
    }
    return r;
  }
  // Narrow jitter: the Gaussian expectation of the quadratic on each period.
  auto cdf = [](double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); };
  auto pdf = [](double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * kPi); };
  double r = 0.0;
  for (double j = std::floor(d - 10.0 * s); j <= std::floor(d + 10.0 * s); j += 1.0) {
    const double dj = d - j, za = -dj / s, zb = (1.0 - dj) / s;
    const double m0 = cdf(zb) - cdf(za), pa = pdf(za), pb = pdf(zb);
    const double m1 = dj * m0 + s * (pa - pb);
    const double m2 = dj * dj * m0 + 2.0 * dj * s * (pa - pb) + v * (m0 + za * pa - zb * pb);
    r += m0 / 12.0 - 0.5 * (m1 - m2);
  }
  return r;
}

double modelSlope(const Fit& f, double tau) {
  const double a = modelAt(f, tau / 1.05), b = modelAt(f, tau * 1.05);
  return a > 0.0 && b > 0.0 ? std::log(b / a) / std::log(1.05 * 1.05) : 0.0;
}

// Start for the logarithmic fit: non-negative linear least squares of the
// variances weighted by the measured ones (convex, so no local minima;
// dropping the most negative coefficient until none is left is enough for
// six terms). A term the linear fit drops starts at 1e-3 of the curve where
// it comes closest, so that the logarithmic fit can still raise it.
Eigen::VectorXd linearStart(const AllanCurve& curve, const std::vector<int>& terms, double tcS) {
  const auto n = static_cast<Eigen::Index>(curve.points.size());
  const auto k = static_cast<Eigen::Index>(terms.size());
  Eigen::MatrixXd a(n, k);
  Eigen::VectorXd avar(n), sw(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& pt = curve.points[static_cast<std::size_t>(i)];
    avar[i] = pt.deviation * pt.deviation;
    sw[i] = std::sqrt(pt.edf / 2.0) / std::max(avar[i], 1e-300);
    for (Eigen::Index j = 0; j < k; ++j)
      a(i, j) = unitAllanVariance(static_cast<NoiseTermKind>(terms[static_cast<std::size_t>(j)]), pt.tauS, tcS);
  }
  Eigen::VectorXd c = Eigen::VectorXd::Zero(k);
  std::vector<Eigen::Index> active(static_cast<std::size_t>(k));
  for (Eigen::Index j = 0; j < k; ++j) active[static_cast<std::size_t>(j)] = j;
  while (!active.empty()) {
    const auto m = static_cast<Eigen::Index>(active.size());
    Eigen::MatrixXd aw(n, m);
    for (Eigen::Index j = 0; j < m; ++j) aw.col(j) = sw.cwiseProduct(a.col(active[static_cast<std::size_t>(j)]));
    Eigen::VectorXd scale = aw.colwise().norm().transpose();
    for (Eigen::Index j = 0; j < m; ++j)
      if (!(scale[j] > 0.0)) scale[j] = 1.0;
    aw = aw * scale.cwiseInverse().asDiagonal();
    const Eigen::VectorXd z = aw.colPivHouseholderQr().solve(sw.cwiseProduct(avar)).cwiseQuotient(scale);
    Eigen::Index worst = 0;
    if (z.allFinite() && z.minCoeff(&worst) >= 0.0) {
      for (Eigen::Index j = 0; j < m; ++j) c[active[static_cast<std::size_t>(j)]] = z[j];
      break;
    }
    if (!z.allFinite()) worst = m - 1;
    active.erase(active.begin() + worst);
  }
  Eigen::VectorXd p(k);
  for (Eigen::Index j = 0; j < k; ++j) {
    double room = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < n; ++i) room = std::min(room, avar[i] / a(i, j));
    p[j] = std::log(c[j] > 1e-3 * room ? c[j] : 1e-3 * room);
  }
  return p;
}

// Weighted least squares in the logarithm: r_i = sqrt(edf_i / 2) (ln avar_i +
// bias_i - ln model_i), since var(ln avar) = 2 / edf for a chi-squared
// estimate and E[ln avar] = ln sigma^2 - 1/edf - 1/(3 edf^2) to second order
// (the bias is added back). Parameters are ln(coefficient) (so every term
// stays >= 0) and, with a Markov term and freeTc, ln(Tc). Levenberg-Marquardt
// from a start that puts each term at a tenth of the curve where it fits best.
Fit solve(const AllanCurve& curve, const std::vector<int>& terms, double tcS, bool freeTc,
          const Eigen::VectorXd* start = nullptr, int maxIterations = IdentifyOptions{}.maxIterations) {
  const auto n = static_cast<Eigen::Index>(curve.points.size());
  const auto k = static_cast<Eigen::Index>(terms.size());
  const bool markov = std::find(terms.begin(), terms.end(), static_cast<int>(NoiseTermKind::kMarkov)) != terms.end();
  const bool tcFree = markov && freeTc;
  const Eigen::Index np = k + (tcFree ? 1 : 0);
  Fit fit;
  fit.active = terms;
  fit.tcS = markov ? tcS : 0.0;
  fit.pulse = curve.pulse;
  fit.tau0S = curve.tau0S;
  if (k == 0 || n <= np) return fit;
  const bool shaped = pulseShaped(curve.pulse, curve.tau0S);
  // The pulse-quantisation shape depends on the other terms (they dither the
  // angle): it is held fixed within a pass and recomputed between passes.
  Eigen::VectorXd qShape(n);
  auto updateShape = [&](const Eigen::VectorXd& q) {
    const Eigen::VectorXd c = q.head(k).array().exp().matrix();
    const double tc = tcFree ? std::exp(q[k]) : fit.tcS;
    for (Eigen::Index i = 0; i < n; ++i)
      qShape[i] = quantisationShape(curve.pulse, curve.tau0S, terms, c, tc, curve.points[static_cast<std::size_t>(i)].tauS);
  };

  Eigen::VectorXd tau(n), logAvar(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& p = curve.points[static_cast<std::size_t>(i)];
    tau[i] = p.tauS;
    logAvar[i] = 2.0 * std::log(std::max(p.deviation, 1e-300));
  }
  std::vector<PowerLawNoise> noise(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) noise[static_cast<std::size_t>(i)] = curve.points[static_cast<std::size_t>(i)].noise;

  Eigen::VectorXd p(np);
  if (start && start->size() == k) {
    p.head(k) = *start;
  } else {
    p.head(k) = linearStart(curve, terms, fit.tcS);
  }
  if (tcFree) p[k] = std::log(fit.tcS);

  auto evaluate = [&](const Eigen::VectorXd& q, Eigen::VectorXd& r, Eigen::MatrixXd* jac, const Eigen::VectorXd& w,
                      const Eigen::VectorXd& target) {
    const double tc = tcFree ? std::exp(q[k]) : fit.tcS;
    for (Eigen::Index i = 0; i < n; ++i) {
      double model = 0.0;
      double dTc = 0.0;
      Eigen::VectorXd parts(k);
      for (Eigen::Index j = 0; j < k; ++j) {
        const auto kind = static_cast<NoiseTermKind>(terms[static_cast<std::size_t>(j)]);
        parts[j] = std::exp(q[j]) * (kind == NoiseTermKind::kQuantisation && shaped ? qShape[i]
                                                                                    : unitAllanVariance(kind, tau[i], tc));
        model += parts[j];
        if (tcFree && kind == NoiseTermKind::kMarkov) {
          const double h = 1e-4;
          dTc = std::exp(q[j]) * (unitAllanVariance(kind, tau[i], tc * std::exp(h)) -
                                  unitAllanVariance(kind, tau[i], tc * std::exp(-h))) / (2.0 * h);
        }
      }
      model = std::max(model, 1e-300);
      r[i] = w[i] * (target[i] - std::log(model));
      if (jac) {
        for (Eigen::Index j = 0; j < k; ++j) (*jac)(i, j) = -w[i] * parts[j] / model;
        if (tcFree) (*jac)(i, k) = -w[i] * dTc / model;
      }
    }
  };

  Eigen::VectorXd r(n);
  Eigen::MatrixXd jac(n, np);
  const int passes = shaped ? 8 : 3;
  for (int outer = 0; outer < passes; ++outer) {
    updateShape(p);
    Eigen::VectorXd w(n), target(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double edf = edfOverlappingAllan(curve.phasePoints, curve.points[static_cast<std::size_t>(i)].m,
                                             noise[static_cast<std::size_t>(i)]);
      w[i] = std::sqrt(edf / 2.0);
      target[i] = logAvar[i] + 1.0 / edf + 1.0 / (3.0 * edf * edf);
    }
    double lambda = 1e-3;
    evaluate(p, r, &jac, w, target);
    double cost = r.squaredNorm();
    fit.converged = false;
    for (int it = 0; it < maxIterations; ++it) {
      const Eigen::MatrixXd jtj = jac.transpose() * jac;
      const Eigen::VectorXd g = jac.transpose() * r;
      Eigen::MatrixXd a = jtj;
      a.diagonal() += lambda * (jtj.diagonal().array() + 1e-12).matrix();
      const Eigen::VectorXd step = -a.ldlt().solve(g);
      // Keep ln(Tc) inside the taus observed: the hump must be seen.
      Eigen::VectorXd q = p + step.cwiseMax(-5.0).cwiseMin(5.0);
      if (tcFree) q[k] = std::clamp(q[k], std::log(tau[0]), std::log(tau[n - 1]));
      Eigen::VectorXd rq(n);
      evaluate(q, rq, nullptr, w, target);
      const double newCost = rq.squaredNorm();
      if (newCost < cost) {
        const bool small = cost - newCost < 1e-10 * (1.0 + cost);
        p = q;
        cost = newCost;
        evaluate(p, r, &jac, w, target);
        lambda = std::max(lambda * 0.3, 1e-12);
        if (small) {
          fit.converged = true;
          break;
        }
      } else {
        lambda *= 10.0;
        if (lambda > 1e12) {
          fit.converged = true;
          break;
        }
      }
    }
    fit.chiSquare = cost;
    fit.tcS = tcFree ? std::exp(p[k]) : fit.tcS;
    fit.coefficient = p.head(k).array().exp().matrix();
    for (Eigen::Index i = 0; i < n; ++i) noise[static_cast<std::size_t>(i)] = noiseOfSlope(modelSlope(fit, tau[i]));
  }
  fit.dof = static_cast<int>(n - np);
  const Eigen::MatrixXd jtj = jac.transpose() * jac;
  const Eigen::MatrixXd covP = jtj.completeOrthogonalDecomposition().pseudoInverse();
  fit.logStd = covP.diagonal().head(k).cwiseMax(0.0).cwiseSqrt();
  fit.covariance = fit.coefficient.asDiagonal() * covP.topLeftCorner(k, k) * fit.coefficient.asDiagonal();
  fit.logTcStd = tcFree ? std::sqrt(std::max(0.0, covP(k, k))) : 0.0;
  fit.ok = fit.coefficient.allFinite() && std::isfinite(fit.chiSquare);
  return fit;
}

std::vector<double> markovGrid(const AllanCurve& curve) {
  std::vector<double> grid;
  if (curve.points.size() < 3) return grid;
  // Tc from 2 tau_min to tau_max / 2: only there does the hump show.
  const double lo = 2.0 * curve.points.front().tauS, hi = 0.5 * curve.points.back().tauS;
  for (double t = lo; t <= hi; t *= std::pow(10.0, 1.0 / 10.0)) grid.push_back(t);
  return grid;
}

bool hasMarkov(const std::vector<int>& terms) {
  return std::find(terms.begin(), terms.end(), static_cast<int>(NoiseTermKind::kMarkov)) != terms.end();
}

// With a Markov term: the best correlation time on the grid, then refined
// with Tc free.
Fit best(const AllanCurve& curve, const std::vector<int>& terms, const std::vector<double>& grid,
         int maxIterations) {
  if (!hasMarkov(terms)) return solve(curve, terms, 0.0, false, nullptr, maxIterations);
  Fit bestFit;
  for (double tc : grid) {
    Fit f = solve(curve, terms, tc, false, nullptr, maxIterations);
    if (f.ok && f.chiSquare < bestFit.chiSquare) bestFit = std::move(f);
  }
  if (!bestFit.ok) return bestFit;
  const Eigen::VectorXd start = bestFit.coefficient.array().log().matrix();
  Fit refined = solve(curve, terms, bestFit.tcS, true, &start, maxIterations);
  return refined.ok && refined.chiSquare <= bestFit.chiSquare ? refined : bestFit;
}

double inflation(const Fit& f) { return std::max(1.0, f.dof > 0 ? f.chiSquare / f.dof : 1.0); }

double significanceOf(const Fit& f, std::size_t j) {
  const double s = f.logStd[static_cast<Eigen::Index>(j)] * std::sqrt(inflation(f));
  return s > 0.0 ? 1.0 / s : 0.0;
}

// Per tau with replicates: the factor (>= 1) by which its replicates'
// deviations from the full variance are stretched (in the logarithm) so
// that their spread is at least the model's 2 / EDF. Only where a second
// difference spans more than a jackknife block (2 m blocks > record): there
// the blocks' data are shared by so many differences that the replicates
// cannot see the variance -- in a 250-seed Monte Carlo their spread was
// 0.45-0.65 of the scatter of ln(avar) beyond tau = T/20, while 2 / EDF was
// 0.91-1.00 of it beyond T/10 (docs/noise.md). Shorter taus keep the
// jackknife's own spread (within 0.89-1.22 of the scatter), which also
// holds when the model is wrong.
std::vector<double> replicateStretch(const AllanCurve& curve, const Fit& fit, std::size_t blocks) {
  std::vector<double> stretch;
  for (const auto& p : curve.points) {
    if (p.jackknifeVariance.empty()) continue;
    const bool spans = 2.0 * static_cast<double>(p.m) * static_cast<double>(blocks) > static_cast<double>(curve.phasePoints);
    const double full = p.deviation * p.deviation;
    double squares = 0.0;
    for (double v : p.jackknifeVariance) squares += std::pow(std::log(std::max(v, 1e-300) / full), 2);
    const double spread = squares * static_cast<double>(blocks - 1) / static_cast<double>(blocks);
    const double modelSpread = 2.0 / edfOverlappingAllan(curve.phasePoints, p.m, noiseOfSlope(modelSlope(fit, p.tauS)));
    stretch.push_back(spans && spread > 0.0 ? std::max(1.0, std::sqrt(modelSpread / spread)) : 1.0);
  }
  return stretch;
}

// Delete-a-block jackknife of the term values (and Tc): refit each replicate
// curve with the same terms, starting from the full fit.
void jackknife(const AllanCurve& curve, const Fit& fit, NoiseModel& model) {
  std::size_t blocks = curve.points.empty() ? 0 : curve.points.front().jackknifeVariance.size();
  for (const auto& p : curve.points) blocks = std::min(blocks, p.jackknifeVariance.size());
  if (blocks < 2) return;
  // Taus without replicates (too few differences) are left out of every replicate.
  AllanCurve replicate = curve;
  std::erase_if(replicate.points, [](const AllanPoint& p) { return p.jackknifeVariance.empty(); });
  if (replicate.points.size() <= fit.active.size() + 1) return;
  const bool markov = hasMarkov(fit.active);
  const Eigen::VectorXd start = fit.coefficient.array().log().matrix();
  const std::size_t k = fit.active.size();
  std::vector<std::vector<double>> values(k + 1);
  const std::vector<double> stretch = replicateStretch(curve, fit, blocks);
  for (std::size_t b = 0; b < blocks; ++b) {
    std::size_t i = 0;
    for (const auto& p : curve.points) {
      if (p.jackknifeVariance.empty()) continue;
      const double full = p.deviation * p.deviation;
      const double logRatio = std::log(std::max(p.jackknifeVariance[b], 1e-300) / full);
      replicate.points[i].deviation = std::sqrt(full * std::exp(stretch[i] * logRatio));
      ++i;
    }
    if (b < curve.jackknifeStepChange.size()) replicate.pulse.stepDeg = curve.pulse.stepDeg + curve.jackknifeStepChange[b];
    const Fit f = solve(replicate, fit.active, fit.tcS, markov, &start);
    if (!f.ok) continue;
    for (std::size_t j = 0; j < k; ++j) values[j].push_back(std::sqrt(f.coefficient[static_cast<Eigen::Index>(j)]));
    values[k].push_back(std::log(f.tcS > 0.0 ? f.tcS : 1.0));
  }
  if (values[0].size() < 2) return;
  auto spread = [](const std::vector<double>& v) {
    double mean = 0.0;
    for (double x : v) mean += x;
    mean /= static_cast<double>(v.size());
    double ss = 0.0;
    for (double x : v) ss += (x - mean) * (x - mean);
    return std::sqrt(ss * static_cast<double>(v.size() - 1) / static_cast<double>(v.size()));
  };
  for (std::size_t j = 0; j < k; ++j) {
    NoiseTerm& t = model.terms[j];
    t.stdError = spread(values[j]);
    // Significance of the variance coefficient value^2: value / (2 std).
    t.significance = t.stdError > 0.0 ? t.value / (2.0 * t.stdError) : t.significance;
    if (t.kind == NoiseTermKind::kMarkov) {
      const double s = spread(values[k]);
      t.correlationTimeLowS = t.correlationTimeS * std::exp(-s);
      t.correlationTimeHighS = t.correlationTimeS * std::exp(s);
    }
  }
}

// The overlapping Allan variance at averaging factor m and its
// delete-a-block jackknife replicates, in one pass: the record's increments are cut into
// `blocks` blocks and block b's data are left out -- every second
// difference that uses an increment of the block, i.e. those starting up to
// 2m - 1 before it too. Leaving out only the differences that start in the
// block (as a jackknife of independent blocks would) keeps the overlapping
// ones, so neighbouring blocks' sums are correlated once 2 tau nears the
// block length, and the replicates' spread understated the scatter of the
// long-tau variances by up to 5x (a 250-seed Monte Carlo, docs/noise.md).
// A replicate that leaves out l_b of the n differences spreads by
// (n - l_b) / l_b per unit of the variance of the estimate (delete-l
// jackknife of dependent data, l beyond the dependence); it is returned
// rescaled, v + c_b (v_b - v) with c_b^2 = (n - l_b) / (l_b (blocks - 1)),
// so that the ordinary delete-1-of-`blocks` formula applies to every tau
// alike (c_b = 1 when l_b = n / blocks). Each replicate then stands for the
// same data left out at every tau, which keeps their correlation across
// taus for the refit.
struct BlockedAllanVariance {
  double variance = 0.0;
  std::vector<double> replicates;
};
BlockedAllanVariance allanVarianceInBlocks(std::span<const double> phase, double tau0S, std::size_t m, std::size_t blocks) {
  const std::size_t increments = phase.size() - 1, count = phase.size() - 2 * m;
  // Starts of the differences left out with block b: [lo_b, hi_b).
  std::vector<std::size_t> lo(blocks), hi(blocks), cuts = {0, count};
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t first = increments * b / blocks, end = increments * (b + 1) / blocks;
    lo[b] = first + 1 > 2 * m ? std::min(first + 1 - 2 * m, count) : 0;
    hi[b] = std::min(end, count);
    cuts.push_back(lo[b]);
    cuts.push_back(hi[b]);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  // Sum of the squared second differences (as variance x count) before each cut.
  std::vector<double> before(cuts.size(), 0.0);
  for (std::size_t c = 1; c < cuts.size(); ++c) {
    const std::size_t n = cuts[c] - cuts[c - 1];
    std::size_t used = 0;
    const double v = allanVariance(phase.subspan(cuts[c - 1], n + 2 * m), tau0S, m, true, &used);
    before[c] = before[c - 1] + v * static_cast<double>(used);
  }
  auto sumBefore = [&](std::size_t at) {
    return before[static_cast<std::size_t>(std::lower_bound(cuts.begin(), cuts.end(), at) - cuts.begin())];
  };
  BlockedAllanVariance result;
  const double full = result.variance = before.back() / static_cast<double>(count);
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t left = hi[b] - lo[b];
    if (left == 0 || left >= count) {  // nothing or everything left out: no spread to take
      result.replicates.push_back(full);
      continue;
    }
    const double v = (before.back() - (sumBefore(hi[b]) - sumBefore(lo[b]))) / static_cast<double>(count - left);
    const double c = std::sqrt(static_cast<double>(count - left) /
                               (static_cast<double>(left) * static_cast<double>(blocks - 1)));
    result.replicates.push_back(full + c * (v - full));
  }
  return result;
}

}  // namespace

const char* noiseTermName(NoiseTermKind kind) {
  switch (kind) {
    case NoiseTermKind::kQuantisation: return "quantisation";
    case NoiseTermKind::kAngleRandomWalk: return "angle random walk";
    case NoiseTermKind::kBiasInstability: return "bias instability";
    case NoiseTermKind::kRateRandomWalk: return "rate random walk";
    case NoiseTermKind::kRateRamp: return "rate ramp";
    case NoiseTermKind::kMarkov: return "Markov (correlated) rate";
  }
  return "?";
}

const char* noiseTermKey(NoiseTermKind kind) {
  switch (kind) {
    case NoiseTermKind::kQuantisation: return "quantisation";
    case NoiseTermKind::kAngleRandomWalk: return "angle_random_walk";
    case NoiseTermKind::kBiasInstability: return "bias_instability";
    case NoiseTermKind::kRateRandomWalk: return "rate_random_walk";
    case NoiseTermKind::kRateRamp: return "rate_ramp";
    case NoiseTermKind::kMarkov: return "markov";
  }
  return "?";
}

double unitAllanVariance(NoiseTermKind kind, double tau, double tc) {
  switch (kind) {
    case NoiseTermKind::kQuantisation: return 3.0 / (tau * tau);
    case NoiseTermKind::kAngleRandomWalk: return 1.0 / tau;
    case NoiseTermKind::kBiasInstability: return kFlickerFactor;
    case NoiseTermKind::kRateRandomWalk: return tau / 3.0;
    case NoiseTermKind::kRateRamp: return 0.5 * tau * tau;
    case NoiseTermKind::kMarkov: {
      if (!(tc > 0.0)) return 0.0;
      const double x = tau / tc;
      // Below x = 1e-3 the bracket cancels to x^2/3 - x^3/4 (series).
      const double bracket = x < 1e-3 ? x * x / 3.0 - x * x * x / 4.0
                                      : 1.0 - (3.0 - 4.0 * std::exp(-x) + std::exp(-2.0 * x)) / (2.0 * x);
      return 2.0 * bracket / x;
    }
  }
  return 0.0;
}

double NoiseModel::allanVariance(double tauS) const {
  std::vector<int> kinds;
  Eigen::VectorXd c(static_cast<Eigen::Index>(terms.size()));
  double tc = 0.0;
  for (const auto& t : terms) {
    c[static_cast<Eigen::Index>(kinds.size())] = t.value * t.value;
    kinds.push_back(static_cast<int>(t.kind));
    if (t.kind == NoiseTermKind::kMarkov) tc = t.correlationTimeS;
  }
  double v = 0.0;
  for (const auto& t : terms)
    v += t.value * t.value *
         (t.kind == NoiseTermKind::kQuantisation ? quantisationShape(pulse, tau0S, kinds, c, tc, tauS)
                                                 : unitAllanVariance(t.kind, tauS, t.correlationTimeS));
  return v;
}

double pulseQuantisationUnitVariance(double tauS, double tau0S, double step, double jitter1, double jitter2) {
  const double m = tauS / tau0S;
  const double r1 = sawtoothCovariance(step * m, jitter1), r2 = sawtoothCovariance(step * 2.0 * m, jitter2);
  return 12.0 * (3.0 / 12.0 - 4.0 * r1 + r2) / (tauS * tauS);
}

double unitAngleVariance(NoiseTermKind kind, double lag, double tc) {
  switch (kind) {
    case NoiseTermKind::kAngleRandomWalk: return lag;
    case NoiseTermKind::kRateRandomWalk: return lag * lag * lag / 3.0;
    case NoiseTermKind::kBiasInstability: return kFlickerFactor * lag * lag;
    case NoiseTermKind::kMarkov: {
      if (!(tc > 0.0)) return 0.0;
      const double x = lag / tc;
      const double g = x < 1e-4 ? x * x / 2.0 - x * x * x / 6.0 : x - 1.0 + std::exp(-x);
      return 2.0 * tc * tc * g;
    }
    case NoiseTermKind::kQuantisation:
    case NoiseTermKind::kRateRamp: return 0.0;
  }
  return 0.0;
}

const NoiseTerm* NoiseModel::find(NoiseTermKind kind) const {
  for (const auto& t : terms)
    if (t.kind == kind) return &t;
  return nullptr;
}

Result<AllanCurve> overlappingAllanCurve(std::span<const double> phase, double tau0S, const AllanOptions& options) {
  if (phase.size() < 8) return insufficientData("an Allan deviation needs at least 8 samples, got " + std::to_string(phase.size()));
  if (!(tau0S > 0.0)) return invalidArgument("the sample interval must be > 0 s");
  if (!(options.confidence > 0.0 && options.confidence < 1.0))
    return invalidArgument("the confidence level must be within (0, 1)");
  AllanCurve curve;
  curve.tau0S = tau0S;
  curve.phasePoints = phase.size();
  curve.confidence = options.confidence;
  if (options.jackknifeBlocks >= 2 && phase.size() >= static_cast<std::size_t>(4 * options.jackknifeBlocks)) {
    // The mean step of the record without block b (phase index blocks).
    const auto blocks = static_cast<std::size_t>(options.jackknifeBlocks);
    const std::size_t last = phase.size() - 1;
    const double total = phase[last] - phase[0];
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t lo = last * b / blocks, hi = last * (b + 1) / blocks;
      const double rest = static_cast<double>(last - (hi - lo));
      curve.jackknifeStepChange.push_back((total - (phase[hi] - phase[lo])) / rest - total / static_cast<double>(last));
    }
  }
  for (std::size_t m : averagingFactors(phase.size(), options.tausPerOctave, options.maxTauFraction)) {
    AllanPoint p;
    p.m = m;
    p.tauS = static_cast<double>(m) * tau0S;
    const int blocks = options.jackknifeBlocks;
    const std::size_t count = phase.size() - 2 * m;
    if (blocks < 2 || count < static_cast<std::size_t>(4 * blocks)) {
      p.deviation = std::sqrt(allanVariance(phase, tau0S, m, true, &p.differences));
    } else {
      auto blocked = allanVarianceInBlocks(phase, tau0S, m, static_cast<std::size_t>(blocks));
      p.differences = count;
      p.deviation = std::sqrt(blocked.variance);
      p.jackknifeVariance = std::move(blocked.replicates);
    }
    curve.points.push_back(p);
  }
  // First guess of each point's noise type: the local slope of the curve.
  const std::size_t n = curve.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 < n ? i + 1 : i;
    double mu = -1.0;
    if (b > a && curve.points[a].deviation > 0.0 && curve.points[b].deviation > 0.0)
      mu = 2.0 * std::log(curve.points[b].deviation / curve.points[a].deviation) /
           std::log(curve.points[b].tauS / curve.points[a].tauS);
    auto& p = curve.points[i];
    p.noise = noiseOfSlope(mu);
    p.edf = edfOverlappingAllan(curve.phasePoints, p.m, p.noise);
    p.interval = deviationInterval(p.deviation, p.edf, curve.confidence);
  }
  return curve;
}

Result<NoiseModel> identifyNoise(AllanCurve& curve, const IdentifyOptions& options) {
  if (curve.points.size() < 3)
    return insufficientData("noise terms need an Allan curve of at least 3 taus, got " +
                            std::to_string(curve.points.size()) + "; record longer");
  std::vector<int> terms;
  for (int k = 0; k < kNoiseTermKinds; ++k) {
    if (!options.allowed[k]) continue;
    if (k == static_cast<int>(NoiseTermKind::kMarkov) && !options.allowMarkov) continue;
    terms.push_back(k);
  }
  const auto grid = markovGrid(curve);
  if (grid.empty()) std::erase(terms, static_cast<int>(NoiseTermKind::kMarkov));
  // A term that stays under 1e-3 of the model everywhere has no information;
  // then the least significant term goes, until every remaining one is
  // significant.
  Fit fit = best(curve, terms, grid, options.maxIterations);
  // A term is dropped when it carries nothing (under 1e-3 of the model at
  // every tau) or when its Wald significance is below minSignificance -- the
  // least significant first. A Markov term has two strongly correlated
  // parameters (sigma and Tc; a hump only partly inside the record), and the
  // Wald test on ln(sigma^2) alone understates it: at rest the simulator's
  // 0.5 deg/h / 300 s wander has z ~ 1.9, but dropping it raises chi^2 from
  // 9 to 530 for ~28 dof. So a Markov term is dropped only when leaving it
  // out also raises chi^2 (scaled by chi^2/dof when above 1) by less than a
  // chi-squared of 2 degrees of freedom at the same tail probability
  // (likelihood ratio). The single-parameter terms keep the Wald test: their
  // chi^2 with and without differ also by the EDFs of the noise types the
  // models assign, which would bias a likelihood-ratio test there.
  const double tail = std::erfc(options.minSignificance / std::numbers::sqrt2);
  for (;;) {
    if (!fit.ok || fit.active.size() <= 1) break;
    std::vector<std::pair<double, std::size_t>> weak;
    for (std::size_t j = 0; j < fit.active.size(); ++j) {
      double maxShare = 0.0;
      for (const auto& p : curve.points) {
        const double total = modelAt(fit, p.tauS);
        if (total > 0.0)
          maxShare = std::max(maxShare, fit.coefficient[static_cast<Eigen::Index>(j)] * termUnit(fit, j, p.tauS) / total);
      }
      const double z = maxShare < 1e-3 ? 0.0 : significanceOf(fit, j);
      if (z < options.minSignificance) weak.emplace_back(z, j);
    }
    if (weak.empty()) break;
    std::sort(weak.begin(), weak.end());
    bool dropped = false;
    for (const auto& [z, j] : weak) {
      std::vector<int> fewer = fit.active;
      fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(j));
      Fit without = best(curve, fewer, grid, options.maxIterations);
      const bool markov = fit.active[j] == static_cast<int>(NoiseTermKind::kMarkov);
      const double limit = chiSquareQuantile(1.0 - tail, 2.0) * inflation(fit);
      if (z == 0.0 || !markov || !without.ok || without.chiSquare - fit.chiSquare < limit) {
        fit = std::move(without);
        dropped = true;
        break;
      }
    }
    if (!dropped) break;
  }
  if (!fit.ok) return insufficientData("no noise term could be fitted to the Allan curve");
  if (!fit.converged)
    return Status(StatusCode::kNotConverged,
                  "the noise-term fit did not converge in " + std::to_string(options.maxIterations) +
                      " iterations; the Allan curve's terms are poorly determined: record longer or allow fewer terms");

  NoiseModel model;
  model.chiSquare = fit.chiSquare;
  model.dof = fit.dof;
  model.tau0S = curve.tau0S;
  model.pulse = curve.pulse;
  const double inflate = std::sqrt(inflation(fit));
  for (std::size_t j = 0; j < fit.active.size(); ++j) {
    const auto jj = static_cast<Eigen::Index>(j);
    const double c = fit.coefficient[jj];
    NoiseTerm t;
    t.kind = static_cast<NoiseTermKind>(fit.active[j]);
    t.value = std::sqrt(c);
    t.stdError = 0.5 * t.value * fit.logStd[jj] * inflate;
    t.significance = significanceOf(fit, j);
    if (t.kind == NoiseTermKind::kMarkov) {
      t.correlationTimeS = fit.tcS;
      t.correlationTimeLowS = fit.tcS * std::exp(-fit.logTcStd * inflate);
      t.correlationTimeHighS = fit.tcS * std::exp(fit.logTcStd * inflate);
    }
    // Where the term carries the model: share >= 1/3, else its best tau.
    double bestShare = -1.0;
    bool any = false;
    for (const auto& p : curve.points) {
      const double total = modelAt(fit, p.tauS);
      const double share = total > 0.0 ? c * termUnit(fit, j, p.tauS) / total : 0.0;
      if (share >= 1.0 / 3.0) {
        if (!any) t.tauLowS = p.tauS;
        t.tauHighS = p.tauS;
        any = true;
      }
      if (!any && share > bestShare) {
        bestShare = share;
        t.tauLowS = t.tauHighS = p.tauS;
      }
    }
    model.terms.push_back(t);
  }
  jackknife(curve, fit, model);
  std::sort(model.terms.begin(), model.terms.end(),
            [](const NoiseTerm& a, const NoiseTerm& b) { return a.kind < b.kind; });
  for (auto& p : curve.points) {
    p.noise = noiseOfSlope(modelSlope(fit, p.tauS));
    p.edf = edfOverlappingAllan(curve.phasePoints, p.m, p.noise);
    p.interval = deviationInterval(p.deviation, p.edf, curve.confidence);
  }
  return model;
}

}  // namespace fog::noise
