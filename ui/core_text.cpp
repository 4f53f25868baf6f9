#include "ui/core_text.h"

#include "core/analysis/frequency_response.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>
#include <algorithm>
#include <string_view>
#include <utility>
#include <vector>


namespace fog::ui {
namespace {

using Size = decltype(QString().size());  // int in Qt 5, qsizetype in Qt 6

// The core's message templates, as the core writes them (core/analysis,
// core/diagnosis, core/noise, core/acquisition, core/session); %1, %2, ...
// stand for the variable parts. A template is only ever matched whole, so a
// message the core changes stops matching and shows in English until its
// template here follows (tests/ui/core_text_test.cpp then fails).
const char* const kTemplates[] = {
    QT_TRANSLATE_NOOP("core_text", "table"),
    QT_TRANSLATE_NOOP("core_text", "gyro"),
    QT_TRANSLATE_NOOP("core_text", "gyro-table"),
    QT_TRANSLATE_NOOP("core_text", "timing"),
    QT_TRANSLATE_NOOP("core_text", "imu"),
    QT_TRANSLATE_NOOP("core_text", "none"),
    QT_TRANSLATE_NOOP("core_text", "unexplained"),
    QT_TRANSLATE_NOOP("core_text", "bias_drift"),
    QT_TRANSLATE_NOOP("core_text", "scale_factor_error"),
    QT_TRANSLATE_NOOP("core_text", "scale_factor_asymmetry"),
    QT_TRANSLATE_NOOP("core_text", "scale_factor_nonlinearity"),
    QT_TRANSLATE_NOOP("core_text", "misalignment"),
    QT_TRANSLATE_NOOP("core_text", "g_sensitivity"),
    QT_TRANSLATE_NOOP("core_text", "first_order_lag"),
    QT_TRANSLATE_NOOP("core_text", "table_harmonic_distortion"),
    QT_TRANSLATE_NOOP("core_text", "encoder_cyclic_error"),
    QT_TRANSLATE_NOOP("core_text", "timestamp_jitter"),
    QT_TRANSLATE_NOOP("core_text", "clock_drift"),
    QT_TRANSLATE_NOOP("core_text", "dropped_frames"),
    QT_TRANSLATE_NOOP("core_text", "earth_rate_projection"),
    QT_TRANSLATE_NOOP("core_text", "bias drift"),
    QT_TRANSLATE_NOOP("core_text", "scale-factor error"),
    QT_TRANSLATE_NOOP("core_text", "scale-factor asymmetry"),
    QT_TRANSLATE_NOOP("core_text", "scale-factor nonlinearity"),
    QT_TRANSLATE_NOOP("core_text", "g-sensitivity"),
    QT_TRANSLATE_NOOP("core_text", "first-order lag"),
    QT_TRANSLATE_NOOP("core_text", "table harmonic distortion"),
    QT_TRANSLATE_NOOP("core_text", "encoder cyclic error"),
    QT_TRANSLATE_NOOP("core_text", "time-stamp jitter"),
    QT_TRANSLATE_NOOP("core_text", "IMU clock drift"),
    QT_TRANSLATE_NOOP("core_text", "dropped frames"),
    QT_TRANSLATE_NOOP("core_text", "Earth-rate projection"),
    QT_TRANSLATE_NOOP("core_text", "none (the recording agrees with the simulation)"),
    QT_TRANSLATE_NOOP("core_text", "unexplained (no effect of the library closes the gap)"),
    QT_TRANSLATE_NOOP("core_text", "harmonic %1, in phase"),
    QT_TRANSLATE_NOOP("core_text", "harmonic %1, quadrature"),
    QT_TRANSLATE_NOOP("core_text", "residual mean square"),
    QT_TRANSLATE_NOOP("core_text", "cross-axis, in phase"),
    QT_TRANSLATE_NOOP("core_text", "cross-axis, quadrature"),
    QT_TRANSLATE_NOOP("core_text", "table stamp interval"),
    QT_TRANSLATE_NOOP("core_text", "table stamp-interval variance"),
    QT_TRANSLATE_NOOP("core_text", "IMU stamp interval"),
    QT_TRANSLATE_NOOP("core_text", "IMU stamp-interval variance"),
    QT_TRANSLATE_NOOP("core_text", "IMU frames lost"),
    QT_TRANSLATE_NOOP("core_text", "table samples lost"),
    QT_TRANSLATE_NOOP("core_text", "h%1_in_phase"),
    QT_TRANSLATE_NOOP("core_text", "h%1_quadrature"),
    QT_TRANSLATE_NOOP("core_text", "residual_ms"),
    QT_TRANSLATE_NOOP("core_text", "gain"),
    QT_TRANSLATE_NOOP("core_text", "delay"),
    QT_TRANSLATE_NOOP("core_text", "trend"),
    QT_TRANSLATE_NOOP("core_text", "cross_in_phase"),
    QT_TRANSLATE_NOOP("core_text", "cross_quadrature"),
    QT_TRANSLATE_NOOP("core_text", "table_interval"),
    QT_TRANSLATE_NOOP("core_text", "table_interval_var"),
    QT_TRANSLATE_NOOP("core_text", "imu_interval"),
    QT_TRANSLATE_NOOP("core_text", "imu_interval_var"),
    QT_TRANSLATE_NOOP("core_text", "imu_lost"),
    QT_TRANSLATE_NOOP("core_text", "table_lost"),
    QT_TRANSLATE_NOOP("core_text", "frames"),
    QT_TRANSLATE_NOOP("core_text", "drift"),
    QT_TRANSLATE_NOOP("core_text", "scale_factor"),
    QT_TRANSLATE_NOOP("core_text", "asymmetry"),
    QT_TRANSLATE_NOOP("core_text", "nonlinearity"),
    QT_TRANSLATE_NOOP("core_text", "time_constant"),
    QT_TRANSLATE_NOOP("core_text", "sin_amplitude"),
    QT_TRANSLATE_NOOP("core_text", "cos_amplitude"),
    QT_TRANSLATE_NOOP("core_text", "jitter_variance"),
    QT_TRANSLATE_NOOP("core_text", "loss_rate"),
    QT_TRANSLATE_NOOP("core_text", "latitude_error"),
    QT_TRANSLATE_NOOP("core_text", "heading_error"),
    QT_TRANSLATE_NOOP("core_text", "deg/h per min"),
    QT_TRANSLATE_NOOP("core_text", "ppm at 100 deg/s"),
    QT_TRANSLATE_NOOP("core_text", "ppm of full scale over +-100 deg/s"),
    QT_TRANSLATE_NOOP("core_text", "h2"),
    QT_TRANSLATE_NOOP("core_text", "h3"),
    QT_TRANSLATE_NOOP("core_text", "per mille"),
    QT_TRANSLATE_NOOP("core_text", "arcsec"),
    QT_TRANSLATE_NOOP("core_text", "Sim-to-real diagnosis: %1 gap-map cells, chi2 %2 (%3)"),
    QT_TRANSLATE_NOOP("core_text", "significant gap"),
    QT_TRANSLATE_NOOP("core_text", "no significant gap"),
    QT_TRANSLATE_NOOP("core_text", "replay calibrated to: lag %1 ms, table frequency %2 ppm, encoder noise %3 deg, ARW %4 deg/sqrt(h), bias %5 deg/h,"),
    QT_TRANSLATE_NOOP("core_text", "z %1, heading %2 +- %3 deg, table every %4 ms, IMU every %5 ms, bias instability %6 deg/h over %7 s (%8)"),
    QT_TRANSLATE_NOOP("core_text", "stated"),
    QT_TRANSLATE_NOOP("core_text", "assumed"),
    QT_TRANSLATE_NOOP("core_text", "Timing audit real replay"),
    QT_TRANSLATE_NOOP("core_text", "%1 interval %2 ppm, std %3 us, gaps %4, dup %5 | %6 ppm, std %7 us, gaps %8"),
    QT_TRANSLATE_NOOP("core_text", "lost %1 / %2, duplicates %3 / %4, wraps %5 / %6, checksum failures %7 / %8"),
    QT_TRANSLATE_NOOP("core_text", "Gap per channel (rms z; 1 = within the simulator's spread) before after held-out shrink"),
    QT_TRANSLATE_NOOP("core_text", "%1 %2 cells %3 %4 %5 %"),
    QT_TRANSLATE_NOOP("core_text", "largest cells:"),
    QT_TRANSLATE_NOOP("core_text", "point %1 segment %2 %3 %4 axis %5: real %6, replay %7 +- %8 %9 (z %10)"),
    QT_TRANSLATE_NOOP("core_text", "Effects, ranked (score = training delta chi2 - k ln n)"),
    QT_TRANSLATE_NOOP("core_text", "%1 score %2 held-out shrink %3 % KEPT %4"),
    QT_TRANSLATE_NOOP("core_text", "%1 score %2 held-out shrink %3 % %4"),
    QT_TRANSLATE_NOOP("core_text", "%1 %2 +- %3 %4, %5"),
    QT_TRANSLATE_NOOP("core_text", "%1 %2 +- %3 %4"),
    QT_TRANSLATE_NOOP("core_text", "Alias groups (swing data cannot separate these)"),
    QT_TRANSLATE_NOOP("core_text", "to separate: %1"),
    QT_TRANSLATE_NOOP("core_text", "note: %1"),
    QT_TRANSLATE_NOOP("core_text", "Verdict: %1 (+ %2) - %3"),
    QT_TRANSLATE_NOOP("core_text", "Verdict: %1 - %2"),
    QT_TRANSLATE_NOOP("core_text", "(diagnosis took %1 s)"),
    QT_TRANSLATE_NOOP("core_text", "constant delay: %1"),
    QT_TRANSLATE_NOOP("core_text", "constant rate: %1"),
    QT_TRANSLATE_NOOP("core_text", "pure gyro delay, first-order lag with time constant <= 5 ms, table read delay, timestamp offset, fixed serial / board latency"),
    QT_TRANSLATE_NOOP("core_text", "gyro bias, earth_rate_projection (latitude / heading error)"),
    QT_TRANSLATE_NOOP("core_text", "lag %1 ms (taken as the replay's nominal delay)"),
    QT_TRANSLATE_NOOP("core_text", "bias %1 / %2 / %3 deg/h (X/Y/Z, over the nominal Earth rate)"),
    QT_TRANSLATE_NOOP("core_text", "swing data shift all of them by one constant at every frequency: measure the read delay and the board latency on the board (loop-back / sync pulse), and separate a lag from a delay with a step or a swing above 1/(2 pi tau) (~30 Hz for 5 ms)"),
    QT_TRANSLATE_NOOP("core_text", "a constant rate per axis looks the same either way: a multi-position static test (IMU turned to four headings) separates the Earth rate from the bias"),
    QT_TRANSLATE_NOOP("core_text", "the gap is significant and no effect in the library closes it on held-out blocks"),
    QT_TRANSLATE_NOOP("core_text", "real and simulated data agree within the simulator's own spread"),
    QT_TRANSLATE_NOOP("core_text", "%1 closes %2 % of the held-out gap but leaves a significant remainder in the %3; the rest is not in the library"),
    QT_TRANSLATE_NOOP("core_text", "closes %1 % of the held-out gap"),
    QT_TRANSLATE_NOOP("core_text", "the gap is significant and no effect in the library explains it: the best, %1, closes only %2 % of the held-out gap and leaves a significant remainder in the %3"),
    QT_TRANSLATE_NOOP("core_text", "with the IMU's z axis %1 instead, a g-sensitivity of %2 deg/h/g gives the same data as %3 deg/h/g in the frame used: an isotropic g-sensitivity adds to the vertical Earth rate and swing data cannot tell them apart"),
    QT_TRANSLATE_NOOP("core_text", "check the IMU's mounting (a static test with the IMU turned over separates them)"),
    QT_TRANSLATE_NOOP("core_text", "the table channel's harmonics are in the encoder's reading only: the share of the table's harmonics the gyros do not see is %1 +- %2 (0 for a motion of the table, 1 for an encoder reading error), %3 sigma from a motion"),
    QT_TRANSLATE_NOOP("core_text", "an encoder reading error (an eccentric grating, a read-head error) is not in the library, whose table harmonic distortion is a motion and is kept as the table channel's partial explanation"),
    QT_TRANSLATE_NOOP("core_text", "fits the table channel, but the gyros do not see its harmonics: a reading error, not a motion"),
    QT_TRANSLATE_NOOP("core_text", "an encoder reading error with the same harmonics is not excluded: the share of the table's harmonics the gyros do not see is %1 +- %2 (0 for a motion of the table, 1 for an encoder reading error)"),
    QT_TRANSLATE_NOOP("core_text", "a second read head opposite the first, or an autocollimator on the table, separates a reading error from a motion"),
    QT_TRANSLATE_NOOP("core_text", "%1 channel (%2)"),
    QT_TRANSLATE_NOOP("core_text", "held-out cells (%1)"),
    QT_TRANSLATE_NOOP("core_text", "excess chi2 %1 over %2 cells, %3 sigma"),
    QT_TRANSLATE_NOOP("core_text", "%1 lost IMU frames filled with the mean increment"),
    QT_TRANSLATE_NOOP("core_text", "the noise model fits the Allan curve poorly (chi^2 %1 for %2 dof): a term outside IEEE 952, or non-white quantisation"),
    QT_TRANSLATE_NOOP("core_text", "quantisation"),
    QT_TRANSLATE_NOOP("core_text", "angle random walk"),
    QT_TRANSLATE_NOOP("core_text", "bias instability"),
    QT_TRANSLATE_NOOP("core_text", "rate random walk"),
    QT_TRANSLATE_NOOP("core_text", "rate ramp"),
    QT_TRANSLATE_NOOP("core_text", "simulator, seed %1, %2"),
    QT_TRANSLATE_NOOP("core_text", "effect %1=%2"),
    QT_TRANSLATE_NOOP("core_text", "session %1 (%2)"),
    QT_TRANSLATE_NOOP("core_text", "result %1 of %2, stored %3 by %4 (fogbench %5)"),
    QT_TRANSLATE_NOOP("core_text", "acquisition"),
    QT_TRANSLATE_NOOP("core_text", "Sagnac sensing"),
    QT_TRANSLATE_NOOP("core_text", "instantaneous in principle"),
    QT_TRANSLATE_NOOP("core_text", "closed-loop delay"),
    QT_TRANSLATE_NOOP("core_text", "<= %1 eigen periods"),
    QT_TRANSLATE_NOOP("core_text", "pulse output update"),
    QT_TRANSLATE_NOOP("core_text", "0 .. one update period"),
    QT_TRANSLATE_NOOP("core_text", "board: pulse sampling"),
    QT_TRANSLATE_NOOP("core_text", "board clock cycles"),
    QT_TRANSLATE_NOOP("core_text", "board: temperature compensation"),
    QT_TRANSLATE_NOOP("core_text", "board: serial frame"),
    QT_TRANSLATE_NOOP("core_text", "%1 bytes at %2 baud"),
    QT_TRANSLATE_NOOP("core_text", "real time"),
    QT_TRANSLATE_NOOP("core_text", "as fast as possible"),
    QT_TRANSLATE_NOOP("core_text", "%1x real time"),
    QT_TRANSLATE_NOOP("core_text", "preset %1"),
    QT_TRANSLATE_NOOP("core_text", "simulator truth, test point %1: lag %2 ms"),
    QT_TRANSLATE_NOOP("core_text", "replay of %1 at as fast as possible"),
    QT_TRANSLATE_NOOP("core_text", "replay of %1 at %2x"),
    QT_TRANSLATE_NOOP("core_text", "replay of %1 at as fast as possible (%2)"),
    QT_TRANSLATE_NOOP("core_text", "replay of %1 at %2x (%3)"),
    QT_TRANSLATE_NOOP("core_text", "stopped by the operator after %1 s"),
    QT_TRANSLATE_NOOP("core_text", "recording was interrupted: the recording program stopped without finishing the session (crash, kill, power cut or a full disk); everything committed until then is kept"),
    QT_TRANSLATE_NOOP("core_text", "being recorded now: the session is not finished yet"),
    QT_TRANSLATE_NOOP("core_text", "%1 (after %2 s)"),
    QT_TRANSLATE_NOOP("core_text", "the session file could not be written after %1 s (%2)"),
    QT_TRANSLATE_NOOP("core_text", "no data for %1 s from %2 (after %3 s)"),
    QT_TRANSLATE_NOOP("core_text", "the session file could not be written at the end of the run (%1)"),
    QT_TRANSLATE_NOOP("core_text", "test point %1: %2"),
    QT_TRANSLATE_NOOP("core_text", "table position of axis %1 must be within +-%2 deg, got %3 deg"),
    QT_TRANSLATE_NOOP("core_text", "a static segment has no frequency, amplitude or start phase (got %1 Hz, %2 deg, %3 deg); leave them out"),
    QT_TRANSLATE_NOOP("core_text", "a static segment needs a duration > 0 s, got %1"),
    QT_TRANSLATE_NOOP("core_text", "frequency must be > 0 Hz, got %1"),
    QT_TRANSLATE_NOOP("core_text", "frequency %1 Hz is beyond the table limit of %2 Hz"),
    QT_TRANSLATE_NOOP("core_text", "amplitude must be > 0 deg, got %1"),
    QT_TRANSLATE_NOOP("core_text", "amplitude %1 deg is beyond the table limit of %2 deg"),
    QT_TRANSLATE_NOOP("core_text", "peak rate %1 deg/s exceeds the table limit of %2 deg/s; lower the frequency or amplitude"),
    QT_TRANSLATE_NOOP("core_text", "peak acceleration %1 deg/s^2 exceeds the table limit of %2 deg/s^2; lower the frequency or amplitude"),
    // One rule for the fewest periods (test_plan.h kMinSwingPeriods): the plan's and the analysis' words.
    QT_TRANSLATE_NOOP("core_text", "duration %1 s covers %2 swing periods, under two swing periods: a delay needs at least two whole periods (%3 s)"),
    QT_TRANSLATE_NOOP("core_text", "the record covers %1 swing periods, under two swing periods: a delay needs at least two whole periods"),
    QT_TRANSLATE_NOOP("core_text", "the table angle covers %1 swing periods, under two swing periods: a delay needs at least two whole periods (at %2 Hz)"),
    QT_TRANSLATE_NOOP("core_text", "duration must be a finite number of seconds, got %1"),
    QT_TRANSLATE_NOOP("core_text", "duration %1 s is over 24 h; split the test into points"),
    QT_TRANSLATE_NOOP("core_text", "settle time must be >= 0 s, got %1"),
    QT_TRANSLATE_NOOP("core_text", "start phase must be finite"),
    QT_TRANSLATE_NOOP("core_text", "the test plan has no test points"),
    QT_TRANSLATE_NOOP("core_text", "rest time between points must be >= 0 s"),
    QT_TRANSLATE_NOOP("core_text", "the test plan has %1 test points; at most %2"),
    QT_TRANSLATE_NOOP("core_text", "%1 turns the table by %2 deg with no rest time to move in; give rest_between_s > 0"),
    QT_TRANSLATE_NOOP("core_text", "the move to test point %1"),
    QT_TRANSLATE_NOOP("core_text", "the return to zero after the last point"),
    QT_TRANSLATE_NOOP("core_text", "%1 (%2 deg in %3 s) exceeds the table's rate or acceleration limit; give rest_between_s >= %4 s"),
    QT_TRANSLATE_NOOP("core_text", "the test plan lasts %1 h in all; at most %2 h (every sample is held in memory): split it into several sessions"),
    QT_TRANSLATE_NOOP("core_text", "%1 (no delay)"),
    QT_TRANSLATE_NOOP("core_text", "no test point gave a delay"),
    QT_TRANSLATE_NOOP("core_text", "the delay or its uncertainty is not a finite number"),
    // analysis::judgePoint/judgeReport: k is the decision rule's coverage factor (decision_rule.h)
    QT_TRANSLATE_NOOP("core_text", "every test point passed its validity checks and its IMU delay + %1σ is below the %2 ms limit"),
    QT_TRANSLATE_NOOP("core_text", "IMU delay %1 ± %2 ms; + %3σ = %4 ms < %5 ms limit (margin %6 ms)"),
    QT_TRANSLATE_NOOP("core_text", "IMU delay %1 ± %2 ms; + %3σ = %4 ms ≥ %5 ms limit (over by %6 ms)"),
    // The text report's decision rule and each point's risk (analysis/decision_rule.h, report_writer.cpp)
    QT_TRANSLATE_NOOP("core_text", "decision rule: PASS when IMU delay + k·σ < limit (k = %1, one-sided guarded acceptance, ISO/IEC 17025:2017 §7.8.6 / ILAC-G8:09/2019); FAIL otherwise; INVALID when a validity check fails; maximum probability of false accept 1 − Φ(k) = %2 (a delay measured just at the acceptance boundary, with a Gaussian error of the stated σ); limit %3 ms"),
    QT_TRANSLATE_NOOP("core_text", "guard band %1σ = %2 ms; probability that the true delay is at or above the limit: %3"),
    QT_TRANSLATE_NOOP("core_text", "no false-accept probability: the delay is refused (INVALID)"),
    QT_TRANSLATE_NOOP("core_text", "no false-accept probability: the run stopped before its plan ended (INCOMPLETE)"),
    // session::decisionRuleProvenance: a row stored before k was kept
    QT_TRANSLATE_NOOP("core_text", "not stored: the rule of that version, k = %1"),
    QT_TRANSLATE_NOOP("core_text", "the gyro turns with the table (gyro/table ratio %1)"),
    QT_TRANSLATE_NOOP("core_text", "the gyro turns with the table (gyro/table ratio %1, after the stated sign -1)"),
    QT_TRANSLATE_NOOP("core_text", "the gyro's %1 axis turns against the table (gyro/table ratio %2): the axis is mounted the other way round or its sign convention differs from the table's; the delay is refused (read as a normal axis it would be a half-period lag). If the IMU is mounted so, state it (metadata bench.gyro_sign {\"%3\": -1}, or --gyro-sign %4=-1) and analyse again"),
    // The gain check (core/analysis/gain_check.cpp): the gyro's scale against the bench's tolerance.
    QT_TRANSLATE_NOOP("core_text", "the gyro's amplitude matches the table's (%1, within %2)"),
    QT_TRANSLATE_NOOP("core_text", "gyro/table ratio %1"),
    QT_TRANSLATE_NOOP("core_text", "gyro/table ratio %1 at %2 Hz, where the fitted %3 response's own gain is %4: scale %5"),
    QT_TRANSLATE_NOOP("core_text", "the gyro reads %1 (%2, outside %3): the pulse equivalent or the frame period is wrong. An increment is its pulse count times the pulse equivalent, or its rate times the IMU's frame period: check both (bench.pulse_equivalent_deg; for imported rates bench.gyro_frame_period_ms or import --frame-period-ms) and analyse again; the delay is refused"),
    QT_TRANSLATE_NOOP("core_text", "the gyro reads %1 (%2, outside %3): its scale is not the one the bench states. A pulse equivalent or frame period slightly off (rounded, or for another gyro) or a gyro outside its scale tolerance: check them and analyse again; the delay is refused. If the gyro's scale is known to be off by this much, state its tolerance (--gain-tolerance)"),
    QT_TRANSLATE_NOOP("core_text", "the gyro reads %1 (%2, outside %3): its scale is not the one the bench states. A pulse equivalent or frame period slightly off (rounded, or for another gyro) or a gyro outside its scale tolerance: check them and analyse again; the delay is refused. If the gyro's own dynamics lower its gain at %4 Hz, measure its frequency response (run --preset response): the check takes out the dynamics fitted there. If the gyro's scale is known to be off by this much, state its tolerance (--gain-tolerance)"),
    QT_TRANSLATE_NOOP("core_text", "%1× the table"),
    QT_TRANSLATE_NOOP("core_text", "1/%1 of the table"),
    QT_TRANSLATE_NOOP("core_text", "%1 % more than the table"),
    QT_TRANSLATE_NOOP("core_text", "%1 % less than the table"),
    QT_TRANSLATE_NOOP("core_text", "not judged: the gyro/table ratio is not a finite number"),
    // session::differencesFromRecord: this version's analysis against a stored result
    QT_TRANSLATE_NOOP("core_text", "test point %1: IMU delay %2 ms stored, %3 ms by this version's analysis"),
    QT_TRANSLATE_NOOP("core_text", "test point %1: %2 stored, %3 by this version's analysis"),
    // its verdicts (analysis::verdictName), as variable parts of the line above
    QT_TRANSLATE_NOOP("core_text", "pass"),
    QT_TRANSLATE_NOOP("core_text", "fail"),
    QT_TRANSLATE_NOOP("core_text", "invalid"),
    QT_TRANSLATE_NOOP("core_text", "test point %1: the stored result has no delay for it; this version's analysis gives one"),
    // session::judgeShown: a point the shown record does not state
    QT_TRANSLATE_NOOP("core_text", "the stored result has no delay for this test point"),
    QT_TRANSLATE_NOOP("core_text", "test point %1: the stored result has a delay; this version's analysis gives none"),
    QT_TRANSLATE_NOOP("core_text", "the gyro's %1 axis turns against the table (gyro/table ratio %2 after the stated sign -1): the axis is mounted the other way round or its sign convention differs from the table's; the delay is refused (read as a normal axis it would be a half-period lag). Check the stated sign: without it the gyro turns with the table"),
    QT_TRANSLATE_NOOP("core_text", "a steady sinusoid: smooth table residual %1, harmonics %2, amplitude change %3, smooth gyro residual %4 of the amplitude"),
    QT_TRANSLATE_NOOP("core_text", "a steady sinusoid: smooth table residual %1, harmonics %2, amplitude change %3 of the amplitude"),
    QT_TRANSLATE_NOOP("core_text", "not a steady sinusoid: %1. The sine fits are biased by such a swing (the noise figures then describe the misfit, not noise); the delay is refused. Check the table's servo and amplitude, and record a steady swing"),
    QT_TRANSLATE_NOOP("core_text", "not a steady sinusoid: %1. The sine fits are biased by such a swing (the noise figures then describe the misfit, not noise); the delay is refused. Check the table's servo and amplitude, and record a steady swing. A damped sinusoid fits the table (decay time %2 s, residual %3 of the amplitude): its lag is %4 ± %5 ms, if the decay is the table's true motion"),
    QT_TRANSLATE_NOOP("core_text", "the table's residual has a smooth part of %1 of the amplitude (limit %2)"),
    QT_TRANSLATE_NOOP("core_text", "harmonics 2-5 reach %1 of the amplitude (limit %2)"),
    QT_TRANSLATE_NOOP("core_text", "the amplitude decays by %1 over the record (limit %2)"),
    QT_TRANSLATE_NOOP("core_text", "the amplitude grows by %1 over the record (limit %2)"),
    QT_TRANSLATE_NOOP("core_text", "the gyro angle's residual has a smooth part of %1 of its amplitude (limit %2)"),
    QT_TRANSLATE_NOOP("core_text", "per-period lag drifts %1 ± %2 ppm (%3 σ)"),
    QT_TRANSLATE_NOOP("core_text", "periods differ by %1 ± %2 ppm (%3 σ)"),
    QT_TRANSLATE_NOOP("core_text", "%1 (information)"),
    QT_TRANSLATE_NOOP("core_text", "not judged: the swing is not a steady sinusoid (steady_sine), which moves the fitted periods and the per-period lags; %1"),
    QT_TRANSLATE_NOOP("core_text", "table and gyro stamps keep one rate: %1"),
    QT_TRANSLATE_NOOP("core_text", "the gyro's time stamps run %1 ppm fast against the table's (%2): the two streams are not stamped on one clock at one rate, so their phase difference is not a delay. Stamp both with the sampling board's common counter (or correct the clock rate) and record again"),
    QT_TRANSLATE_NOOP("core_text", "the gyro's time stamps run %1 ppm slow against the table's (%2): the two streams are not stamped on one clock at one rate, so their phase difference is not a delay. Stamp both with the sampling board's common counter (or correct the clock rate) and record again"),
    QT_TRANSLATE_NOOP("core_text", "the IMU delay is negative (%1 ± %2 ms): the gyro would report rotation before it happened. A stamping, sign or clock problem: check the table read delay constant, that both streams share one clock, and the gyro axis' sign"),
    QT_TRANSLATE_NOOP("core_text", "the IMU delay is causal (%1 ms)"),
    QT_TRANSLATE_NOOP("core_text", "'%1' is empty (0 bytes), not a fogbench session; it was never written"),
    QT_TRANSLATE_NOOP("core_text", "'%1' is not a fogbench session (not an SQLite database)"),
    QT_TRANSLATE_NOOP("core_text", "'%1' is not a fogbench session"),
    QT_TRANSLATE_NOOP("core_text", "'%1' is a folder, not a fogbench session file"),
    QT_TRANSLATE_NOOP("core_text", "cannot open session '%1': no such file; check the path"),
    QT_TRANSLATE_NOOP("core_text", "the stream does not state its gyro pulse equivalent (degrees per pulse): give --pulse-equivalent-deg or set it in the bench constants"),
    QT_TRANSLATE_NOOP("core_text", "session '%1': the stream does not state its gyro pulse equivalent (degrees per pulse): give --pulse-equivalent-deg or set it in the bench constants"),
    QT_TRANSLATE_NOOP("core_text", "'%1' is truncated: it holds %2 of its %3 bytes; copy it again from the original or restore a backup"),
    QT_TRANSLATE_NOOP("core_text", "'%1' is truncated: it holds %2 of its %3 bytes; copy it again from the original or restore a backup (its -wal does not hold the missing pages)"),
    QT_TRANSLATE_NOOP("core_text", "'%1' is an SQLite database but not a fogbench session (application_id %2)"),
    QT_TRANSLATE_NOOP("core_text", "'%1' is a fogbench session whose SQLite header (its first 100 bytes) is damaged; it is not analysed as a raw stream. Restore it from a backup, or repair a copy: printf 'SQLite format 3\\0' | dd of=COPY.fbs conv=notrunc (when only the header's first bytes were hit, the copy opens again)"),
    QT_TRANSLATE_NOOP("core_text", "'%1' is a fogbench session whose first page (the SQLite header and the list of its tables, 4 KiB) is damaged; it is not analysed as a raw stream (the stream inside is cut into database pages). Restore it from a backup"),
    QT_TRANSLATE_NOOP("core_text", "%1 is %2, not %3: only regular files are read (a pipe or a device may never end); copy the data into a file first"),
    QT_TRANSLATE_NOOP("core_text", "%1 (a link to %2) is %3, not %4: only regular files are read (a pipe or a device may never end); copy the data into a file first"),
    QT_TRANSLATE_NOOP("core_text", "a FIFO (named pipe)"),
    QT_TRANSLATE_NOOP("core_text", "a device"),
    QT_TRANSLATE_NOOP("core_text", "a fogbench session file"),
    QT_TRANSLATE_NOOP("core_text", "a raw sampling-board stream"),
    QT_TRANSLATE_NOOP("core_text", "a plan file"),
    QT_TRANSLATE_NOOP("core_text", "%1 holds %2 bytes, more than the %3 that %4 may hold (docs/reliability.md): split the recording"),
    QT_TRANSLATE_NOOP("core_text", "the fits gave no finite %1 (%2): the data hold values the sine model cannot fit; check the recording's units and values"),
    QT_TRANSLATE_NOOP("core_text", "the run reached its memory budget of %1 table and IMU samples after %2 s; everything recorded is kept"),
    QT_TRANSLATE_NOOP("core_text", "no verdict: %1, not a finite number, so real and simulated data cannot be compared"),
    QT_TRANSLATE_NOOP("core_text", "undetermined"),
    QT_TRANSLATE_NOOP("core_text", "static segment %1: the %2 gyro's %3 increments are all %4 deg: no noise to analyse (a dead or disconnected axis, or a file of constants)"),
    QT_TRANSLATE_NOOP("core_text", "Markov (correlated) rate"),
    QT_TRANSLATE_NOOP("core_text", "deg"),
    QT_TRANSLATE_NOOP("core_text", "the replay cannot reach the measured lag exactly"),
    QT_TRANSLATE_NOOP("core_text", "heading %1 +- %2 deg, from the Earth rate the gyros see as the table turns"),
    QT_TRANSLATE_NOOP("core_text",
                      "heading %1 +- %2 deg, from the Earth rate the gyros see as the table turns; %3 is taken >= 0: "
                      "the plan's swings do not show its sign"),
    QT_TRANSLATE_NOOP("core_text", "left out: %1"),
    // The IMU's frame (core/common/imu_frame.h) and the diagnosis' check of it.
    QT_TRANSLATE_NOOP("core_text", "not stated"),
    QT_TRANSLATE_NOOP("core_text", "north-east-down (x north, y east, z down)"),
    QT_TRANSLATE_NOOP("core_text", "east-north-up (x east, y north, z up)"),
    QT_TRANSLATE_NOOP("core_text", "forward-right-down (x forward, y right, z down)"),
    QT_TRANSLATE_NOOP("core_text", "right-forward-up (x right, y forward, z up)"),
    QT_TRANSLATE_NOOP("core_text", "%1, forward at %2 deg from north"),
    QT_TRANSLATE_NOOP("core_text", "up"),
    QT_TRANSLATE_NOOP("core_text", "down"),
    QT_TRANSLATE_NOOP("core_text", "the IMU's frame was not checked: the plan gives too few gyro trend and cross-axis cells"),
    QT_TRANSLATE_NOOP("core_text", "the IMU's frame was not checked: the plan's swings do not turn the Earth rate between the gyros"),
    QT_TRANSLATE_NOOP("core_text", "the IMU's frame was not checked: the plan's swings do not turn the vertical Earth rate between the gyros"),
    QT_TRANSLATE_NOOP("core_text", "the stated frame is used"),
    QT_TRANSLATE_NOOP("core_text", "z down is assumed: state the IMU's frame"),
    QT_TRANSLATE_NOOP("core_text", "the data cannot tell the IMU's z axis up from down (vertical Earth rate %1 +- %2 of the z-%3 frame's)"),
    QT_TRANSLATE_NOOP("core_text", "the data show the IMU's z axis %1 (vertical Earth rate %2 +- %3 of the z-%4 frame's)"),
    QT_TRANSLATE_NOOP("core_text", "the data show the IMU's z axis %1 (vertical Earth rate %2 +- %3 of the z-%4 frame's), as the bench constants state"),
    QT_TRANSLATE_NOOP("core_text", "the bench constants state %1: the replays use the frame the data show"),
    QT_TRANSLATE_NOOP("core_text", "the bench constants do not state the IMU's frame, so the replays use the one found: state it in the bench constants (a latitude of the wrong sign looks the same)"),
    QT_TRANSLATE_NOOP("core_text", "a latitude of the wrong sign looks the same"),
    QT_TRANSLATE_NOOP("core_text", "a latitude of the wrong sign (the other hemisphere) looks the same: check it too"),
    QT_TRANSLATE_NOOP("core_text", "the heading the data show, %1 deg, is %2 deg from the stated frame's (%3 deg for x): check the bench's heading"),
    QT_TRANSLATE_NOOP("core_text", "the replays use the one found"),
    QT_TRANSLATE_NOOP("core_text", "the IMU's frame contradicts the data (no effect named)"),
    QT_TRANSLATE_NOOP("core_text", "the data show the IMU's z axis %1"),
    QT_TRANSLATE_NOOP("core_text", "the bench constants state %1 (%2). Correct the IMU frame in the bench constants (or the IMU's mounting) and diagnose again"),
    QT_TRANSLATE_NOOP("core_text", "no effect is named. Replayed in the frame the data show, the verdict would be: %1"),
    // The table's limits, checked before any motion (core/table).
    QT_TRANSLATE_NOOP("core_text", "%1 position is not a number"),
    QT_TRANSLATE_NOOP("core_text", "%1 position %2 deg is beyond the table's +-%3 deg"),
    QT_TRANSLATE_NOOP("core_text", "the table was not moved"),
    // The C library's texts of the system errors a bench meets (strerror,
    // glibc), quoted inside the core's reasons.
    QT_TRANSLATE_NOOP("core_text", "Operation not permitted"),
    QT_TRANSLATE_NOOP("core_text", "No such file or directory"),
    QT_TRANSLATE_NOOP("core_text", "Interrupted system call"),
    QT_TRANSLATE_NOOP("core_text", "Input/output error"),
    QT_TRANSLATE_NOOP("core_text", "No such device or address"),
    QT_TRANSLATE_NOOP("core_text", "Bad file descriptor"),
    QT_TRANSLATE_NOOP("core_text", "Resource temporarily unavailable"),
    QT_TRANSLATE_NOOP("core_text", "Permission denied"),
    QT_TRANSLATE_NOOP("core_text", "Device or resource busy"),
    QT_TRANSLATE_NOOP("core_text", "File exists"),
    QT_TRANSLATE_NOOP("core_text", "No such device"),
    QT_TRANSLATE_NOOP("core_text", "Not a directory"),
    QT_TRANSLATE_NOOP("core_text", "Is a directory"),
    QT_TRANSLATE_NOOP("core_text", "Invalid argument"),
    QT_TRANSLATE_NOOP("core_text", "Too many open files in system"),
    QT_TRANSLATE_NOOP("core_text", "Too many open files"),
    QT_TRANSLATE_NOOP("core_text", "Inappropriate ioctl for device"),
    QT_TRANSLATE_NOOP("core_text", "File too large"),
    QT_TRANSLATE_NOOP("core_text", "No space left on device"),
    QT_TRANSLATE_NOOP("core_text", "Read-only file system"),
    QT_TRANSLATE_NOOP("core_text", "Broken pipe"),
    QT_TRANSLATE_NOOP("core_text", "File name too long"),
    QT_TRANSLATE_NOOP("core_text", "Too many levels of symbolic links"),
    QT_TRANSLATE_NOOP("core_text", "Disk quota exceeded"),
    QT_TRANSLATE_NOOP("core_text", "Connection refused"),
    QT_TRANSLATE_NOOP("core_text", "Connection reset by peer"),
    QT_TRANSLATE_NOOP("core_text", "Connection timed out"),
    QT_TRANSLATE_NOOP("core_text", "No route to host"),
    QT_TRANSLATE_NOOP("core_text", "Network is unreachable"),
    QT_TRANSLATE_NOOP("core_text", "Address already in use"),
    QT_TRANSLATE_NOOP("core_text", "Transport endpoint is not connected"),
    QT_TRANSLATE_NOOP("core_text", "Text file busy"),
    QT_TRANSLATE_NOOP("core_text", "Cannot allocate memory"),
    QT_TRANSLATE_NOOP("core_text", "cannot create session '%1': %2; check the folder exists and is writable"),
    QT_TRANSLATE_NOOP("core_text", "bias instability %1 deg/h over %2 s assumed (the simulator's default): a bias drift or step within such a wander is not resolved; state the IMU's own (its static noise test) for a sharper test of the gyro trends"),
    QT_TRANSLATE_NOOP("core_text", "ran on %1 of the %2 threads asked for, to stay within the %3 MB memory limit"),
    QT_TRANSLATE_NOOP("core_text", "the Ceres fit on the forward model failed (%1); linear fit kept"),
    QT_TRANSLATE_NOOP("core_text", "fogbench delay report"),
    QT_TRANSLATE_NOOP("core_text", "source: session %1 (%2)"),
    QT_TRANSLATE_NOOP("core_text", "source: %1"),
    QT_TRANSLATE_NOOP("core_text", "verdict: %1"),
    QT_TRANSLATE_NOOP("core_text", "verdict: %1 (delay refused)"),
    QT_TRANSLATE_NOOP("core_text", "PASS"),
    QT_TRANSLATE_NOOP("core_text", "FAIL"),
    QT_TRANSLATE_NOOP("core_text", "INVALID"),
    QT_TRANSLATE_NOOP("core_text", "INCOMPLETE"),
    QT_TRANSLATE_NOOP("core_text", "Stored verdict: %1, against the stored limit of %2 ms"),
    QT_TRANSLATE_NOOP("core_text", "Stored verdict: %1 (the data recorded give %2), against the stored limit of %3 ms"),
    QT_TRANSLATE_NOOP("core_text", "This version's analysis of the same data with the same settings differs from the stored result:"),
    QT_TRANSLATE_NOOP("core_text", "This version's analysis with the stored result's settings (plots and fits):"),
    QT_TRANSLATE_NOOP("core_text", "INCOMPLETE RUN: %1"),
    QT_TRANSLATE_NOOP("core_text", "stream: %1 table, %2 IMU, %3 status frames; %4 checksum failures, %5 lost, %6 duplicated, %7 bytes skipped"),
    QT_TRANSLATE_NOOP("core_text", "bench constants: table read delay %1 ± %2 ms, board delay %3 ± %4 ms"),
    QT_TRANSLATE_NOOP("core_text", "gyro signs: %1 (-1: the gyro axis counts against the table's); IMU frame: %2"),
    QT_TRANSLATE_NOOP("core_text", "Test point %1: %2 axis, %3 Hz / %4 deg, %5 s (%6 periods)"),
    QT_TRANSLATE_NOOP("core_text", "fits (angle = A sin(2 pi (t - t0) / T); t0 is the phase):"),
    QT_TRANSLATE_NOOP("core_text", "%1 period %2 (nominal) ms phase %3 ± %4 ms amplitude %5 deg"),
    QT_TRANSLATE_NOOP("core_text", "%1 period %2 ± %3 ms phase %4 ± %5 ms amplitude %6 deg"),
    QT_TRANSLATE_NOOP("core_text", "table 3-parameter"),
    QT_TRANSLATE_NOOP("core_text", "gyro 3-parameter"),
    QT_TRANSLATE_NOOP("core_text", "table 4-parameter"),
    QT_TRANSLATE_NOOP("core_text", "gyro 4-parameter"),
    QT_TRANSLATE_NOOP("core_text", "joint fit: frequency %1 Hz, gyro/table amplitude %2, trend %3 deg/s (%4 deg/h), chi2/dof %5"),
    QT_TRANSLATE_NOOP("core_text", "delay:"),
    QT_TRANSLATE_NOOP("core_text", "measured lag (gyro behind table) %1 ± %2 ms (CRLB %3 ms, std/CRLB %4)"),
    QT_TRANSLATE_NOOP("core_text", "uncertainty from %1 (fit alone %2 ms, per-period scatter %3 ms)"),
    QT_TRANSLATE_NOOP("core_text", "fit, with errors that repeat every period"),
    QT_TRANSLATE_NOOP("core_text", "per-period scatter, with errors that repeat every period"),
    QT_TRANSLATE_NOOP("core_text", "fit, less the errors that cancel between periods"),
    QT_TRANSLATE_NOOP("core_text", "per-period scatter, less the errors that cancel between periods"),
    QT_TRANSLATE_NOOP("core_text", "per-period scatter"),
    QT_TRANSLATE_NOOP("core_text", "fit, random walk at its upper bound (fewer than 5 periods to check it)"),
    QT_TRANSLATE_NOOP("core_text", "+ table read delay %1 ms"),
    QT_TRANSLATE_NOOP("core_text", "= IMU delay %1 ± %2 ms"),
    QT_TRANSLATE_NOOP("core_text", "- processing board delay %1 ms"),
    QT_TRANSLATE_NOOP("core_text", "= gyro's own delay %1 ± %2 ms"),
    QT_TRANSLATE_NOOP("core_text", "simulator truth: lag %1 ms (error %2 ms = %3 std)"),
    QT_TRANSLATE_NOOP("core_text", "per-period delay: %1 periods, mean %2 ms, scatter %3 ms"),
    QT_TRANSLATE_NOOP("core_text", "noise: encoder %1 deg, pulse output %2 deg, angle random walk %3 deg/sqrt(h) (near the swing frequency %4)"),
    QT_TRANSLATE_NOOP("core_text", "lost IMU frames: %1"),
    QT_TRANSLATE_NOOP("core_text", "affected: %1 table and %2 IMU frames lost, %3 duplicated, %4 checksum failures, %5 bytes skipped; data cover %6 of %7 s (%8 %), longest gap %9 ms"),
    QT_TRANSLATE_NOOP("core_text", "warning: %1"),
    QT_TRANSLATE_NOOP("core_text", "checks:"),
    QT_TRANSLATE_NOOP("core_text", "ok %1: %2"),
    QT_TRANSLATE_NOOP("core_text", "FAILED %1: %2"),
    QT_TRANSLATE_NOOP("core_text", "n/a %1: %2"),
    QT_TRANSLATE_NOOP("core_text", "Test point %1: static segment, %2 axis, %3 s at rest: no delay to measure (gyro noise: fogbench-cli noise)"),
    QT_TRANSLATE_NOOP("core_text", "no delay from %1"),
    QT_TRANSLATE_NOOP("core_text", "Delay against frequency, %1 axis (%2 frequencies): weighted lag %3 ± %4 ms, chi2 %5 on %6 dof, p = %7: %8"),
    QT_TRANSLATE_NOOP("core_text", "consistent with a pure delay"),
    QT_TRANSLATE_NOOP("core_text", "NOT a pure delay (frequency-dependent: lag, filtering or dynamics)"),
    QT_TRANSLATE_NOOP("core_text", "the table swung at %1 Hz, not the planned %2 Hz; fitting from the measured frequency"),
    QT_TRANSLATE_NOOP("core_text", "the per-period lags scatter %1 ms, more than the fit's noise model implies; the uncertainty rests on their scatter (%2 ms instead of %3 ms)"),
    QT_TRANSLATE_NOOP("core_text", "the per-period lags scatter %1 ms, less than the fit's noise model implies; the uncertainty rests on their scatter (%2 ms instead of %3 ms)"),
    QT_TRANSLATE_NOOP("core_text", "%1 IMU frames were lost; their increments are missing"),
    QT_TRANSLATE_NOOP("core_text", "%1 table frames were lost; the data cover %2 of %3 s (longest gap %4 ms)"),
    QT_TRANSLATE_NOOP("core_text", "the residuals do not match the noise model (chi^2/dof = %1); an unmodelled effect may be present"),
    QT_TRANSLATE_NOOP("core_text", "the table swung %1 deg, not the planned %2 deg"),
    QT_TRANSLATE_NOOP("core_text", "the gyro's own delay is negative: the processing board delay (%1 ms) is larger than the IMU delay; check that constant"),
    QT_TRANSLATE_NOOP("core_text", "axis_sign"),
    QT_TRANSLATE_NOOP("core_text", "steady_sine"),
    QT_TRANSLATE_NOOP("core_text", "clock_rate"),
    QT_TRANSLATE_NOOP("core_text", "causal"),
    QT_TRANSLATE_NOOP("core_text", "uncertainty_below_bound"),
    QT_TRANSLATE_NOOP("core_text", "σ %1 ms is %2 of the Cramér–Rao bound %3 ms (%4, %5 degrees of freedom; at least %6 expected)"),
    QT_TRANSLATE_NOOP("core_text", "σ %1 ms is %2 of the Cramér–Rao bound %3 ms; before the errors that cancel between periods, which the bound's white noise does not see, %4 ms, %5 of it (%6, %7 degrees of freedom; at least %8 expected)"),
    QT_TRANSLATE_NOOP("core_text", "the stated uncertainty is below what the noise allows: %1. No estimate of the lag scatters less than the bound; the σ is understated and the delay is not vouched for. Record more periods, or check the noise model (docs/method.md)"),
    QT_TRANSLATE_NOOP("core_text", "not judged: the Cramér–Rao bound of this session's noise is not known"),
    QT_TRANSLATE_NOOP("core_text", "fit"),
    QT_TRANSLATE_NOOP("core_text", "measured lag (gyro behind table) %1 ± %2 ms (CRLB %3 ms, std/CRLB %4: BELOW THE BOUND, the σ is understated (uncertainty_below_bound))"),
    QT_TRANSLATE_NOOP("core_text", "%1, fogbench %2"),
    // The frequency response's notes (core/analysis/frequency_response.cpp).
    QT_TRANSLATE_NOOP("core_text", "the -3 dB bandwidth %1 Hz lies beyond the highest point (%2 Hz): an extrapolation of the model"),
    QT_TRANSLATE_NOOP("core_text", "%1 and %2 correlate at %3: the points barely separate them (the low-frequency delay %4 ± %5 ms is better determined than either)"),
    QT_TRANSLATE_NOOP("core_text", "%1 = %2 ± %3 is not distinguished from 0 by these points"),
    QT_TRANSLATE_NOOP("core_text", "%1: %2 parameters need more than %3 values, %4 points give %5"),
    QT_TRANSLATE_NOOP("core_text", "%1: no fit from any of its %2 starting points (%3); the points may not hold such a filter"),
    QT_TRANSLATE_NOOP("core_text", "the fit did not converge in %1 iterations"),
    QT_TRANSLATE_NOOP("core_text", "%1: its best fit has 1/wn^2 = %2 ms^2, not above 0: the points hold no resonance (the first-order lag, T = %3 ms, is its limit)"),
    QT_TRANSLATE_NOOP("core_text", "%1: its best fit has 1/wn^2 = %2 ms^2, not above 0: the points hold no resonance (a magnitude droop without a filter's phase, as an average over about %3 ms would give)"),
    QT_TRANSLATE_NOOP("core_text", "AIC prefers it to %1 by %2, but it lowers chi^2 by %3 only (1 more parameter claimed at %4, 3 sigma): %5 is chosen"),
    QT_TRANSLATE_NOOP("core_text", "AIC prefers it to %1 by %2, but it lowers chi^2 by %3 only (%4 more parameters claimed at %5, 3 sigma): %6 is chosen"),
    // Each model judged before one is chosen (issue 40).
    QT_TRANSLATE_NOOP("core_text", "no model fits: %1"),
    QT_TRANSLATE_NOOP("core_text", "no model fits: none could be fitted"),
    QT_TRANSLATE_NOOP("core_text", "%1 is not adequate: chi^2 %2 on %3 dof, p = %4 below %5"),
    QT_TRANSLATE_NOOP("core_text", "%1 is not admissible: %2"),
    QT_TRANSLATE_NOOP("core_text", "%1 = %2 ± %3 ms is negative beyond 3 sigma: the gyro would answer before the table moves"),
    QT_TRANSLATE_NOOP("core_text", "%1 = %2 ± %3 ms is negative beyond 3 sigma: a lead, not a lag"),
    QT_TRANSLATE_NOOP("core_text", "the low-frequency delay %1 ± %2 ms is negative beyond 3 sigma: the gyro would answer before the table moves"),
    QT_TRANSLATE_NOOP("core_text", "%1 = %2 ± %3 ms is below -%4 ms (minus the table read delay) beyond 3 sigma: the gyro would answer before the table moves"),
    QT_TRANSLATE_NOOP("core_text", "the low-frequency delay %1 ± %2 ms is below -%3 ms (minus the table read delay) beyond 3 sigma: the gyro would answer before the table moves"),
    QT_TRANSLATE_NOOP("core_text", "%1 = %2 ± %3 sits at its bound 0 within 3 sigma: the points do not place the resonance"),
    QT_TRANSLATE_NOOP("core_text", "the fit ran past zeta = 0: its poles are unstable (a lead that grows to the resonance)"),
    QT_TRANSLATE_NOOP("core_text", "the pure delay"),
    QT_TRANSLATE_NOOP("core_text", "the first-order lag"),
    QT_TRANSLATE_NOOP("core_text", "the second-order response"),
    QT_TRANSLATE_NOOP("core_text", "the fit's sums are not finite numbers (a value in the data is far beyond its range)"),
    QT_TRANSLATE_NOOP("core_text", "the fit's parameters are not determined by the data"),
    QT_TRANSLATE_NOOP("core_text", "the fit's covariance is not positive"),
    // The response models' names and parameters (the model "delay" is above).
    QT_TRANSLATE_NOOP("core_text", "first_order"),
    QT_TRANSLATE_NOOP("core_text", "second_order"),
    QT_TRANSLATE_NOOP("core_text", "tau_ms"),
    QT_TRANSLATE_NOOP("core_text", "T_ms"),
    QT_TRANSLATE_NOOP("core_text", "fn_hz"),
    QT_TRANSLATE_NOOP("core_text", "zeta"),
    // core/catalog: a catalog's description, who analysed a result, the
    // lot statistics' limit source and definitions (catalog.h).
    QT_TRANSLATE_NOOP("core_text", "SQLite catalog %1"),
    QT_TRANSLATE_NOOP("core_text", "PostgreSQL catalog %1"),
    QT_TRANSLATE_NOOP("core_text", "not recorded"),
    QT_TRANSLATE_NOOP("core_text", "stored"),
    QT_TRANSLATE_NOOP("core_text", "given"),
    QT_TRANSLATE_NOOP("core_text", "units whose latest session's shown result is PASS, over units"),
    QT_TRANSLATE_NOOP("core_text", "units whose first session's shown result is PASS, over units"),
    QT_TRANSLATE_NOOP("core_text", "over the vouched test points (PASS or FAIL) of shown PASS or FAIL results; "
                                   "INVALID and INCOMPLETE results are counted, never averaged"),
    QT_TRANSLATE_NOOP("core_text", "(limit - mean) / (3 s), one-sided: the IMU delay has an upper limit only"),
};

struct Template {
  const char* source;
  QRegularExpression strict;   // variable parts without "; " (a list of reasons is split first)
  QRegularExpression relaxed;  // variable parts of any text
  std::vector<int> placeholders;  // the placeholder number of each capture group, in order
  int literalLength = 0;          // characters other than spaces outside the placeholders: more is more specific
};

// "%1 closes %2 %" -> ^(.*?)\s+closes\s+(.*?)\s+%$ ; runs of spaces match any
// run of white space (the core aligns columns with them). The strict pattern
// keeps "; " out of the variable parts: "A: %1" must not swallow "A: x; B: y".
Template compile(const char* source) {
  static const QRegularExpression placeholder(QStringLiteral("%(\\d+)"));
  static const QRegularExpression spaces(QStringLiteral(" +"));
  const QString text = QString::fromUtf8(source);
  Template t{source, {}, {}, {}, 0};
  QString re = QStringLiteral("^");
  QString strict = re;
  auto literal = [&](const QString& piece) {
    const QStringList words = piece.split(spaces);
    for (const QString& w : words) t.literalLength += static_cast<int>(w.size());
    QStringList escaped;
    for (const QString& w : words) escaped << QRegularExpression::escape(w);
    re += escaped.join(QStringLiteral("\\s+"));
    strict += escaped.join(QStringLiteral("\\s+"));
  };
  Size last = 0;
  for (auto it = placeholder.globalMatch(text); it.hasNext();) {
    const auto m = it.next();
    literal(text.mid(last, m.capturedStart() - last));
    re += QStringLiteral("(.*?)");
    strict += QStringLiteral("((?:(?!; ).)*?)");
    t.placeholders.push_back(m.captured(1).toInt());
    last = m.capturedEnd();
  }
  literal(text.mid(last));
  re += QStringLiteral("$");
  strict += QStringLiteral("$");
  t.relaxed = QRegularExpression(re, QRegularExpression::DotMatchesEverythingOption);
  t.strict = QRegularExpression(strict, QRegularExpression::DotMatchesEverythingOption);
  return t;
}

// Compiled once; the most specific (most literal characters) first, so that a
// general template ("%1 (after %2 s)") never takes a message a specific one
// describes.
const std::vector<Template>& templates() {
  static const std::vector<Template> all = [] {
    std::vector<Template> out;
    for (const char* s : kTemplates) out.push_back(compile(s));
    std::stable_sort(out.begin(), out.end(),
                     [](const Template& a, const Template& b) { return a.literalLength > b.literalLength; });
    return out;
  }();
  return all;
}

constexpr int kMaxDepth = 12;  // variable parts within variable parts (a list of six parameters is six deep)

QString translatePart(const QString& text, int depth);

// One message without line breaks; leading and trailing white space kept.
QString translateMessage(const QString& text, int depth) {
  Size begin = 0, end = text.size();
  while (begin < end && text[begin].isSpace()) ++begin;
  while (end > begin && text[end - 1].isSpace()) --end;
  if (begin >= end) return text;
  return text.left(begin) + translatePart(text.mid(begin, end - begin), depth) + text.mid(end);
}

// The first template (most specific first) whose pattern matches, translated
// with its variable parts; an empty string when none matches.
QString translateWith(const QString& text, int depth, QRegularExpression Template::*pattern) {
  for (const Template& t : templates()) {
    const auto m = (t.*pattern).match(text);
    if (!m.hasMatch()) continue;
    const QString translated = QCoreApplication::translate("core_text", t.source);
    if (translated == QString::fromUtf8(t.source)) return text;  // no translation: as the core wrote it
    QString out = translated;
    // Highest placeholder numbers first: %10 before %1.
    std::vector<std::size_t> order(t.placeholders.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t.placeholders[a] > t.placeholders[b]; });
    for (std::size_t i : order)
      out.replace(QStringLiteral("%") + QString::number(t.placeholders[i]),
                  translateMessage(m.captured(static_cast<int>(i) + 1), depth + 1));
    return out;
  }
  return {};
}

QString translatePart(const QString& text, int depth) {
  if (depth > kMaxDepth) return text;
  if (QString out = translateWith(text, depth, &Template::strict); !out.isEmpty()) return out;
  // A list of reasons joined by "; ", when each of them is a message of its own.
  if (text.contains(QStringLiteral("; "))) {
    QStringList parts = text.split(QStringLiteral("; "));
    bool all = true;
    for (QString& p : parts) {
      const QString t = translateMessage(p, depth + 1);
      all = all && t != p;
      p = t;
    }
    if (all) return parts.join(QStringLiteral("；"));
  }
  if (QString out = translateWith(text, depth, &Template::relaxed); !out.isEmpty()) return out;
  return text;
}

}  // namespace

// The response models' parameter keys (the JSON's) as the GUI names them in
// every language: the symbols.
static QString displaySymbols(QString text) {
  static const std::vector<std::pair<QRegularExpression, QString>> kSymbols = [] {
    std::vector<std::pair<QRegularExpression, QString>> out;
    for (const auto& s : analysis::responseParameterSymbols())
      if (std::string_view(s.key) != s.symbol)
        out.emplace_back(QRegularExpression(QStringLiteral("\\b") + QString::fromUtf8(s.key) + QStringLiteral("\\b")),
                         QString::fromUtf8(s.symbol));
    return out;
  }();
  for (const auto& [pattern, symbol] : kSymbols) text.replace(pattern, symbol);
  return text;
}

QString coreText(const QString& english) {
  QStringList lines = english.split(QLatin1Char('\n'));
  for (QString& line : lines) line = translateMessage(line, 0);
  return displayUnits(displaySymbols(lines.join(QLatin1Char('\n'))));
}

QString coreText(const std::string& english) { return coreText(QString::fromStdString(english)); }

QString coreText(const char* english) { return coreText(QString::fromUtf8(english)); }

QString displayUnits(const QString& text) {
  static const QRegularExpression per(QStringLiteral("\\bdeg/"));
  static const QRegularExpression squared(QStringLiteral("/s\\^2\\b"));
  static const QRegularExpression root(QStringLiteral("sqrt\\(h\\)"));
  static const QRegularExpression angle(QStringLiteral("(\\d) ?deg\\b"));
  QString out = text;
  out.replace(per, QStringLiteral("°/"));
  out.replace(squared, QStringLiteral("/s²"));
  out.replace(root, QStringLiteral("√h"));
  out.replace(angle, QStringLiteral("\\1°"));
  return out;
}

}  // namespace fog::ui
