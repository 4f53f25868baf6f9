#pragma once
// The stated lag uncertainty against the Cramér–Rao bound of the session's
// noise: the check `uncertainty_below_bound`.
//
// No unbiased estimator of the lag scatters less than the bound. A stated σ
// far below it means the uncertainty is understated (a per-period scatter
// that happened to be small, a noise model that missed a term), and a
// verdict resting on it is not one the bench can vouch for.
//
// Two things make a σ below the bound honest, and the check allows both:
//  - the bound's own noise model is conservative for pulse quantisation:
//    it treats the quantisation of each increment as white, while the
//    quantisation of a pulse count is carried from frame to frame. On 197
//    independent Monte Carlo sessions (tests/independent/monte_carlo.py,
//    seed 1) whose z-scores were right (std 0.98), σ/CRLB went down to 0.54
//    (coarse pulses), 5 % below 0.79: the check allows down to 0.4 of the
//    bound, a quarter below the lowest seen;
//  - σ is itself an estimate with ν degrees of freedom (the fit's residuals,
//    or the periods of a per-period scatter): it may read low by chance. The
//    check fails only below the 0.1 % quantile of that chance,
//    sqrt(χ²(ν, 0.001) / ν).
// So it fails when σ / CRLB < 0.4 · sqrt(χ²(ν, 0.001) / ν).

#include "core/analysis/delay_analysis.h"
#include "core/analysis/validity.h"

namespace fog::analysis {

// The factor by which the bound's noise model may overstate the lag's
// variance (see above), as a ratio of standard deviations.
inline constexpr double kBoundModelFactor = 0.4;

// The degrees of freedom of the point's stated σ (lagStdSource says which).
int lagStdDegreesOfFreedom(const TestPointResult& point);

// The smallest σ / CRLB the check accepts for ν degrees of freedom.
double smallestStdOverBound(int dof);

// The check for one analysed point (its σ, CRLB and source set); judged
// only when the bound is known (> 0).
ValidityCheck uncertaintyBelowBoundCheck(const TestPointResult& point);

// True when the point's check uncertainty_below_bound was judged and failed:
// the views mark the σ/CRLB they show beside the σ.
bool sigmaBelowBound(const TestPointResult& point);

}  // namespace fog::analysis
