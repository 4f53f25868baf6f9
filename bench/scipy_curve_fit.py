#!/usr/bin/env python3
"""SciPy's curve_fit on a session's two channels, beside fogbench's analysis
of the same session in the same run (docs/benchmarks.md, "Analysis at its
floor").

usage: bench/scipy_curve_fit.py CSV_DIR [BENCH_BINARY]

CSV_DIR: `fogbench-cli export SESSION.fbs --csv CSV_DIR` of a one-point
session (run --preset paper-slow: 294 000 table angles, 147 000 gyro
increments). Two curve_fit calls are timed, each started at the planned
frequency, half the table's peak-to-peak and zero phase (fogbench starts its
4-parameter fits from 3-parameter fits, which its time includes): the table angle, A sin(w t + p) + c, and the cumulative gyro
angle, A sin(w t + p) + c + d t. The best of five runs of each is taken.
BENCH_BINARY (build/release/bench/fog_bench_analysis by default) is then
run for BM_AnalyzeSlowSession, the whole analysis (both 3- and 4-parameter
fits of both channels, the noise model, the joint fit, the checks), and the
ratio printed. Only timing: nothing here is a check of fogbench's numbers.
"""
import csv
import json
import subprocess
import sys
import time

import numpy as np
from scipy.optimize import curve_fit


def load(path, column):
    t, v = [], []
    with open(path) as f:
        rows = (line for line in f if not line.startswith('#'))
        for row in csv.DictReader(rows):
            if row['test_point'] == '1':
                t.append(float(row['time_s']))
                v.append(float(row[column]))
    return np.array(t), np.array(v)


def best_of(n, fit):
    best = float('inf')
    for _ in range(n):
        start = time.perf_counter()
        result = fit()
        best = min(best, time.perf_counter() - start)
    return best, result


def main():
    directory = sys.argv[1]
    binary = sys.argv[2] if len(sys.argv) > 2 else 'build/release/bench/fog_bench_analysis'
    with open(f'{directory}/metadata.json') as f:
        meta = json.load(f)
    tt, angle = load(f'{directory}/table.csv', 'x_deg')
    tg, inc = load(f'{directory}/gyro.csv', 'x_inc_deg')
    gyro_angle = np.cumsum(inc[1:])  # the first frame only starts integration
    tg = tg[1:]
    mid = 0.5 * (max(tt[0], tg[0]) + min(tt[-1], tg[-1]))
    tt, tg = tt - mid, tg - mid
    f0 = 0.1
    try:
        f0 = meta['test_points'][0]['frequency_hz']
    except (KeyError, IndexError, TypeError):
        pass
    w0 = 2 * np.pi * f0

    def table_model(t, a, p, c, w):
        return a * np.sin(w * t + p) + c

    def gyro_model(t, a, p, c, d, w):
        return a * np.sin(w * t + p) + c + d * t

    amp = 0.5 * (angle.max() - angle.min())
    table_s, table_fit = best_of(5, lambda: curve_fit(table_model, tt, angle, p0=[amp, 0.0, 0.0, w0]))
    gyro_s, gyro_fit = best_of(5, lambda: curve_fit(gyro_model, tg, gyro_angle, p0=[amp, 0.0, 0.0, 0.0, w0]))
    scipy_ms = 1e3 * (table_s + gyro_s)
    print(f'table samples {len(tt)}, gyro increments {len(tg)}')
    print(f'scipy curve_fit: table {1e3 * table_s:.1f} ms, gyro {1e3 * gyro_s:.1f} ms, both {scipy_ms:.1f} ms')
    print(f'  fitted frequencies: table {table_fit[0][3] / (2 * np.pi):.9f} Hz, gyro {gyro_fit[0][4] / (2 * np.pi):.9f} Hz')
    out = subprocess.run([binary, '--benchmark_filter=BM_AnalyzeSlowSession', '--benchmark_repetitions=5',
                          '--benchmark_format=json'], capture_output=True, text=True, check=True)
    runs = [b for b in json.loads(out.stdout)['benchmarks'] if b.get('run_type') == 'iteration']
    wall = min(b['real_time'] for b in runs)
    cpu = min(b['cpu_time'] for b in runs)
    print(f'fogbench analysis (BM_AnalyzeSlowSession, best of {len(runs)}): {wall:.1f} ms wall, {cpu:.1f} ms CPU')
    print(f'SciPy / fogbench: {scipy_ms / wall:.1f}x (wall)')


if __name__ == '__main__':
    main()
