#!/usr/bin/python3
"""`fogbench-cli export --hdf5` read back with h5py: every dataset holds the
CSV export's values bit for bit and carries its unit; the root states the
format version and the session file's SHA-256; the shown result's verdict is
analyze --json's and delays.csv's; a second export to the same name is refused.

h5py and numpy are required: a missing module fails the test (no skip), since
a skipped round trip would vouch for nothing.
"""
import argparse
import csv
import hashlib
import json
import math
import os
import resource
import signal
import struct
import shutil
import subprocess
import sys
import tempfile

import h5py  # noqa: E402  (ImportError = test failure, on purpose)
import numpy as np

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


def bits(x):
    x = float(x)
    # NaN: the CSV's empty cell / "nan"; any NaN is the same missing value.
    return "nan" if math.isnan(x) else struct.pack("<d", x)


def same(csv_values, h5_values, what):
    """csv_values: texts as the CSV prints them ('' = empty = NaN)."""
    h5_values = list(np.asarray(h5_values, dtype=np.float64).ravel())
    if len(csv_values) != len(h5_values):
        failures.append(f"{what}: {len(csv_values)} CSV values, {len(h5_values)} in HDF5")
        return
    for i, (c, h) in enumerate(zip(csv_values, h5_values)):
        if bits(float(c) if c != "" else float("nan")) != bits(h):
            failures.append(f"{what}[{i}]: CSV {c!r} != HDF5 {h!r}")
            return


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def unit(ds, expected):
    check("unit" in ds.attrs, f"{ds.name} has no unit attribute")
    got = ds.attrs.get("unit")
    check(got == expected, f"{ds.name}: unit {got!r}, expected {expected!r}")


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def check_response(h, doc):
    check("response" in h, "`response` gives a response, the HDF5 has no /response")
    if "response" not in h:
        return
    check(sorted(h["response"].keys()) == sorted(r["axis"] for r in doc["responses"]), "response axes differ")
    point_units = {"frequency_hz": "Hz", "magnitude": "1", "magnitude_std": "1", "magnitude_db": "dB",
                   "magnitude_db_std": "dB", "phase_deg": "deg", "phase_std_deg": "deg", "lag_ms": "ms",
                   "lag_std_ms": "ms", "magnitude_phase_cov_deg": "deg", "harmonic_fraction": "1",
                   # the phase against the table's motion with its budget and U (k = 2)
                   "phase_vs_table_motion_deg": "deg", "phase_standard_uncertainty_deg": "deg",
                   "phase_read_delay_std_deg": "deg", "coverage_factor": "1",
                   "phase_expanded_uncertainty_deg": "deg", "phase_expanded_uncertainty_ms": "ms"}
    model_units = {"chi_square": "1", "aic": "1", "bic": "1", "p_value": "1", "low_frequency_delay_ms": "ms",
                   "low_frequency_delay_std_ms": "ms", "group_delay_ms": "ms", "group_delay_std_ms": "ms",
                   "bandwidth_hz": "Hz", "bandwidth_std_hz": "Hz"}
    # JSON numbers are nlohmann's shortest round-trip text: float() gives the double back.
    js = lambda v: "" if v is None else repr(float(v))
    for r in doc["responses"]:
        g = h["response"][r["axis"]]
        where = f"response {r['axis']}"
        check(g.attrs["chosen_model"] == (r["chosen_model"] or ""), f"{where}: chosen model")
        check(g.attrs["no_model_reason"] == (r["no_model_reason"] or ""), f"{where}: no-model reason")
        same([js(r["group_delay_at_hz"])], [g.attrs["group_delay_at_hz"]], f"{where} group_delay_at_hz")
        check(list(g["points/test_point"][()]) == [p["test_point"] for p in r["points"]], f"{where}: points")
        for key, u in point_units.items():
            same([js(p[key]) for p in r["points"]], g["points"][key], f"{where} points {key}")
            unit(g["points"][key], u)
        check(list(g["left_out/test_point"][()]) == [p["test_point"] for p in r["left_out"]], f"{where}: left out")
        check([text(v) for v in g["left_out/reason"][()]] == [p["reason"] for p in r["left_out"]],
              f"{where}: left-out reasons")
        check(sorted(g["models"].keys()) == sorted(m["model"] for m in r["models"]), f"{where}: models")
        for m in r["models"]:
            k = g["models"][m["model"]]
            for key, u in model_units.items():
                same([js(m[key])], k[key], f"{where} {m['model']} {key}")
                unit(k[key], u)
            check(int(k["dof"][0]) == m["dof"], f"{where} {m['model']} dof")
            check(bool(k["adequate"][0]) == m["adequate"], f"{where} {m['model']} adequate")
            check(bool(k["admissible"][0]) == m["admissible"], f"{where} {m['model']} admissible")
            for name, pv in m["parameters"].items():
                same([js(pv["value"])], k["parameters"][name], f"{where} {m['model']} {name}")
                same([js(pv["std"])], k["parameters"][name + "_std"], f"{where} {m['model']} {name}_std")
            same([js(v) for row in m["correlation"] for v in row], k["correlation"],
                 f"{where} {m['model']} correlation")


def check_noise(h, doc):
    """/noise against `noise --json`: every segment, its Allan curve and terms,
    customary and SI values bit for bit, with their units."""
    check("noise" in h, "`noise` finds static segments, the HDF5 has no /noise")
    if "noise" not in h:
        return
    js = lambda v: repr(float(v))
    segments = doc["segments"]
    check(len(h["noise"].keys()) == len(segments), f"noise segments: {list(h['noise'].keys())} vs {len(segments)}")
    for s in segments:
        name = f"segment_{s['test_point']:02d}"
        check(name in h["noise"], f"no /noise/{name}")
        if name not in h["noise"]:
            continue
        g = h["noise"][name]
        check(g.attrs["axis"] == s["axis"], f"{name}: axis")
        for key, u in {"duration_s": "s", "interval_s": "s", "bias_deg_h": "deg/h", "bias_std_deg_h": "deg/h",
                       "earth_rate_deg_h": "deg/h", "earth_corrected_bias_deg_h": "deg/h", "confidence": "1"}.items():
            same([js(s[key])], g[key], f"{name} {key}")
            unit(g[key], u)
        for key, u in {"tau_s": "s", "adev_deg_h": "deg/h", "low_deg_h": "deg/h", "high_deg_h": "deg/h",
                       "edf": "1"}.items():
            same([js(p[key]) for p in s["allan"]], g["allan"][key], f"{name} allan {key}")
            unit(g["allan"][key], u)
        check(sorted(g["terms"].keys()) == sorted(t["term"] for t in s["terms"]), f"{name}: terms")
        for t in s["terms"]:
            k = g["terms"][t["term"]]
            for key, ukey in (("value", "unit"), ("std", "unit"), ("value_si", "unit_si"), ("std_si", "unit_si")):
                same([js(t[key])], k[key], f"{name} {t['term']} {key}")
                unit(k[key], t[ukey])
            for key in ("tau_low_s", "tau_high_s"):
                same([js(t[key])], k[key], f"{name} {t['term']} {key}")
                unit(k[key], "s")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", required=True)
    # CTest uses the quick preset; a longer session can be checked by hand.
    ap.add_argument("--preset", default="quick")
    ap.add_argument("--seed", default="3")
    args = ap.parse_args()
    cli = args.cli
    work = tempfile.mkdtemp(prefix="fog_hdf5_")
    status = 1
    try:
        status = check_in(cli, args, work)
        return status
    finally:
        # A passing run leaves nothing behind (its session, CSV and HDF5 are
        # about 150 MB); a failing or interrupted one keeps them for a look.
        if status == 0:
            shutil.rmtree(work, ignore_errors=True)
        else:
            print(f"hdf5 round trip: the files are kept in {work}", file=sys.stderr)


def check_in(cli, args, work):
    run = lambda *a, **k: subprocess.run([cli, *a], cwd=work, capture_output=True, text=True, **k)

    r = run("run", "--preset", args.preset, "--seed", args.seed, "--out", "S.fbs", "--imu-serial", "SN-5",
            "--lot", "L-2026-11", "--bench-id", "bench-3")
    check(r.returncode == 0, f"run failed: {r.stderr}")
    r = run("export", "S.fbs", "--csv", "csv", "--hdf5", "S.h5")
    check(r.returncode == 0, f"export failed: {r.stderr}")
    if failures:
        return finish()
    c = os.path.join(work, "csv")
    # Hashed before `analyze` below, which stores a result in the session and
    # so changes its bytes: the HDF5 states the file as it was exported.
    with open(os.path.join(work, "S.fbs"), "rb") as f:
        sha = hashlib.sha256(f.read()).hexdigest()
    version = run("--version").stdout.split()[-1]

    with h5py.File(os.path.join(work, "S.h5"), "r") as h:
        # Root attributes.
        check(h.attrs["format"] == "fogbench-hdf5", f"format {h.attrs['format']!r}")
        check(int(h.attrs["format_version"]) == 1, "format_version is not 1")
        check(h.attrs["session_sha256"] == sha, f"session_sha256 {h.attrs['session_sha256']} != sha256 {sha}")
        check(h.attrs["fogbench_version"] == version, f"fogbench_version {h.attrs['fogbench_version']} != {version}")
        with open(os.path.join(c, "metadata.json")) as f:
            meta_text = f.read()
            check(h["metadata"].attrs["json"] == meta_text, "/metadata json differs from metadata.json")
        # The unit's identity at the root, as the session states it (and the CSV metadata).
        meta = json.loads(meta_text)
        for key, given in (("imu_serial", "SN-5"), ("lot", "L-2026-11"), ("bench_id", "bench-3")):
            check(h.attrs[key] == given and meta[key] == given,
                  f"{key}: root {h.attrs[key]!r}, metadata.json {meta.get(key)!r}, given {given!r}")

        # Every dataset carries a unit.
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                check("unit" in obj.attrs, f"/{name} has no unit attribute")
        h.visititems(visit)

        # table.csv and gyro.csv, per test point.
        table, gyro = rows(os.path.join(c, "table.csv")), rows(os.path.join(c, "gyro.csv"))
        points = sorted({int(x["test_point"]) for x in table} | {int(x["test_point"]) for x in gyro})
        check(sorted(int(g.attrs["test_point"]) for g in h["test_points"].values()) == points,
              "test point groups differ from the CSV's test points")
        for n in points:
            g = h["test_points"][f"{n:02d}"]
            t = [x for x in table if int(x["test_point"]) == n]
            same([x["time_s"] for x in t], g["table/time_s"], f"tp{n} table time_s")
            same([x[k] for x in t for k in ("x_deg", "y_deg", "z_deg")], g["table/angle_deg"], f"tp{n} angle_deg")
            check(g["table/angle_deg"].shape == (len(t), 3), f"tp{n} angle_deg shape")
            unit(g["table/time_s"], "s")
            unit(g["table/angle_deg"], "deg")
            y = [x for x in gyro if int(x["test_point"]) == n]
            same([x["time_s"] for x in y], g["gyro/time_s"], f"tp{n} gyro time_s")
            same([x[k] for x in y for k in ("x_inc_deg", "y_inc_deg", "z_inc_deg")], g["gyro/increment_deg"],
                 f"tp{n} increment_deg")
            same([x["temperature_c"] for x in y], g["gyro/temperature_c"], f"tp{n} temperature_c")
            check([int(x["lost_before"]) for x in y] == list(g["gyro/lost_before"][()]), f"tp{n} lost_before")
            unit(g["gyro/time_s"], "s")
            unit(g["gyro/increment_deg"], "deg")
            unit(g["gyro/temperature_c"], "degC")
            unit(g["gyro/lost_before"], "frames")

        # fits.csv: every column, rows in the CSV's order, empty cell = NaN.
        fits = rows(os.path.join(c, "fits.csv"))
        fit_units = {"frequency_hz": "Hz", "frequency_std_hz": "Hz", "period_ms": "ms", "period_std_ms": "ms",
                     "phase_ms": "ms", "phase_std_ms": "ms", "amplitude_deg": "deg", "amplitude_std_deg": "deg",
                     "offset_deg": "deg", "trend_deg_per_s": "deg/s", "trend_std_deg_per_s": "deg/s",
                     "residual_rms_deg": "deg", "chi2_per_dof": "1", "lag_ms": "ms", "lag_std_ms": "ms",
                     "magnitude_ratio": "1", "magnitude_ratio_std": "1"}
        fitted = sorted({int(x["test_point"]) for x in fits})
        check(len(fitted) > 0, "fits.csv holds no fit (the quick preset should be analysed)")
        with open(os.path.join(c, "report.json")) as f:
            report = json.load(f)
        for n in fitted:
            g = h["test_points"][f"{n:02d}"]
            f_rows = [x for x in fits if int(x["test_point"]) == n]
            check([text(v) for v in g["fits/channel"][()]] == [x["channel"] for x in f_rows], f"tp{n} fit channels")
            check([text(v) for v in g["fits/model"][()]] == [x["model"] for x in f_rows], f"tp{n} fit models")
            check([int(x["samples"]) for x in f_rows] == list(g["fits/samples"][()]), f"tp{n} fit samples")
            for col, u in fit_units.items():
                same([x[col] for x in f_rows], g["fits"][col], f"tp{n} fits {col}")
                unit(g["fits"][col], u)
            res = rows(os.path.join(c, f"residuals_{n}.csv"))
            for ch in ("table", "gyro"):
                rr = [x for x in res if x["channel"] == ch]
                same([x["time_s"] for x in rr], g[f"residuals/{ch}_time_s"], f"tp{n} {ch} residual time")
                same([x["residual_deg"] for x in rr], g[f"residuals/{ch}_residual_deg"], f"tp{n} {ch} residuals")
                unit(g[f"residuals/{ch}_time_s"], "s")
                unit(g[f"residuals/{ch}_residual_deg"], "deg")
            # The per-period track: report.json's (the CSV export has no file of it).
            jp = [p for p in report["test_points"] if p["index"] == n - 1]  # report.json: 0-based
            track = jp[0]["period_track"] if jp else None
            check(track is not None and len(track) > 0, f"tp{n}: report.json has no period track to compare")
            if track:
                for key, u in (("time_s", "s"), ("lag_ms", "ms"), ("table_amplitude_deg", "deg")):
                    same([repr(float(d[key])) for d in track], g["period_track"][key], f"tp{n} period_track {key}")
                    unit(g["period_track"][key], u)

        # The shown result: delays.csv's rows, verdict and marks.
        delays = rows(os.path.join(c, "delays.csv"))
        pts = h["result/points"]
        for q in ("measured_lag", "table_read_delay", "imu_delay", "processing_board_delay", "gyro_delay"):
            d = [x for x in delays if x["quantity"] == q]
            same([x["value_ms"] for x in d], pts[f"{q}_ms"], f"result {q}_ms")
            same([x["std_ms"] for x in d], pts[f"{q}_std_ms"], f"result {q}_std_ms")
            unit(pts[f"{q}_ms"], "ms")
            check([text(v) for v in pts["verdict"][()]] == [x["verdict"] for x in d], f"result verdicts ({q})")
            check([bool(v) for v in pts["vouched"][()]] == [x["vouched"] == "true" for x in d], f"vouched ({q})")
            check([text(v) for v in pts["reason"][()]] == [x["reason"] for x in d], f"reasons ({q})")
            check(list(pts["test_point"][()]) == [int(x["test_point"]) for x in d], f"result test points ({q})")
        with open(os.path.join(c, "delays.csv")) as f:
            line = [x for x in f if x.startswith("# result verdict:")][0]
        shown = h["result"].attrs["verdict"]
        check(line.startswith(f"# result verdict: {shown.upper()} ("), f"delays.csv says {line!r}, HDF5 {shown!r}")
        # The frequency response and the static segments' noise: the numbers
        # `response --json` and `noise --json` give (same constants, default
        # options); no group when the command finds none (exit 1).
        for command, group, compare in (("response", "response", check_response), ("noise", "noise", check_noise)):
            r = run(command, "S.fbs", "--json")
            if r.returncode == 0:
                compare(h, json.loads(r.stdout))
            else:
                check(r.returncode == 1, f"{command} failed: {r.stderr}")
                check(group not in h, f"/{group} exists although `{command}` finds none")

        a = run("analyze", "S.fbs", "--json")
        check(a.returncode == 0, f"analyze --json failed: {a.stderr}")
        analysed = json.loads(a.stdout)
        check(shown == analysed["verdict"], f"HDF5 verdict {shown!r} != analyze --json {analysed['verdict']!r}")
        check(shown in ("pass", "fail", "invalid", "incomplete"), f"verdict {shown!r} is not a verdict word")
        reasons = [text(v) for v in h["result/reasons"][()]]
        check(len(reasons) > 0, "the result states no reasons")
        check(reasons == analysed["verdict_reasons"], f"reasons {reasons} != analyze --json {analysed['verdict_reasons']}")
        check(float(h["result"].attrs["limit_ms"]) == float(analysed["imu_delay_limit_ms"]), "limit_ms differs")
        k = h["result/constants"]
        for name in ("table_read_delay_ms", "processing_board_delay_ms"):
            unit(k[name], "ms")
        same([x["value_ms"] for x in delays if x["quantity"] == "table_read_delay"][:1],
             k["table_read_delay_ms"], "constants table_read_delay_ms")
        same([x["value_ms"] for x in delays if x["quantity"] == "processing_board_delay"][:1],
             k["processing_board_delay_ms"], "constants processing_board_delay_ms")

    # A second export to the same name is refused and leaves the file alone.
    before = open(os.path.join(work, "S.h5"), "rb").read()
    r = run("export", "S.fbs", "--hdf5", "S.h5")
    check(r.returncode != 0, "a second export to the same name was not refused")
    check("already exists" in r.stderr and "--overwrite" in r.stderr, f"refusal words: {r.stderr!r}")
    check(open(os.path.join(work, "S.h5"), "rb").read() == before, "the refused export changed the file")
    r = run("export", "S.fbs", "--hdf5", "S.h5", "--overwrite")
    check(r.returncode == 0, f"--overwrite export failed: {r.stderr}")
    # A folder that does not exist: a clear error, no crash, no HDF5 stack dump.
    r = run("export", "S.fbs", "--hdf5", "no/such/folder/S.h5")
    check(r.returncode == 2, f"export into a missing folder: exit {r.returncode}")
    check("cannot create" in r.stderr and "HDF5-DIAG" not in r.stderr, f"missing folder words: {r.stderr!r}")
    # A write that fails midway (a 64 KiB file size limit: EFBIG, as a full
    # disk gives ENOSPC): exit 2 with words, no crash, nothing left behind.
    def small_files():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (64 * 1024, resource.getrlimit(resource.RLIMIT_FSIZE)[1]))
    r = run("export", "S.fbs", "--hdf5", "full.h5", preexec_fn=small_files)
    check(r.returncode == 2, f"export onto a 'full disk': exit {r.returncode} (negative = killed by a signal)")
    check("disk full?" in r.stderr, f"full disk words: {r.stderr!r}")
    check(not os.path.exists(os.path.join(work, "full.h5")), "a failed export left full.h5")
    check(not any(n.endswith(".partial") for n in os.listdir(work)), "a .partial file was left behind")
    return finish()


def finish():
    for f in failures:
        print("FAIL:", f, file=sys.stderr)
    print(f"hdf5 round trip: {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
