#!/usr/bin/python3
"""fast_vs_reference: fogbench's fast simulator against the reference one.

The reference (refgen.py) integrates the body rate on a 10 kHz grid with full
rotation matrices and shares no code with core/model; the fast simulator
(fogbench-cli run) uses exact motion and per-frame sensing. Each case below
runs one stage or effect in both, noise off and quanta far below the effects
(pulses and encoder steps of 1e-6 / 1e-7 deg), and compares what an analysis
sees, fitted here in numpy the same way for both recordings:

  delay_us    gyro behind table on the swing axis (phase of the fundamental)
  gain_ppm    gyro / table amplitude - 1 on the swing axis
  cross_*     the other gyros' fundamental, in phase and in quadrature with
              the table angle, ppm of its amplitude
  h2_*        second harmonic of each gyro, ppm of the table amplitude
  trend_*     each gyro's mean rate, deg/h
  ramp_*      each gyro's rate ramp, deg/h per min
  table_h2_*, table_h3_*
              the table angle's 2nd and 3rd harmonics, in phase and in
              quadrature with its fundamental, ppm of its amplitude
  interval_*  the mean interval between table readings and between gyro
              frames (their stamps), ppm off the nominal 1 ms and 2 ms: the
              sign of a clock error (an IMU crystal > 0 runs fast, shorter
              frames) must be one in both simulators

The effects of the diagnosis' library that act on the motion, the rate or
the encoder are cases too, each in both simulators at a size the figures
resolve; timestamp jitter and dropped frames are random and clock drift is
a matter of the time origin, so the blind check (blind_reference.py)
covers those.

Every figure must agree within the case's tolerance (docs/simulator.md gives
the table of tolerances and measured differences). Exit status 1 on any
disagreement; --table prints the measured differences as markdown.
"""

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import refgen  # noqa: E402

AXES = "xyz"
IMU_DELAY_MS = 0.5
READ_DELAY_MS = 0.05
BOARD_DELAY_MS = 0.28  # the fast simulator's processing + 31-byte frame at 1 Mbaud

# name: (description, swing, geometry/site, effects, tolerances)
CASES = {
    "earth_rate_x": dict(
        what="Earth rate turning in the body frame: X swing 0.2 Hz / 10 deg, latitude 40, heading 30",
        axis="x", f=0.2, a=10.0, d=50.0, pos=[0, 0, 0], lat=40.0, heading=30.0),
    "earth_rate_z": dict(
        what="Earth rate, vertical axis: Z swing 0.2 Hz / 10 deg, heading 75",
        axis="z", f=0.2, a=10.0, d=50.0, pos=[0, 0, 0], lat=40.0, heading=75.0),
    "geometry": dict(
        what="table geometry: Y swing 0.5 Hz / 5 deg about 5 deg, X held at 30, Z at 45 (axis order zyx)",
        axis="y", f=0.5, a=5.0, d=40.0, pos=[30, 5, 45], lat=40.0, heading=60.0),
    "imu_clock": dict(
        what="IMU crystal +40 ppm: X swing 1 Hz / 3 deg",
        axis="x", f=1.0, a=3.0, d=30.0, pos=[0, 0, 0], lat=40.0, heading=0.0, imu_ppm=40.0),
    "lag_0.3ms": dict(
        what="first-order lag 0.3 ms: X swing 1 Hz / 3 deg",
        axis="x", f=1.0, a=3.0, d=30.0, pos=[0, 0, 0], lat=40.0, heading=0.0, lag_ms=0.3),
    "lag_5ms": dict(
        what="first-order lag 5 ms: X swing 2 Hz / 2 deg",
        axis="x", f=2.0, a=2.0, d=20.0, pos=[0, 0, 0], lat=40.0, heading=0.0, lag_ms=5.0),
    "misalignment": dict(
        what="misalignment m = (100, -50, 200, 80, -150, 60) urad: Y swing 1 Hz / 3 deg",
        axis="y", f=1.0, a=3.0, d=30.0, pos=[0, 0, 0], lat=40.0, heading=0.0,
        mis=[100.0, -50.0, 200.0, 80.0, -150.0, 60.0]),
    "g_sensitivity": dict(
        what="g-sensitivity 50 deg/h/g along each gyro: X swing 0.1 Hz / 10 deg about 20 deg, Y at -15",
        axis="x", f=0.1, a=10.0, d=60.0, pos=[20, -15, 0], lat=40.0, heading=0.0, gsens=50.0),
    # The library's other effects: (fogbench-cli run --effect, refgen parameters).
    "scale_factor_error": dict(
        what="scale-factor error 300 ppm: X swing 1 Hz / 3 deg",
        axis="x", f=1.0, a=3.0, d=30.0, pos=[0, 0, 0], lat=40.0, heading=0.0,
        effect=("scale_factor_error=300", {"scale_factor_ppm": 300.0})),
    "scale_factor_asymmetry": dict(
        what="scale-factor asymmetry (K+ - K-) / Kbar = 600 ppm (IEEE Std 528): X swing 1 Hz / 3 deg",
        axis="x", f=1.0, a=3.0, d=30.0, pos=[0, 0, 0], lat=40.0, heading=0.0,
        # refgen: K+ = Kbar (1 + a/2) on positive rates, K- = Kbar (1 - a/2) on negative ones
        effect=("scale_factor_asymmetry=600", {"sf_asymmetry_ieee_ppm": 600.0})),
    "scale_factor_nonlinearity": dict(
        what="scale-factor nonlinearity 400 ppm of full scale over +-100 deg/s (IEEE Std 528, least-squares "
             "line): X swing 2 Hz / 5 deg (63 deg/s)",
        axis="x", f=2.0, a=5.0, d=20.0, pos=[0, 0, 0], lat=40.0, heading=0.0,
        # refgen: the least-squares line (1 + 1.5 N) w plus N 100 P3(w / 100)
        effect=("scale_factor_nonlinearity=400", {"sf_nonlinearity_ieee_ppm": 400.0})),
    "bias_drift": dict(
        what="bias ramp 2 deg/h per min on every gyro: X swing 1 Hz / 3 deg",
        axis="x", f=1.0, a=3.0, d=30.0, pos=[0, 0, 0], lat=40.0, heading=0.0,
        effect=("bias_drift=2", {"bias_drift_deg_h_per_min": 2.0}),
        # The ramp's zero is each simulator's own start (refgen: the first
        # frame; fogbench: the simulation's start, 1 s earlier), which only
        # moves the mean rate -- a constant bias, which the diagnosis
        # calibrates. The ramp itself is compared.
        skip=("trend_",)),
    "table_harmonic_distortion": dict(
        what="table motion's 2nd / 3rd harmonics 25 / -7.5 ppm of the fundamental at 10 deg (phase 0 at its "
             "peak): X swing 0.2 Hz / 10 deg",
        axis="x", f=0.2, a=10.0, d=30.0, pos=[0, 0, 0], lat=40.0, heading=0.0,
        # refgen: the harmonics added to the commanded swing, amplitude ratio and phase
        effect=("table_harmonic_distortion=25,-7.5", {"table_harmonics_ppm": [25.0, -7.5]})),
    "encoder_cyclic_error": dict(
        what="encoder cyclic error 0.5 sin + 0.3 cos arcsec (10 deg period): X swing 0.2 Hz / 8 deg",
        axis="x", f=0.2, a=8.0, d=30.0, pos=[0, 0, 0], lat=40.0, heading=0.0,
        effect=("encoder_cyclic_error=0.5,0.3", {"encoder_cyclic_arcsec": [0.5, 0.3]})),
}

# Tolerances, the same for every case: what two correct simulators of the
# same physics may differ by with these quanta (1e-6 deg pulses over
# 3..10 deg swings are ~0.1 ppm; the reference's trapezoid on 0.1 ms steps
# is exact to ~1e-4 ppm at these frequencies). The delay may differ by
# 0.05 us plus 2e-5 of itself: the fast simulator's lag takes the sensed
# angle as a quadratic between its 2-ms samples (0.055 us of 5443 us for a
# 5-ms lag at 2 Hz).
TOL = {"delay_us": 0.05, "delay_rel": 2e-5, "gain_ppm": 1.0, "cross_ppm": 1.0, "h2_ppm": 1.0, "trend_deg_h": 0.01,
       "ramp_deg_h_per_min": 0.01, "interval_ppm": 0.5}


def reference_params(c):
    seg = {"axis": c["axis"], "freq_hz": c["f"], "amp_deg": c["a"], "duration_s": c["d"],
           "start_phase_deg": 0.0, "centre_deg": c["pos"][AXES.index(c["axis"])]}
    return {
        "seed": 1, "segments": [seg], "timing": "commensurate",
        "fixed_angles_deg": [float(v) for v in c["pos"]], "axis_order": "zyx",
        "latitude_deg": c["lat"], "heading_deg": c["heading"],
        "imu_delay_ms": IMU_DELAY_MS, "table_read_delay_ms": READ_DELAY_MS, "board_delay_ms": BOARD_DELAY_MS,
        "bias_deg_h": [0.0, 0.0, 0.0], "arw_deg_sqrt_h": 0.0, "pulse_arcsec": 1e-6 * 3600.0,
        "encoder_arcsec": 1e-7 * 3600.0, "imu_clock_ppm": c.get("imu_ppm", 0.0),
        "misalignment_urad": c.get("mis", [0.0] * 6), "g_sens_deg_h_g": c.get("gsens", 0.0),
        "lag_tau_ms": c.get("lag_ms", 0.0),
        **(c["effect"][1] if "effect" in c else {}),
    }


def fast_args(c, plan_path, out):
    effects = []
    if c.get("lag_ms"):
        effects.append("first_order_lag=%r" % c["lag_ms"])
    if c.get("mis"):
        effects.append("misalignment=" + ",".join(repr(v) for v in c["mis"]))
    if c.get("gsens"):
        effects.append("g_sensitivity=%r" % c["gsens"])
    if "effect" in c:
        effects.append(c["effect"][0])
    args = ["run", "--plan", plan_path, "--seed", "1", "--arw-deg-sqrt-h", "0", "--bias-instability-deg-h", "0",
            "--bias-x-deg-h", "0", "--bias-y-deg-h", "0", "--bias-z-deg-h", "0", "--pulse-equivalent-deg", "1e-6",
            "--encoder-quantum-deg", "1e-7", "--table-freq-error-ppm", "0", "--latitude-deg", repr(c["lat"]),
            "--heading-deg", repr(c["heading"]), "--imu-clock-ppm", repr(c.get("imu_ppm", 0.0)),
            "--gyro-delay-ms", repr(IMU_DELAY_MS - BOARD_DELAY_MS), "--out", out]
    if effects:
        args += ["--effect", "+".join(effects)]
    return args


def read_csv(path):
    with open(path) as fh:
        lines = [ln for ln in fh if not ln.startswith("#")]
    header = lines[0].strip().split(",")
    data = np.array([[float(v) if v else 0.0 for v in ln.strip().split(",")] for ln in lines[1:]])
    return {h: data[:, i] for i, h in enumerate(header)}


def coefficients(directory, c):
    """The figures of the module docstring from an import directory."""
    tab = read_csv(os.path.join(directory, "table.csv"))
    gyr = read_csv(os.path.join(directory, "gyro.csv"))
    if "test_point" in tab:  # the fast simulator's export: its one test point
        tab = {k: v[tab["test_point"] == 1] for k, v in tab.items()}
        gyr = {k: v[gyr["test_point"] == 1] for k, v in gyr.items()}
    w = 2.0 * math.pi * c["f"]
    tt = tab["time_s"]
    t0 = tt[0]
    # Table: sin / cos of the fundamental, offset.
    th = tab[c["axis"] + "_deg"]
    A = np.column_stack([np.sin(h * w * (tt - t0)) for h in (1, 2, 3)] +
                        [np.cos(h * w * (tt - t0)) for h in (1, 2, 3)] + [np.ones_like(tt)])
    ts, th2s, th3s, tc, th2c, th3c, _ = np.linalg.lstsq(A, th, rcond=None)[0]
    table = complex(ts, tc)
    out = {}
    # Harmonic h of the table relative to its fundamental: the phase of the
    # fundamental, h times, taken out (in phase / quadrature).
    for h, z in ((2, complex(th2s, th2c)), (3, complex(th3s, th3c))):
        rel = z / (table / abs(table)) ** h / abs(table) * 1e6
        out["table_h%d_in_phase_ppm" % h] = rel.real
        out["table_h%d_quadrature_ppm" % h] = rel.imag
    # Clocks: the mean stamp interval of each stream against its nominal
    # period (the sampling board stamps both on its one counter).
    for name, times, nominal in (("table", tt, 1e-3), ("imu", gyr["time_s"], 2e-3)):
        mean = (times[-1] - times[0]) / (len(times) - 1)
        out["interval_%s_ppm" % name] = (mean / nominal - 1.0) * 1e6
    # Gyros: cumulative angle at the stamps; fundamental, 2nd harmonic,
    # offset, trend and ramp. The first frame's increment belongs before its stamp.
    gt = gyr["time_s"]
    G = np.column_stack([np.sin(w * (gt - t0)), np.cos(w * (gt - t0)), np.sin(2 * w * (gt - t0)),
                         np.cos(2 * w * (gt - t0)), np.ones_like(gt), gt - t0, (gt - t0) ** 2])
    for ax in AXES:
        col = ax + "_inc_deg"
        if col not in gyr:
            continue
        cum = np.cumsum(gyr[col])
        s1, c1, s2, c2, _, slope, curve = np.linalg.lstsq(G, cum, rcond=None)[0]
        out["ramp_%s_deg_h_per_min" % ax] = 2.0 * curve * 3600.0 * 60.0
        r = complex(s1, c1) / table
        if ax == c["axis"]:
            # gyro = table delayed by tau: ratio = g e^{-i w tau}
            out["delay_us"] = -math.atan2(r.imag, r.real) / w * 1e6
            out["gain_ppm"] = (abs(r) - 1.0) * 1e6
        else:
            out["cross_in_phase_%s_ppm" % ax] = r.real * 1e6
            out["cross_quadrature_%s_ppm" % ax] = r.imag * 1e6
        out["h2_%s_ppm" % ax] = abs(complex(s2, c2)) / abs(table) * 1e6
        # the mean rate over the record (the ramp's middle)
        out["trend_%s_deg_h" % ax] = (slope + curve * (gt[-1] - t0)) * 3600.0
    return out


def tolerance(key, value):
    if key.startswith("delay"):
        return TOL["delay_us"] + TOL["delay_rel"] * abs(value)
    if key.startswith("gain"):
        return TOL["gain_ppm"]
    if key.startswith("cross"):
        return TOL["cross_ppm"]
    if key.startswith("h2") or key.startswith("table_h"):
        return TOL["h2_ppm"]
    if key.startswith("ramp"):
        return TOL["ramp_deg_h_per_min"]
    if key.startswith("interval"):
        return TOL["interval_ppm"]
    return TOL["trend_deg_h"]


def run_case(name, c, cli, work):
    ref_dir = os.path.join(work, name + "-reference")
    res = refgen.generate(reference_params(c))
    refgen.write_dir(res, ref_dir, overwrite=True)
    plan = {"rest_between_s": 1.0, "points": [{"axis": c["axis"], "frequency_hz": c["f"], "amplitude_deg": c["a"],
                                               "duration_s": c["d"], "settle_s": 1.0, "position_deg": c["pos"]}]}
    plan_path = os.path.join(work, name + "-plan.json")
    with open(plan_path, "w") as fh:
        json.dump(plan, fh)
    session = os.path.join(work, name + ".fbs")
    fast_dir = os.path.join(work, name + "-fast")
    for args in (fast_args(c, plan_path, session), ["export", session, "--csv", fast_dir]):
        p = subprocess.run([cli] + args, capture_output=True, text=True)
        if p.returncode != 0:
            raise RuntimeError("fogbench-cli %s failed (%d): %s" % (args[0], p.returncode, p.stderr.strip()))
    ref = coefficients(ref_dir, c)
    fast = coefficients(fast_dir, c)
    rows = []
    for key in sorted(ref):
        if key.startswith(c.get("skip", ())):
            continue
        rows.append((key, ref[key], fast[key], fast[key] - ref[key], tolerance(key, ref[key])))
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", required=True, help="path to fogbench-cli")
    ap.add_argument("--case", action="append", help="run only these cases")
    ap.add_argument("--table", action="store_true", help="print the differences as a markdown table")
    a = ap.parse_args(argv)
    names = a.case or list(CASES)
    failures = compared = 0
    with tempfile.TemporaryDirectory(prefix="fogbench-fast-vs-ref-") as work:
        for name in names:
            c = CASES[name]
            rows = run_case(name, c, a.cli, work)
            print("%s: %s" % (name, c["what"]))
            for key, r, f, d, tol in rows:
                bad = abs(d) > tol
                failures += bad
                print("  %-28s reference %12.5f  fast %12.5f  diff %+10.5f  (tolerance %g)%s"
                      % (key, r, f, d, tol, "  DISAGREES" if bad else ""))
            if a.table:
                worst = max(rows, key=lambda row: abs(row[3]) / row[4])
                print("| %s | %s | %s %+.4f (tolerance %g) |" % (name, c["what"], worst[0], worst[3], worst[4]))
            compared += len(rows)
    print("fast vs reference: %d figures in %d cases compared, %d disagree" % (compared, len(names), failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
