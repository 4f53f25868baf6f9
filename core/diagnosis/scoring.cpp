// The diagnosis' scoring (diagnosis_stages.h): the linear fits, each
// effect's score, the exact refinement of the best, the model and the
// verdict.
#include "core/diagnosis/diagnosis_stages.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "core/common/parallel.h"

namespace fog::diagnosis::detail {

double chi2(const std::vector<double>& r, const std::vector<bool>& mask, bool which) {
  double s = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i)
    if (mask[i] == which) s += r[i] * r[i];
  return s;
}

namespace {
// Weighted least squares of z on the columns (already divided by sigma) over
// the rows with held == false (training) or all rows.
struct LinearFit {
  Eigen::VectorXd p, stdErr;
  bool ok = false;
};
LinearFit fitColumns(const std::vector<std::vector<double>>& cols, const std::vector<double>& z,
                     const std::vector<bool>& held, bool trainingOnly) {
  const std::size_t k = cols.size();
  Eigen::MatrixXd ata = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
  Eigen::VectorXd atz = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(k));
  std::size_t n = 0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (trainingOnly && held[i]) continue;
    ++n;
    for (std::size_t a = 0; a < k; ++a) {
      atz(static_cast<Eigen::Index>(a)) += cols[a][i] * z[i];
      for (std::size_t b = 0; b < k; ++b)
        ata(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) += cols[a][i] * cols[b][i];
    }
  }
  // A column with no signature in these rows (a misalignment term of an axis
  // the plan never swings) has no information: it stays at 0 with error 0
  // and the others are fitted without it.
  std::vector<Eigen::Index> active;
  for (std::size_t a = 0; a < k; ++a)
    if (ata(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(a)) > 0.0) active.push_back(static_cast<Eigen::Index>(a));
  LinearFit f;
  if (active.empty() || n <= active.size()) return f;
  const auto m = static_cast<Eigen::Index>(active.size());
  Eigen::MatrixXd reduced(m, m);
  Eigen::VectorXd rhs(m);
  for (Eigen::Index a = 0; a < m; ++a) {
    rhs(a) = atz(active[static_cast<std::size_t>(a)]);
    for (Eigen::Index b = 0; b < m; ++b)
      reduced(a, b) = ata(active[static_cast<std::size_t>(a)], active[static_cast<std::size_t>(b)]);
  }
  Eigen::LDLT<Eigen::MatrixXd> ldlt(reduced);
  if (ldlt.info() != Eigen::Success) return f;
  const Eigen::VectorXd p = ldlt.solve(rhs);
  const Eigen::VectorXd se = reduced.inverse().diagonal().cwiseSqrt();
  f.p = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(k));
  f.stdErr = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(k));
  for (Eigen::Index a = 0; a < m; ++a) {
    f.p(active[static_cast<std::size_t>(a)]) = p(a);
    f.stdErr(active[static_cast<std::size_t>(a)]) = se(a);
  }
  f.ok = f.p.allFinite() && f.stdErr.allFinite();
  return f;
}
}  // namespace

// Subtracts from z its least-squares fit on the columns, fitted on the
// training rows (or all rows) and applied everywhere; returns the coefficients.
Eigen::VectorXd projectOut(const std::vector<std::vector<double>>& cols, std::vector<double>& z,
                           const std::vector<bool>& held, bool trainingOnly) {
  const LinearFit f = fitColumns(cols, z, held, trainingOnly);
  if (!f.ok) return Eigen::VectorXd::Zero(static_cast<Eigen::Index>(cols.size()));
  for (std::size_t i = 0; i < z.size(); ++i)
    for (std::size_t c = 0; c < cols.size(); ++c) z[i] -= cols[c][i] * f.p(static_cast<Eigen::Index>(c));
  return f.p;
}

namespace {
// Ceres cost of a nonlinear effect: the training z-residuals of the real
// features against the replay with the effect. A replay is the whole cost of
// an evaluation, so the Jacobian is a forward difference whose replays run
// side by side (one round per iteration on two threads, instead of two
// sequential replays per parameter for a central numeric difference). Any
// change of the sensed angle re-draws the gyro's pulse quantisation (~10-20
// chi2 units of noise between any two replays), so the step must be large
// enough to stand above it. With `squared`, the variables are the squares of
// the effect's parameters: the lag acts through tau^2 once the delay is
// calibrated away, so the cost is nearly linear in them, a step of 30 % is
// still a good derivative, and a few iterations from the linear fit suffice.
class ForwardCost final : public ceres::CostFunction {
 public:
  struct Setup {
    const Replay* replay;
    EffectId id;
    std::uint64_t seed;
    const std::vector<double>* base;  // replay features without the effect (same seed)
    const Stats* stats;
    const std::vector<double>* real;
    std::vector<std::size_t> rows;    // training cells
    const std::vector<std::vector<double>>* nuisance;
    bool squared = false;
    double relativeStep = 0.03;
    std::vector<double> minStep;      // per variable
    int threads = 1;
  };
  explicit ForwardCost(Setup s) : s_(std::move(s)) {
    set_num_residuals(static_cast<int>(s_.rows.size()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(effectSpec(s_.id).parameters.size()));
  }

  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override {
    const std::size_t k = effectSpec(s_.id).parameters.size();
    const bool wantJacobian = jacobians != nullptr && jacobians[0] != nullptr;
    // Ceres costs a step first and asks for the Jacobian there only if it
    // takes the step. When the difference points fit on the idle threads,
    // they run with the cost (kept for that request): a step then costs one
    // round of replays instead of two.
    const bool withSteps = wantJacobian || static_cast<int>(k + 1) <= s_.threads;
    std::vector<std::vector<double>> points(withSteps ? k + 1 : 1, std::vector<double>(x[0], x[0] + k));
    std::vector<double> steps(k, 0.0);
    for (std::size_t j = 0; withSteps && j < k; ++j) {
      steps[j] = std::max(s_.relativeStep * std::abs(x[0][j]), s_.minStep[j]);
      points[j + 1][j] += steps[j];
    }
    // Ceres asks for the same point again (the Jacobian at a step it just
    // costed, a rejected step retried): a replay with the same seed and
    // parameters gives the same residuals, so those are kept, not re-run.
    std::vector<std::vector<double>> z(points.size());
    std::vector<std::size_t> toRun;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (auto hit = evaluated_.find(points[i]); hit != evaluated_.end()) z[i] = hit->second;
      else toRun.push_back(i);
    }
    std::vector<char> ok(toRun.size(), 0);
    parallelFor(toRun.size(), s_.threads, [&](std::size_t i) { ok[i] = residualsAt(points[toRun[i]], z[toRun[i]]); });
    if (std::find(ok.begin(), ok.end(), 0) != ok.end()) return false;
    for (std::size_t i : toRun) evaluated_.emplace(points[i], z[i]);
    for (std::size_t r = 0; r < s_.rows.size(); ++r) residuals[r] = z[0][r];
    if (wantJacobian)
      for (std::size_t r = 0; r < s_.rows.size(); ++r)
        for (std::size_t j = 0; j < k; ++j) jacobians[0][r * k + j] = (z[j + 1][r] - z[0][r]) / steps[j];
    return true;
  }

  // The effect's parameters for Ceres' variables.
  std::vector<double> parametersOf(const std::vector<double>& x) const {
    std::vector<double> p = x;
    if (s_.squared)
      for (double& v : p) v = std::sqrt(std::max(v, 0.0));
    return p;
  }

 private:
  bool residualsAt(const std::vector<double>& x, std::vector<double>& out) const {
    auto f = s_.replay->run(s_.seed, {{s_.id, parametersOf(x)}});
    if (!f || f->values.size() != s_.base->size()) return false;
    std::vector<double> z(s_.real->size());
    for (std::size_t i = 0; i < z.size(); ++i)
      z[i] = ((*s_.real)[i] - s_.stats->mean[i] - (f->values[i] - (*s_.base)[i])) /
             spreadWith(*s_.stats, i, f->values[i] - (*s_.base)[i]);
    projectOut(*s_.nuisance, z, s_.stats->held, true);
    out.resize(s_.rows.size());
    for (std::size_t r = 0; r < s_.rows.size(); ++r) out[r] = z[s_.rows[r]];
    // Ceres is told of a non-finite replay as a failed evaluation.
    return std::all_of(out.begin(), out.end(), [](double v) { return std::isfinite(v); });
  }

  Setup s_;
  mutable std::map<std::vector<double>, std::vector<double>> evaluated_;  // point -> residuals
};

// Parameters whose signature is not zero everywhere (the others cost no
// degree of freedom: a misalignment term of an axis the plan never swings).
std::size_t parametersWithSignature(const Candidate& c) {
  return static_cast<std::size_t>(std::count_if(c.cols.begin(), c.cols.end(), [](const auto& col) {
    return std::any_of(col.begin(), col.end(), [](double v) { return v != 0.0; });
  }));
}
}  // namespace

// Every identifiable effect's signature (from the replays) fitted linearly
// with the nuisance directions on the training cells; ranked by score.
std::vector<Candidate> scoreEffects(const FeatureSet& realFeatures, const GapModel& g,
                                    const std::vector<SignatureJob>& jobs, const std::vector<FeatureSet>& outputs,
                                    const std::vector<GapCell>& gapMap) {
  const auto& keys = realFeatures.keys;
  const std::size_t n = keys.size();
  const Stats& st = g.st;
  const auto& nuisance = g.nuisance;
  const std::size_t nNuis = nuisance.size();
  const std::vector<double>& base = g.base;
  const auto& library = effectLibrary();
  std::vector<Candidate> cands;
  std::size_t nTrain = 0, nHeld = 0;
  for (bool h : st.held) (h ? nHeld : nTrain)++;
  for (std::size_t e = 0; e < library.size(); ++e) {
    if (!library[e].identifiable) continue;
    Candidate cand;
    cand.lib = e;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      if (jobs[j].effectIndex != static_cast<int>(e) || jobs[j].sign < 0.0) continue;
      const auto& param = library[e].parameters[static_cast<std::size_t>(jobs[j].parameter)];
      // The -reference job, when there is one, follows the +reference job.
      const bool central = param.canBeNegative;
      const std::vector<double>& minus = central ? outputs[j + 1].values : base;
      const double span = central ? 2.0 * param.reference : param.reference;
      std::vector<double> col(n);
      for (std::size_t i = 0; i < n; ++i) col[i] = (outputs[j].values[i] - minus[i]) / span / st.sigma[i];
      cand.cols.push_back(std::move(col));
    }
    EffectFit& f = cand.fit;
    for (const auto& col : cand.cols) {
      std::vector<double> r = col;
      std::vector<bool> none(n, false);
      projectOut(nuisance, r, none, false);
      double norm2 = 0.0;
      for (double v : r) norm2 += v * v;
      // Linear: 5 / |signature per unit|. Nonlinear (the lag acts through
      // its square once the delay is calibrated away): scale quadratically
      // from the reference magnitude.
      // (the lag's column is per ms^2: tau^2 = 5 / |signature|).
      double th = norm2 <= 0.0         ? 0.0
                  : library[e].linear ? 5.0 / std::sqrt(norm2)
                                      : std::sqrt(5.0 / std::sqrt(norm2));
      // Lost-frame cells: the effect brings its own Poisson spread (a count
      // lambda has variance lambda), so the magnitude reaching delta chi2 =
      // 25 is found with that spread added (bisection; norm grows with p).
      double framesNorm2 = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (keys[i].unit == Unit::kFrames) framesNorm2 += r[i] * r[i];
      if (library[e].linear && th > 0.0 && framesNorm2 > 0.0) {
        auto delta = [&](double p) {
          double s2 = (norm2 - framesNorm2) * p * p;
          for (std::size_t i = 0; i < n; ++i) {
            if (keys[i].unit != Unit::kFrames) continue;
            const double a = col[i] * st.sigma[i] * p;  // frames
            s2 += a * a / (st.sigma[i] * st.sigma[i] + std::abs(a));
          }
          return s2;
        };
        double lo = th, hi = th;
        while (delta(hi) < 25.0 && hi < 1e6 * th) hi *= 2.0;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          (delta(mid) < 25.0 ? lo : hi) = mid;
        }
        th = hi;
      }
      f.detectionThresholds.push_back(th);
    }
    f.name = library[e].name;
    f.description = library[e].description;
    f.parameters = library[e].parameters;
    std::vector<std::vector<double>> withNuisance = nuisance;
    withNuisance.insert(withNuisance.end(), cand.cols.begin(), cand.cols.end());
    const LinearFit train = fitColumns(withNuisance, st.z, st.held, true);
    const LinearFit all = fitColumns(withNuisance, st.z, st.held, false);
    if (!train.ok || !all.ok) {
      f.note = "no signature in this session's features";
      f.values.assign(f.parameters.size(), 0.0);
      f.standardErrors.assign(f.parameters.size(), 0.0);
      cands.push_back(std::move(cand));
      continue;
    }
    std::vector<double> zTrain(n), zAll(n);
    for (std::size_t i = 0; i < n; ++i) {
      double pt = 0, pa = 0;
      for (std::size_t j = 0; j < withNuisance.size(); ++j) {
        pt += withNuisance[j][i] * train.p(static_cast<Eigen::Index>(j));
        pa += withNuisance[j][i] * all.p(static_cast<Eigen::Index>(j));
      }
      zTrain[i] = st.z[i] - pt;
      zAll[i] = st.z[i] - pa;
    }
    // Parameters without a signature here cost no degree of freedom.
    const double k = static_cast<double>(parametersWithSignature(cand));
    f.trainDeltaChi2 = g.chiTrain - chi2(zTrain, st.held, false);
    f.heldOutDeltaChi2 = g.chiHeld - chi2(zTrain, st.held, true);
    f.score = f.trainDeltaChi2 - k * std::log(static_cast<double>(nTrain));
    if (!std::isfinite(*f.score) || !std::isfinite(f.heldOutDeltaChi2)) {
      // Not ranked, never kept: a NaN score would sort anywhere.
      f.score.reset();
      f.note = "its fit is not a finite number in this session's features (not scored)";
    }
    const double chiAfter = chi2(zAll, st.held, false) + chi2(zAll, st.held, true);
    const double scale = std::sqrt(std::max(1.0, chiAfter / std::max(1.0, static_cast<double>(n) - k)));
    for (std::size_t j = 0; j < cand.cols.size(); ++j) {
      const double v = all.p(static_cast<Eigen::Index>(nNuis + j));
      const double se = all.stdErr(static_cast<Eigen::Index>(nNuis + j)) * scale;
      if (library[e].id == EffectId::kFirstOrderLag) {  // fitted tau^2
        const double tau = std::sqrt(std::max(v, 0.0));
        f.values.push_back(tau);
        f.standardErrors.push_back(tau > 0.0 ? se / (2.0 * tau) : std::sqrt(se));
      } else {
        f.values.push_back(v);
        f.standardErrors.push_back(se);
      }
    }
    cand.zAfter = zTrain;
    HeldOutShrink total;
    f.perChannel = shrinkPerChannel(gapMap, g.z0, zTrain, &total);
    f.heldOutShrink = total.shrink;
    cands.push_back(std::move(cand));
  }
  // Best first; effects without a signature last.
  std::stable_sort(cands.begin(), cands.end(), [](const Candidate& a, const Candidate& b) {
    return a.fit.score.value_or(-std::numeric_limits<double>::infinity()) >
           b.fit.score.value_or(-std::numeric_limits<double>::infinity());
  });
  return cands;
}

namespace {
// What the replay with `effects` leaves of the gap: the session's features
// against it in z units, the nuisance directions taken out. (Its seed is the
// signatures', so only the effects differ from the base replay.)
class ExactEvaluator {
 public:
  ExactEvaluator(const Replay& replay, const GapModel& g, const std::vector<double>& real, std::uint64_t seed)
      : replay_(replay), g_(g), real_(real), seed_(seed) {}

  bool operator()(const EffectList& effects, std::vector<double>& zOut) const {
    auto f = replay_.run(seed_, effects);
    const std::size_t n = real_.size();
    if (!f || f->values.size() != n) return false;
    zOut.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      zOut[i] = (real_[i] - g_.st.mean[i] - (f->values[i] - g_.base[i])) / spreadWith(g_.st, i, f->values[i] - g_.base[i]);
    projectOut(g_.nuisance, zOut, g_.st.held, true);
    // A replay with non-finite features is no evaluation: the effect is
    // judged as if it had not been replayed (not kept).
    return std::all_of(zOut.begin(), zOut.end(), [](double v) { return std::isfinite(v); });
  }

 private:
  const Replay& replay_;
  const GapModel& g_;
  const std::vector<double>& real_;
  std::uint64_t seed_;
};
}  // namespace

// The best few candidates on the exact forward model: nonlinear ones fitted
// with Ceres first (sequential: each Ceres evaluation is a replay), then all
// of them evaluated exactly in parallel and kept or not.
Status refineBest(std::vector<Candidate>& cands, const Replay& replay, const GapModel& g,
                  const std::vector<double>& real, const std::vector<GapCell>& gapMap,
                  const DiagnosisOptions& options, const Progress& progress) {
  const std::size_t n = real.size();
  const Stats& st = g.st;
  const auto& library = effectLibrary();
  const double lnN = std::log(static_cast<double>(n));
  const ExactEvaluator exactZ(replay, g, real, options.seed);
  std::vector<std::size_t> trainRows;
  for (std::size_t i = 0; i < n; ++i)
    if (!st.held[i]) trainRows.push_back(i);
  const int refine = std::min<int>(options.refineTop, static_cast<int>(cands.size()));
  // Nonlinear fits first (sequential: each Ceres evaluation is a replay), then
  // the exact evaluations in parallel.
  for (int r = 0; r < refine; ++r) {
    Candidate& cand = cands[static_cast<std::size_t>(r)];
    const EffectSpec& spec = library[cand.lib];
    // Only an effect whose linear fit already improves the training blocks
    // by what the held-out test will ask can be kept; the others are judged
    // at their linear values (a Ceres fit of a 5-min session costs ~15 s).
    if (spec.linear || cand.fit.trainDeltaChi2 < options.heldOutDeltaChi2) continue;
    const bool squared = spec.id == EffectId::kFirstOrderLag;
    ForwardCost::Setup setup{&replay, spec.id, options.seed, &g.base, &g.st, &real, trainRows, &g.nuisance, squared,
                             squared ? 0.3 : 0.03, {}, options.threads};
    std::vector<double> x = cand.fit.values;
    for (std::size_t j = 0; j < x.size(); ++j) {
      const double floor = 0.1 * spec.parameters[j].reference;
      x[j] = std::max(x[j], floor);
      if (squared) x[j] *= x[j];
      setup.minStep.push_back(0.03 * (squared ? floor * floor : floor));
    }
    auto* cost = new ForwardCost(std::move(setup));
    ceres::Problem problem;
    problem.AddResidualBlock(cost, nullptr, x.data());
    for (std::size_t j = 0; j < x.size(); ++j) {
      // Within the range the effect is modelled for: a replay outside it fails.
      const double top = spec.parameters[j].maxMagnitude;
      problem.SetParameterLowerBound(x.data(), static_cast<int>(j), 0.0);
      problem.SetParameterUpperBound(x.data(), static_cast<int>(j), squared ? top * top : top);
      x[j] = std::min(x[j], squared ? top * top : top);
    }
    ceres::Solver::Options so;
    // Near the optimum the steps only wander in the re-drawn quantisation
    // noise (~1 % of tau^2 for a 2-ms lag), which no tolerance on the cost
    // can tell from progress: stop on a step under 1 % instead.
    so.max_num_iterations = 6;
    so.parameter_tolerance = 0.01;
    // With a bound, Ceres follows each trust-region step with a projected
    // line search that evaluates the Jacobian (k + 1 replays) at every trial
    // point: half the replays of a lag fit, for steps that only wander in
    // the quantisation noise. The bound is kept; the line search is not.
    so.max_num_line_search_step_size_iterations = 0;
    so.logging_type = ceres::SILENT;
    so.linear_solver_type = ceres::DENSE_QR;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    if (progress.cancelled()) return cancelledByCaller();
    // A fit Ceres cannot vouch for (the replays failed, the cost went
    // non-finite) keeps the linear values, and says so.
    if (!summary.IsSolutionUsable()) {
      cand.fit.note = "the Ceres fit on the forward model failed (" + summary.message + "); linear fit kept";
      continue;
    }
    cand.fit.values = cost->parametersOf(x);
    cand.fit.note = "fitted with Ceres on the forward model (" + std::to_string(summary.iterations.size()) + " iterations)";
  }
  std::vector<std::vector<double>> zExact(static_cast<std::size_t>(refine));
  std::vector<char> okExact(static_cast<std::size_t>(refine), 0);
  // A fit outside the effect's modelled range (a linear signature
  // extrapolated 1e7 times past its reference) is no finding: it is not
  // replayed, and not kept.
  for (int r = 0; r < refine; ++r) {
    Candidate& cand = cands[static_cast<std::size_t>(r)];
    if (!cand.fit.score) continue;
    if (Status s = checkParameters(library[cand.lib].id, cand.fit.values); !s.isOk())
      cand.fit.note += std::string(cand.fit.note.empty() ? "" : "; ") + "not kept: fitted " + s.message();
  }
  parallelFor(static_cast<std::size_t>(refine), options.threads, [&](std::size_t r) {
    const Candidate& cand = cands[r];
    okExact[r] = cand.fit.score.has_value() && checkParameters(library[cand.lib].id, cand.fit.values).isOk() &&
                 exactZ({{library[cand.lib].id, cand.fit.values}}, zExact[r]);
  });
  for (int r = 0; r < refine; ++r) {
    Candidate& cand = cands[static_cast<std::size_t>(r)];
    if (!okExact[static_cast<std::size_t>(r)]) continue;
    const auto& z = zExact[static_cast<std::size_t>(r)];
    EffectFit& f = cand.fit;
    f.exact = true;
    f.trainDeltaChi2 = g.chiTrain - chi2(z, st.held, false);
    f.heldOutDeltaChi2 = g.chiHeld - chi2(z, st.held, true);
    const double k = static_cast<double>(parametersWithSignature(cand));
    HeldOutShrink total;
    f.perChannel = shrinkPerChannel(gapMap, g.z0, z, &total);
    f.heldOutShrink = total.shrink;
    const double allDelta = f.trainDeltaChi2 + f.heldOutDeltaChi2;
    // The exact replay re-draws the gyro's pulse quantisation (~10-20 chi2
    // units spread over the cells): it confirms an effect the linear fit
    // found worth its parameters (score > 0), never creates one.
    f.kept = f.score.value_or(0.0) > 0.0 && f.heldOutDeltaChi2 >= options.heldOutDeltaChi2 && allDelta > k * lnN;
    // Residual check per channel: an effect that closes the gap in one
    // channel while opening one elsewhere (a lag that takes up a vibration
    // in the gyro residual but breaks the gyro-table harmonics) is not what
    // the data show.
    const double worse = worstChannelWorsening(gapMap, g.z0, z);
    if (f.kept && worse > options.channelWorsening) {
      f.kept = false;
      f.note += std::string(f.note.empty() ? "" : "; ") + "not kept: makes the held-out " +
                "fit of another channel worse by " + fmt("%.0f", worse);
    }
    cand.zAfter = z;
  }
  return Status::ok();
}

// The best kept effect, and a second one when the two together close what
// the first alone leaves, on the exact forward model.
VerdictModel chooseModel(std::vector<Candidate>& cands, const Replay& replay, const GapModel& g,
                         const std::vector<double>& real, const std::vector<GapCell>& gapMap,
                         const DiagnosisOptions& options) {
  const std::size_t n = real.size();
  const Stats& st = g.st;
  const auto& nuisance = g.nuisance;
  const std::size_t nNuis = nuisance.size();
  const auto& library = effectLibrary();
  const double lnN = std::log(static_cast<double>(n));
  const ExactEvaluator exactZ(replay, g, real, options.seed);
  const int refine = std::min<int>(options.refineTop, static_cast<int>(cands.size()));
  std::vector<std::size_t> kept;
  for (int r = 0; r < refine; ++r)
    if (cands[static_cast<std::size_t>(r)].fit.kept) kept.push_back(static_cast<std::size_t>(r));
  std::sort(kept.begin(), kept.end(), [&](std::size_t a, std::size_t b) {
    return cands[a].fit.heldOutDeltaChi2 > cands[b].fit.heldOutDeltaChi2;
  });
  VerdictModel out;
  std::vector<double>& zModel = out.z;
  std::vector<std::size_t>& model = out.members;
  zModel = g.z0;
  if (!kept.empty()) {
    model.push_back(kept[0]);
    zModel = cands[kept[0]].zAfter;
  }
  if (options.allowPairs && !model.empty()) {
    // The best partner by the joint linear fit on training blocks, among the
    // top candidates; then checked on the exact forward model.
    const std::size_t first = model[0];
    double bestTrain = -1e300;
    std::size_t partner = cands.size();
    LinearFit bestFit;
    const std::size_t top = std::min<std::size_t>(cands.size(), 5);
    for (std::size_t j = 0; j < top; ++j) {
      if (j == first || !cands[j].fit.score) continue;
      std::vector<std::vector<double>> cols = nuisance;
      cols.insert(cols.end(), cands[first].cols.begin(), cands[first].cols.end());
      cols.insert(cols.end(), cands[j].cols.begin(), cands[j].cols.end());
      const LinearFit lf = fitColumns(cols, st.z, st.held, true);
      if (!lf.ok) continue;
      std::vector<double> zt(n);
      for (std::size_t i = 0; i < n; ++i) {
        double pr = 0;
        for (std::size_t c2 = 0; c2 < cols.size(); ++c2) pr += cols[c2][i] * lf.p(static_cast<Eigen::Index>(c2));
        zt[i] = st.z[i] - pr;
      }
      const double t = g.chiTrain - chi2(zt, st.held, false);
      if (t > bestTrain) bestTrain = t, partner = j, bestFit = lf;
    }
    if (partner < cands.size()) {
      const std::size_t k1 = cands[first].cols.size();
      std::vector<double> p1 = cands[first].fit.values, p2;
      if (library[cands[first].lib].linear)
        for (std::size_t j = 0; j < k1; ++j) p1[j] = bestFit.p(static_cast<Eigen::Index>(nNuis + j));
      for (std::size_t j = 0; j < cands[partner].cols.size(); ++j)
        p2.push_back(bestFit.p(static_cast<Eigen::Index>(nNuis + k1 + j)));
      if (!library[cands[partner].lib].linear)
        for (double& v : p2) v = std::max(v, 0.0);
      if (library[cands[partner].lib].id == EffectId::kFirstOrderLag)
        for (double& v : p2) v = std::sqrt(v);
      std::vector<double> zPair;
      // A joint fit outside either effect's modelled range is not replayed.
      const bool inRange = checkParameters(library[cands[first].lib].id, p1).isOk() &&
                           checkParameters(library[cands[partner].lib].id, p2).isOk();
      if (inRange && exactZ({{library[cands[first].lib].id, p1}, {library[cands[partner].lib].id, p2}}, zPair)) {
        const double gainHeld = chi2(zModel, st.held, true) - chi2(zPair, st.held, true);
        const double gainAll = gainHeld + chi2(zModel, st.held, false) - chi2(zPair, st.held, false);
        const double k2 = static_cast<double>(p2.size());
        if (gainHeld >= options.heldOutDeltaChi2 && gainAll > k2 * lnN &&
            worstChannelWorsening(gapMap, zModel, zPair) <= options.channelWorsening) {
          model.push_back(partner);
          zModel = zPair;
          Candidate& pc = cands[partner];
          pc.fit.kept = true;
          pc.fit.values = p2;
          pc.fit.note = "kept together with " + cands[first].fit.name;
          if (library[cands[first].lib].linear) cands[first].fit.values = p1;
        }
      }
    }
  }
  return out;
}

// The verdict from the model: its effects, what it leaves of the held-out
// gap, and "none" / an effect / "unexplained" with the reason.
void decideVerdict(const VerdictModel& chosen, const std::vector<Candidate>& cands, const std::vector<double>& z0,
                   const DiagnosisOptions& options, Diagnosis& d) {
  const std::vector<double>& zModel = chosen.z;
  const std::vector<std::size_t>& model = chosen.members;
  for (std::size_t i = 0; i < d.gapMap.size(); ++i) d.gapMap[i].zAfter = zModel[i];
  d.gapAfter = channelGaps(d.gapMap, true);
  HeldOutShrink total;
  d.heldOut = shrinkPerChannel(d.gapMap, z0, zModel, &total);
  // Every verdict, "none" above all, is a comparison of finite chi2 values:
  // with a NaN anywhere, "chi2 - n > 5 sigma" is false and would read as
  // agreement. buildGapMap() refuses non-finite cells; this is the last line.
  std::string notFinite;
  auto requireFinite = [&](double v, const std::string& what) {
    if (notFinite.empty() && !std::isfinite(v)) notFinite = what + " is " + fmt("%g", v);
  };
  requireFinite(d.chiSquare, "the gap's chi2");
  for (const auto& g : d.gapBefore) requireFinite(g.chiSquare, std::string("the ") + channelName(g.channel) + " channel's chi2");
  for (const auto& g : d.gapAfter)
    requireFinite(g.chiSquare, std::string("the ") + channelName(g.channel) + " channel's chi2 after the model");
  for (const auto& h : d.heldOut) {
    requireFinite(h.before, std::string("the ") + channelName(h.channel) + " channel's held-out chi2");
    requireFinite(h.after, std::string("the ") + channelName(h.channel) + " channel's held-out chi2 after the model");
  }
  for (std::size_t m : model)
    for (double v : cands[m].fit.values) requireFinite(v, "the fit of " + cands[m].fit.name);
  if (!notFinite.empty()) {
    d.verdict = "undetermined";
    d.verdictReason = "no verdict: " + notFinite + ", not a finite number, so real and simulated data cannot be compared";
    for (auto& cand : cands) d.effects.push_back(cand.fit);
    return;
  }
  // A right model leaves noise: its held-out remainder is tested like the
  // gap itself, over all held-out cells and within each channel (a ramp
  // fitted to a bias step closes ~90 % of the gap but leaves a remainder of
  // 8-32 sigma in the gyro trends, which the other channels' cells would
  // dilute). In the blind check (240 trials), no right verdict left more
  // than 4.6 sigma in any channel.
  std::string left;
  auto significantRemainder = [&](double excess, int count) {
    return count > 0 && excess > options.gapSigma * std::sqrt(2.0 * static_cast<double>(count));
  };
  auto describeRemainder = [&](double excess, int count) {
    return "excess chi2 " + fmt("%.0f", excess) + " over " + std::to_string(count) + " cells, " +
           fmt("%.1f", excess / std::sqrt(2.0 * static_cast<double>(count))) + " sigma";
  };
  double worstSigma = 0.0;  // name the channel with the most significant remainder
  for (const auto& h : d.heldOut) {
    const double sigma = h.cells > 0 ? h.after / std::sqrt(2.0 * static_cast<double>(h.cells)) : 0.0;
    if (significantRemainder(h.after, h.cells) && sigma > worstSigma) {
      worstSigma = sigma;
      left = std::string(channelName(h.channel)) + " channel (" + describeRemainder(h.after, h.cells) + ")";
    }
  }
  if (left.empty() && significantRemainder(total.after, total.cells))
    left = "held-out cells (" + describeRemainder(total.after, total.cells) + ")";
  if (!model.empty() && !left.empty() && !(total.shrink >= options.partialExplanationShare)) {
    // Kept by its delta chi2, but closing too little to be named.
    d.verdict = "unexplained";
    d.verdictReason = "the gap is significant and no effect in the library explains it: the best, " +
                      effectTitle(cands[model[0]].fit.name) + ", closes only " + fmt("%.0f", 100.0 * total.shrink) +
                      " % of the held-out gap and leaves a significant remainder in the " + left;
    for (auto& cand : cands) d.effects.push_back(cand.fit);
    for (std::size_t m : model)
      d.effects[m].note = "kept by its held-out delta chi2, but it closes only " + fmt("%.0f", 100.0 * total.shrink) +
                          " % of the held-out gap: not named as a partial explanation";
    return;
  }
  for (std::size_t m : model) d.verdictEffects.push_back(cands[m].fit.name);
  if (model.empty()) {
    d.verdict = d.gapSignificant ? "unexplained" : "none";
    d.verdictReason = d.gapSignificant ? "the gap is significant and no effect in the library closes it on held-out blocks"
                                       : "real and simulated data agree within the simulator's own spread";
  } else if (!left.empty()) {
    d.verdict = "unexplained";
    d.verdictReason = effectTitle(cands[model[0]].fit.name) + " closes " + fmt("%.0f", 100.0 * total.shrink) +
                      " % of the held-out gap but leaves a significant remainder in the " + left +
                      "; the rest is not in the library";
  } else {
    d.verdict = cands[model[0]].fit.name;
    d.verdictReason = "closes " + fmt("%.0f", 100.0 * total.shrink) + " % of the held-out gap";
  }
  for (auto& cand : cands) d.effects.push_back(cand.fit);
}

}  // namespace fog::diagnosis::detail
