#pragma once
// The decision rule a verdict applies, and its risk, stated with every
// statement of conformity (ISO/IEC 17025:2017 §7.8.6: a statement of
// conformity states the decision rule and the risk it carries;
// ILAC-G8:09/2019, guarded acceptance). Qt-free.
//
// The rule (verdict.h): PASS when IMU delay + k·σ < limit; FAIL otherwise;
// INVALID when a validity check fails. k·σ is the guard band w: a delay is
// accepted only when it lies at least w below the limit.
//
// The risk, assuming the measured delay d errs by a Gaussian with the stated
// standard uncertainty σ (the true delay ~ N(d, σ²)):
//  - the rule's maximum probability of false accept, 1 − Φ(k): a measurement
//    just at the acceptance boundary (d = limit − k·σ) has the true delay at
//    or above the limit with this probability; every accepted point has less
//    (2.28 % at k = 2);
//  - a point's specific risk, P(true delay ≥ limit | d, σ) = 1 − Φ((limit − d)/σ):
//    for a PASS point, the probability that the acceptance is false; for a
//    FAIL point, the probability that the true delay is above the limit
//    (so 1 minus it is the chance the rejection is false). σ = 0 makes it
//    0 or 1 (d < limit or not).

#include <string>

namespace fog::analysis {

// The coverage factor the bench judged with before k was a setting (and
// still the default); rows stored before state no k and were judged with it.
inline constexpr double kDefaultCoverageFactor = 2.0;
// A k outside (0, kMaxCoverageFactor] is refused: k ≤ 0 is no guard band,
// and beyond 10 the false-accept risk (< 1e-23) is below anything a double
// or a Gaussian assumption can stand for.
inline constexpr double kMaxCoverageFactor = 10.0;

// "" when k is a usable coverage factor; else what is wrong, in a sentence
// ("the coverage factor k must be a finite number in (0, 10], not -1").
std::string coverageFactorProblem(double k);

// Φ(x), the standard normal cumulative distribution (via std::erfc, exact
// in the tails where 1 − erf would cancel).
double standardNormalCdf(double x);

// 1 − Φ(k): the rule's maximum probability of false accept.
double maxFalseAcceptProbability(double k);

// P(true delay ≥ limit | measured delay d, σ) = 1 − Φ((limit − d)/σ).
// σ = 0: 1 when d ≥ limit, else 0. NaN when any input is not finite or σ < 0.
double falseAcceptProbability(double delayMs, double sigmaMs, double limitMs);

// The guard band w = k·σ (ms).
inline double guardBandMs(double k, double sigmaMs) { return k * sigmaMs; }

// k as a person writes it: "2", "2.5", "3".
std::string coverageFactorText(double k);

// A probability as a percentage with enough digits to tell it from its
// neighbours: "2.28 %", "0.135 %", "50.0 %"; "< 1e-6 %" below 1e-8 (and for
// a tail that underflowed to 0), "> 99.9999 %" just below 1.
std::string probabilityText(double p);

// The rule in one sentence: "PASS when IMU delay + k·σ < limit (k = 2,
// one-sided guarded acceptance, ISO/IEC 17025:2017 §7.8.6 /
// ILAC-G8:09/2019); FAIL otherwise; INVALID when a validity check fails".
std::string decisionRuleText(double k);

// The rule's risk in one sentence: "maximum probability of false accept
// 1 − Φ(k) = 2.28 % (a delay measured just at the acceptance boundary, with a
// Gaussian error of the stated σ)".
std::string decisionRiskText(double k);

// The rule and its risk, as the text reports state it (one paragraph):
// "decision rule: <rule>; <risk>" and, when `limitMs` > 0, the limit.
std::string decisionRuleStatement(double k, double limitMs);

// The short name stored in the result's settings and JSON report.
inline constexpr const char* kDecisionRuleName = "guarded acceptance: IMU delay + k*sigma < limit";

}  // namespace fog::analysis
