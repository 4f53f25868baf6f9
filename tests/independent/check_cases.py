#!/usr/bin/python3
"""The validity cases on independent data: each named case of refgen.py (a
generator that shares no code with fogbench) goes through
`fogbench-cli import` and `fogbench-cli analyze --json`, and the verdict, the
failed check and the corrected number are asserted.

    /usr/bin/python3 tests/independent/check_cases.py --cli build/release/app/fogbench-cli [CASE ...]

Exit status 0 when every case holds, 1 when one does not (each failure is
printed with what was expected and what came), 2 on bad usage.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import refgen  # noqa: E402


class Failure(Exception):
    pass


def expect(cond, what):
    if not cond:
        raise Failure(what)


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise Failure("%s exited %d: %s" % (" ".join(cmd), r.returncode, (r.stderr or r.stdout).strip()))
    return r.stdout


class Case:
    def __init__(self, cli, work, name, seed=1):
        self.cli, self.name = cli, name
        self.dir = os.path.join(work, name)
        res = refgen.generate(refgen.case_params(name) | {"seed": seed})
        self.truth = refgen.write_dir(res, self.dir)
        self.session = os.path.join(work, name + ".fbs")

    def analyse(self, *extra, segment=None):
        if os.path.exists(self.session):
            os.remove(self.session)
        imp = [self.cli, "import", self.dir, "--out", self.session]
        if segment:
            imp += ["--segment", segment]
        self.import_text = run(imp)
        return json.loads(run([self.cli, "analyze", self.session, "--json", "--no-store", *extra]))

    @property
    def lag(self):
        return self.truth["true_lag_ms"]


def point(report, i=0):
    expect(report["test_points"], "no test point was analysed: %s" % report.get("failed_points"))
    return report["test_points"][i]


def failed(p):
    return [c["id"] for c in p["checks"] if c.get("judged", True) and not c["passed"]]


def z(p, truth):
    return (p["lag_ms"] - truth) / p["lag_std_ms"]


def valid_and_right(c, report, i=0, zmax=4.0):
    p = point(report, i)
    expect(p["verdict"] in ("pass", "fail"), "%s: verdict %s (%s)" % (c.name, p["verdict"], p["verdict_reasons"]))
    expect(abs(z(p, c.lag)) <= zmax,
           "lag %.6f ± %.6f ms, truth %.6f ms: z = %.1f beyond %g" % (p["lag_ms"], p["lag_std_ms"], c.lag,
                                                                     z(p, c.lag), zmax))
    return p


def refused_by(c, report, check):
    p = point(report)
    expect(report["verdict"] == "invalid" and p["verdict"] == "invalid",
           "%s: verdict %s, expected invalid" % (c.name, report["verdict"]))
    expect(check in failed(p), "%s: failed checks %s, expected %s" % (c.name, failed(p), check))
    return p


def nominal(c):
    r = c.analyse()
    valid_and_right(c, r)
    expect(r["verdict"] == "pass", "nominal: %s" % r["verdict_reasons"])


def reversed_axis(c):
    p = refused_by(c, c.analyse(), "axis_sign")
    ratio = p["joint_fit"]["magnitude_ratio"]
    expect(abs(ratio + 1.0) < 0.01, "gyro/table ratio %.4f, expected -1" % ratio)
    # Never a half-period lag: the lag is the small delay, refused.
    expect(abs(z(p, c.lag)) <= 4.0, "lag %.4f ms against %.4f ms" % (p["lag_ms"], c.lag))
    # Stated on the command line, the sign gives a valid result.
    stated = c.analyse("--gyro-sign", "x=-1")
    p = valid_and_right(c, stated)
    expect(abs(p["joint_fit"]["magnitude_ratio"] - 1.0) < 0.01, "ratio after the stated sign")


def reversed_axis_declared(c):
    valid_and_right(c, c.analyse())


def clock_rate(c):
    p = refused_by(c, c.analyse(), "clock_rate")
    ppm = c.truth["params"]["clock_rate_ppm_gyro"]
    rate = p["timing"]["rate_error_ppm"]
    drift = p["timing"]["lag_drift_ppm"]
    expect(abs(rate - ppm) < 0.2 * abs(ppm) or abs(drift - ppm) < 0.2 * abs(ppm),
           "rate error %.2f ppm, lag drift %.2f ppm; generated %.2f ppm" % (rate, drift, ppm))


def honest_sigma(c):
    valid_and_right(c, c.analyse())


def gyro_jitter(c):
    p = valid_and_right(c, c.analyse())
    # Not pessimistic: the reported sigma is within 2x of the per-period scatter.
    track = p["track_lag_std_ms"]
    expect(p["lag_std_ms"] < 2.0 * track, "sigma %.6f ms against a per-period scatter of %.6f ms"
           % (p["lag_std_ms"], track))


def pendulum(c):
    p = refused_by(c, c.analyse(), "steady_sine")
    d = p.get("damped_fit")
    expect(d is not None, "no damped-sine fit offered")
    expect(abs(d["lag_ms"] - c.lag) <= 4.0 * d["lag_std_ms"] + 0.002,
           "damped lag %.4f ± %.4f ms, truth %.4f" % (d["lag_ms"], d["lag_std_ms"], c.lag))


def not_steady(c):
    refused_by(c, c.analyse(), "steady_sine")


def repeated_decays(c):
    p = refused_by(c, c.analyse(), "steady_sine")
    f = c.truth["params"]["segments"][0]["freq_hz"]
    expect(abs(p["joint_fit"]["frequency_hz"] / f - 1.0) < 0.02,
           "swing frequency %.4f Hz, generated %.4f Hz" % (p["joint_fit"]["frequency_hz"], f))


def acausal(c):
    refused_by(c, c.analyse(), "causal")


def continuous(c):
    r = c.analyse(segment="auto")
    segs = c.truth["params"]["segments"]
    expect(len(r["test_points"]) == len(segs), "%d windows found, %d generated:\n%s"
           % (len(r["test_points"]), len(segs), c.import_text))
    for i, s in enumerate(segs):
        p = valid_and_right(c, r, i)
        expect(abs(p["frequency_hz"] / s["freq_hz"] - 1.0) < 0.01,
               "window %d: %.4f Hz, generated %.4f Hz" % (i + 1, p["frequency_hz"], s["freq_hz"]))


CHECKS = {
    "nominal": nominal,
    "reversed_axis": reversed_axis,
    "reversed_axis_declared": reversed_axis_declared,
    "clock_rate": clock_rate,
    "quantisation_dominated": honest_sigma,
    "commensurate": honest_sigma,
    "gyro_jitter": gyro_jitter,
    "pendulum": pendulum,
    "amplitude_drift": not_steady,
    "repeated_decays": repeated_decays,
    "acausal": acausal,
    "rates_frame_average": honest_sigma,
    "rates_sample_at_stamp": honest_sigma,
    "continuous": continuous,
}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli", required=True, help="the fogbench-cli executable")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("cases", nargs="*", help="case names (default: all)")
    a = ap.parse_args(argv)
    names = a.cases or list(CHECKS)
    unknown = [n for n in names if n not in CHECKS]
    if unknown or set(refgen.CASES) - set(CHECKS):
        print("check_cases.py: no check for %s" % (unknown or sorted(set(refgen.CASES) - set(CHECKS))),
              file=sys.stderr)
        return 2
    failures = 0
    with tempfile.TemporaryDirectory(prefix="fogbench_cases_") as work:
        for name in names:
            try:
                CHECKS[name](Case(os.path.abspath(a.cli), work, name, a.seed))
                print("ok      %s" % name)
            except Failure as e:
                failures += 1
                print("FAILED  %s: %s" % (name, e))
    print("%d of %d cases hold" % (len(names) - failures, len(names)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
