#!/usr/bin/python3
"""Monte Carlo check of fogbench's delay analysis against the independent
reference generator (refgen.py, which shares no code with core/model).

For each trial: draw random test conditions, write an import directory with
refgen, run
    FOGBENCH_CLI import DIR --out S.fbs
    FOGBENCH_CLI analyze S.fbs --json --no-store
and compare the measured lag with the truth: error = lag_ms - true_lag_ms,
z = error / lag_std_ms, plus the verdict (a condition without a defect must
never be "invalid").

Run from the repository root:
    /usr/bin/python3 tests/independent/monte_carlo.py --cli build/release/app/fogbench-cli \
        [--trials 200] [--seed 1] [--jobs 2] [--json OUT.json] [--keep DIR]
Exit status: 0 when the statistics are within the acceptance bounds (see
--help), 1 when not, 2 on bad usage.
"""

from __future__ import annotations

import argparse
import concurrent.futures as cf
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import refgen  # noqa: E402

REPO = os.path.dirname(os.path.dirname(HERE))
DEFAULT_CLI = os.path.join(REPO, "build", "release", "app", "fogbench-cli")


def draw_conditions(rng, i, seed):
    """One random trial: returns (refgen parameters, summary of the draw)."""
    f = float(math.exp(rng.uniform(math.log(0.05), math.log(2.0))))
    amp = float(rng.uniform(1.0, 20.0))
    commensurate = bool(i % 2 == 0)          # half and half, interleaved
    if commensurate:
        # a period of a whole number of gyro frames (2 ms) = whole table samples
        period_ms = 2.0 * round(1000.0 / f / 2.0)
        f = 1000.0 / period_ms
    n_lo, n_hi = max(3.0, 8.0 * f), min(40.0, 120.0 * f)
    periods = float(rng.uniform(n_lo, n_hi))
    if abs(periods - round(periods)) < 0.1:  # keep it a non-integer number of periods
        periods += 0.3 if periods + 0.3 <= n_hi else -0.3
    duration = periods / f
    if commensurate:
        duration = round(duration * 1000.0) / 1000.0
        steps = round(1000.0 / f / 2.0)      # gyro frames per period
        phase = 360.0 * int(rng.integers(0, steps)) / steps
    else:
        phase = float(rng.uniform(0.0, 360.0))
    if rng.uniform() < 0.08:
        # table read delay longer than the IMU delay: a negative lag
        imu = float(rng.uniform(0.1, 0.4))
        read = float(rng.uniform(imu + 0.02, imu + 0.3))
    else:
        imu = float(rng.uniform(0.1, 3.0))
        read = float(rng.uniform(0.0, 0.5))
    p = refgen.default_params()
    p.update({
        "seed": int(seed) * 100003 + i,
        "segments": [{"axis": str(rng.choice(["x", "y", "z"])), "freq_hz": f, "amp_deg": amp,
                      "duration_s": duration, "start_phase_deg": phase, "centre_deg": 0.0}],
        "imu_delay_ms": imu,
        "table_read_delay_ms": read,
        "board_delay_ms": float(rng.uniform(0.0, 0.3)),
        "bias_deg_h": [float(x) for x in rng.uniform(-5.0, 5.0, 3)],
        "arw_deg_sqrt_h": float(math.exp(rng.uniform(math.log(0.001), math.log(0.01)))),
        "pulse_arcsec": float(math.exp(rng.uniform(math.log(0.05), math.log(2.0)))),
        "encoder_arcsec": float(math.exp(rng.uniform(math.log(0.1), math.log(3.6)))),
        "latitude_deg": float(rng.uniform(20.0, 60.0)),
        "heading_deg": float(rng.uniform(0.0, 360.0)),
        "timing": "commensurate" if commensurate else "incommensurate",
        "table_freq_error_ppm": 0.0 if commensurate else float(rng.uniform(-50.0, 50.0)),
        "axes_out": "swing",
    })
    summary = {
        "axis": p["segments"][0]["axis"], "frequency_hz": f, "amplitude_deg": amp, "duration_s": duration,
        "periods": duration * f, "start_phase_deg": phase, "imu_delay_ms": imu, "table_read_delay_ms": read,
        "true_lag_ms": imu - read, "bias_deg_h": p["bias_deg_h"], "arw_deg_sqrt_h": p["arw_deg_sqrt_h"],
        "pulse_arcsec": p["pulse_arcsec"], "encoder_arcsec": p["encoder_arcsec"], "timing": p["timing"],
        "table_freq_error_ppm": p["table_freq_error_ppm"],
    }
    return p, summary


def run_trial(args):
    i, params, summary, cli, workdir, keep, limit_ms = args
    rec = {"trial": i, "conditions": summary}
    d = os.path.join(workdir, "trial_%s" % i)
    os.makedirs(d, exist_ok=True)
    imp = os.path.join(d, "data")
    fbs = os.path.join(d, "s.fbs")
    try:
        t = time.perf_counter()
        res = refgen.generate(params)
        rec["time_model_s"] = time.perf_counter() - t
        tr = refgen.write_dir(res, imp)
        rec["time_generate_s"] = time.perf_counter() - t
        rec["rows"] = tr["rows"]
        t = time.perf_counter()
        r = subprocess.run([cli, "import", imp, "--out", fbs], capture_output=True, text=True)
        rec["time_import_s"] = time.perf_counter() - t
        if r.returncode != 0:
            rec["error"] = "import failed (%d): %s" % (r.returncode, r.stderr.strip())
            return rec
        t = time.perf_counter()
        cmd = [cli, "analyze", fbs, "--json", "--no-store"]
        if limit_ms is not None:
            cmd += ["--limit-ms", str(limit_ms)]
        r = subprocess.run(cmd, capture_output=True, text=True)
        rec["time_analyze_s"] = time.perf_counter() - t
        if r.returncode != 0:
            rec["error"] = "analyze failed (%d): %s" % (r.returncode, r.stderr.strip())
            return rec
        rep = json.loads(r.stdout)
        rec["verdict"] = rep.get("verdict")
        rec["verdict_reasons"] = rep.get("verdict_reasons")
        rec["limit_ms"] = rep.get("imu_delay_limit_ms", limit_ms)
        if not rep.get("test_points"):
            rec["error"] = "no test point analysed: %s" % rep.get("failed_points")
            return rec
        tp = rep["test_points"][0]
        rec["lag_ms"] = tp["lag_ms"]
        rec["lag_std_ms"] = tp["lag_std_ms"]
        rec["crlb_ms"] = tp.get("crlb_ms")
        rec["imu_delay_ms"] = tp.get("imu_delay_ms")
        rec["imu_delay_std_ms"] = tp.get("imu_delay_std_ms")
        rec["error_ms"] = tp["lag_ms"] - tr["true_lag_ms"]
        rec["z"] = rec["error_ms"] / tp["lag_std_ms"] if tp["lag_std_ms"] > 0 else math.inf
        rec["point_verdict"] = tp.get("verdict")
        rec["point_verdict_reasons"] = tp.get("verdict_reasons")
        rec["failed_checks"] = [c for c in tp.get("checks", []) if not c.get("passed", True)]
        rec["warnings"] = tp.get("warnings", [])
        rec["magnitude_ratio"] = tp.get("joint_fit", {}).get("magnitude_ratio")
        # The gain against the truth (informative, not a target): 1 less the trapezoid's (w dt)^2 / 12.
        jf = tp.get("joint_fit", {})
        if jf.get("magnitude_ratio_std"):
            w = 2 * math.pi * jf["frequency_hz"]
            rec["gain_z"] = (jf["magnitude_ratio"] - (1.0 - (w * res["fine_dt_s"]) ** 2 / 12.0)) / jf["magnitude_ratio_std"]
        return rec
    except Exception as e:  # a generator or parsing problem is a result too
        rec["error"] = "%s: %s" % (type(e).__name__, e)
        return rec
    finally:
        if not keep:
            shutil.rmtree(d, ignore_errors=True)


def judge(rec, default_limit):
    """Expected verdict from the truth; 'wrong' only when the truth is clearly
    on one side of the limit (4 sigma + 1 us away)."""
    if "error" in rec:
        return "no result"
    v = rec.get("point_verdict") or rec.get("verdict")
    if v is None:
        return "no verdict"
    if v == "invalid":
        return "wrong"
    limit = rec.get("limit_ms") or default_limit
    true_imu = rec["conditions"]["imu_delay_ms"]
    s = rec.get("imu_delay_std_ms") or rec["lag_std_ms"]
    upper = true_imu + 2 * s
    if abs(upper - limit) < 4 * s + 1e-3:
        return "borderline"
    expect = "pass" if upper < limit else "fail"
    return "ok" if v == expect else "wrong"


def describe(rec):
    c = rec["conditions"]
    return ("trial %s: %s %.4g Hz / %.3g deg, %.1f s (%.2f periods), %s, phase %.1f deg, IMU %.4f ms, read %.4f ms, "
            "ARW %.4g, pulse %.3g\", encoder %.3g\", bias %s deg/h, freq err %.1f ppm" % (
                rec["trial"], c["axis"], c["frequency_hz"], c["amplitude_deg"], c["duration_s"], c["periods"],
                c["timing"], c["start_phase_deg"], c["imu_delay_ms"], c["table_read_delay_ms"],
                c["arw_deg_sqrt_h"], c["pulse_arcsec"], c["encoder_arcsec"],
                ",".join("%.2f" % b for b in c["bias_deg_h"]), c["table_freq_error_ppm"]))


def main(argv=None):
    ap = argparse.ArgumentParser(prog="monte_carlo.py", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", default=os.environ.get("FOGBENCH_CLI", DEFAULT_CLI),
                    help="fogbench-cli to test (default $FOGBENCH_CLI or build/release/app/fogbench-cli)")
    ap.add_argument("--trials", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--json", dest="json_out", help="write every trial to this JSON file")
    ap.add_argument("--only", help="run only these trials of the seed's draw (comma-separated indices; for "
                    "reproducing a bad trial)")
    ap.add_argument("--repeat", type=int, default=1,
                    help="run every (selected) trial's conditions with this many noise seeds and print, per "
                    "condition, the true scatter of the lag against the reported lag_std_ms")
    ap.add_argument("--keep", help="keep the generated directories and sessions under this directory")
    ap.add_argument("--limit-ms", type=float, default=None,
                    help="IMU delay limit passed to analyze (default: the CLI's own, 0.8 ms)")
    ap.add_argument("--min-within-3", type=float, default=0.99,
                    help="acceptance: fraction of |z| <= 3 at least this (default 0.99)")
    ap.add_argument("--std-z-range", type=float, nargs=2, default=[0.85, 1.15],
                    help="acceptance: std(z) within this range (default 0.85 1.15)")
    a = ap.parse_args(argv)
    if not (os.path.isfile(a.cli) and os.access(a.cli, os.X_OK)):
        print("monte_carlo.py: %s is not an executable fogbench-cli; give --cli PATH" % a.cli, file=sys.stderr)
        return 2
    if a.trials < 1 or a.jobs < 1:
        print("monte_carlo.py: --trials and --jobs must be >= 1", file=sys.stderr)
        return 2

    rng = np.random.default_rng(a.seed)
    draws = [draw_conditions(rng, i, a.seed) for i in range(a.trials)]
    workdir = a.keep or tempfile.mkdtemp(prefix="fogbench_mc_")
    os.makedirs(workdir, exist_ok=True)
    jobs = [(i, p, s, os.path.abspath(a.cli), workdir, bool(a.keep), a.limit_ms) for i, (p, s) in enumerate(draws)]
    if a.only:
        wanted = {int(x) for x in a.only.split(",")}
        jobs = [j for j in jobs if j[0] in wanted]
    if a.repeat > 1:
        rep = []
        for j in jobs:
            for k in range(a.repeat):
                p = dict(j[1])
                p["seed"] = j[1]["seed"] + 7919 * k
                rep.append((j[0] + k / (10.0 ** len(str(a.repeat))), p) + j[2:])
        jobs = rep
    a.trials = len(jobs)
    t0 = time.perf_counter()
    recs = []
    try:
        with cf.ProcessPoolExecutor(max_workers=a.jobs) as ex:
            for n, rec in enumerate(ex.map(run_trial, jobs), 1):
                recs.append(rec)
                if n % 20 == 0 or n == a.trials:
                    print("  %d/%d trials (%.0f s)" % (n, a.trials, time.perf_counter() - t0), file=sys.stderr)
    finally:
        if not a.keep:
            shutil.rmtree(workdir, ignore_errors=True)
    wall = time.perf_counter() - t0

    for r in recs:
        r["judgement"] = judge(r, a.limit_ms if a.limit_ms is not None else 0.8)
    good = [r for r in recs if "z" in r and math.isfinite(r["z"])]
    z = np.array([r["z"] for r in good])
    err_us = np.array([r["error_ms"] * 1e3 for r in good])
    within = float(np.mean(np.abs(z) <= 3)) if z.size else 0.0
    counts = {}
    for r in recs:
        counts[r["judgement"]] = counts.get(r["judgement"], 0) + 1
    verdicts = {}
    for r in recs:
        v = r.get("point_verdict") or r.get("verdict") or ("(error)" if "error" in r else "(none)")
        verdicts[v] = verdicts.get(v, 0) + 1

    def mean_of(key):
        v = [r[key] for r in recs if key in r]
        return (float(np.mean(v)), float(np.max(v))) if v else (float("nan"), float("nan"))

    print("fogbench Monte Carlo against the independent generator (refgen.py)")
    print("  cli: %s" % a.cli)
    print("  trials: %d (seed %d, %d jobs, %.0f s wall)" % (a.trials, a.seed, a.jobs, wall))
    print("  with a lag: %d; no result: %d" % (len(good), a.trials - len(good)))
    if z.size:
        print("  fraction |z| <= 3: %.4f" % within)
        print("  std(z): %.4f   mean(z): %.4f   (z = (lag - true lag) / lag_std)" % (np.std(z, ddof=1) if z.size > 1
                                                                                  else float("nan"), np.mean(z)))
        print("  robust std(z) (median |z| / 0.6745): %.4f" % (np.median(np.abs(z)) / 0.6745))
        print("  error: mean %.4g us, rms %.4g us, max |error| %.4g us" % (
            np.mean(err_us), math.sqrt(np.mean(err_us ** 2)), np.max(np.abs(err_us))))
        for tm in ("commensurate", "incommensurate"):
            zz = np.array([r["z"] for r in good if r["conditions"]["timing"] == tm])
            if zz.size > 1:
                print("    %-15s n=%3d  std(z) %.3f  mean(z) %+.3f  |z|<=3 %.3f" % (
                    tm, zz.size, np.std(zz, ddof=1), np.mean(zz), np.mean(np.abs(zz) <= 3)))
    gz = np.array([r["gain_z"] for r in good if "gain_z" in r])
    if gz.size > 1:
        print("  gain (informative): std(z) %.3f, mean(z) %+.3f, |z|<=3 %.3f over %d trials" % (
            np.std(gz, ddof=1), np.mean(gz), np.mean(np.abs(gz) <= 3), gz.size))
    print("  verdicts: %s" % ", ".join("%s %d" % kv for kv in sorted(verdicts.items())))
    print("  judgement: %s" % ", ".join("%s %d" % kv for kv in sorted(counts.items())))
    wrong = [r for r in recs if r["judgement"] in ("wrong", "no result")]
    print("  wrong verdicts (incl. no result): %d" % len(wrong))
    for r in wrong[:20]:
        print("    " + describe(r))
        if "error" in r:
            print("      error: %s" % r["error"])
        else:
            print("      verdict %s: %s" % (r.get("point_verdict") or r.get("verdict"),
                                            "; ".join(r.get("point_verdict_reasons") or r.get("verdict_reasons")
                                                      or [])))
            for c in r.get("failed_checks", []):
                print("      check %s failed: %s" % (c.get("id"), c.get("detail")))
    mg, xg = mean_of("time_generate_s")
    mm, _ = mean_of("time_model_s")
    mi, xi = mean_of("time_import_s")
    mz, xz = mean_of("time_analyze_s")
    print("  per trial: generate %.2f s (model %.2f s, max %.2f s), import %.2f s (max %.2f), analyze %.2f s (max %.2f)"
          % (mg, mm, xg, mi, xi, mz, xz))
    if good:
        print("  5 worst |z|:")
        for r in sorted(good, key=lambda r: -abs(r["z"]))[:5]:
            print("    z %+.2f, error %+.4g us, std %.4g us: %s" % (r["z"], r["error_ms"] * 1e3,
                                                                   r["lag_std_ms"] * 1e3, describe(r)))
    if a.repeat > 1:
        print("  per condition over %d noise seeds (true scatter vs reported std):" % a.repeat)
        by = {}
        for r in good:
            by.setdefault(int(r["trial"]), []).append(r)
        for t, rs in sorted(by.items()):
            e = np.array([r["error_ms"] for r in rs]) * 1e3
            s_ = np.array([r["lag_std_ms"] for r in rs]) * 1e3
            zz = np.array([r["z"] for r in rs])
            inv = sum(1 for r in rs if (r.get("point_verdict") or r.get("verdict")) == "invalid")
            print("    trial %d: n %d, error mean %+.4g us, std %.4g us; reported std mean %.4g us (min %.4g); "
                  "rms z %.3f; invalid %d" % (t, len(rs), e.mean(), e.std(ddof=1) if len(rs) > 1 else float("nan"),
                                              s_.mean(), s_.min(), math.sqrt(np.mean(zz ** 2)), inv))
    if a.json_out:
        with open(a.json_out, "w") as fh:
            json.dump(refgen._jsonable({"trials": a.trials, "seed": a.seed, "cli": a.cli, "wall_s": wall,
                                        "fraction_abs_z_le_3": within,
                                        "std_z": float(np.std(z, ddof=1)) if z.size > 1 else None,
                                        "mean_z": float(np.mean(z)) if z.size else None,
                                        "wrong_verdicts": len(wrong), "records": recs}), fh, indent=1)
        print("  wrote %s" % a.json_out)

    ok = (z.size == a.trials and within >= a.min_within_3 and z.size > 1
          and a.std_z_range[0] <= np.std(z, ddof=1) <= a.std_z_range[1] and not wrong)
    print("  RESULT: %s" % ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
