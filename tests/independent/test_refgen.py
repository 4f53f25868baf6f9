"""Tests of the independent reference generator itself (no C++ involved).

Run from the repository root:
    /usr/bin/python3 -m unittest tests/independent/test_refgen.py -v
or  /usr/bin/python3 -m unittest discover -s tests/independent -v
"""

import csv
import json
import math
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import refgen  # noqa: E402

OMEGA_DEG_S = 15.041067 / 3600.0


def load_json(path):
    with open(path) as fh:
        return json.load(fh)


def quiet(**kw):
    """Parameters without noise, bias or quantisation of the recorded values
    that the test reads (it reads the generator's internal true arrays)."""
    p = refgen.default_params()
    p.update({"arw_deg_sqrt_h": 0.0, "bias_deg_h": 0.0, "encoder_arcsec": 0.0,
              "segments": [{"axis": "x", "freq_hz": 1.0, "amp_deg": 3.0, "duration_s": 12.0}]})
    p.update(kw)
    return p


def fit3(t, y, f, trend=False):
    """Least squares y = a sin wt + b cos wt + c (+ d t) at a known frequency.
    Returns (amplitude, phase rad, coefficients); y = R sin(wt + phase)."""
    w = 2 * math.pi * f
    cols = [np.sin(w * t), np.cos(w * t), np.ones_like(t)]
    if trend:
        cols.append(t)
    X = np.column_stack(cols)
    c, *_ = np.linalg.lstsq(X, y, rcond=None)
    return math.hypot(c[0], c[1]), math.atan2(c[1], c[0]), c


def fit4_freq(t, y, f0, trend=False, iters=8):
    """Frequency-free sine fit (Gauss-Newton); returns the frequency."""
    w = 2 * math.pi * f0
    for _ in range(iters):
        _, _, c = fit3(t, y, w / (2 * math.pi), trend)
        a, b = c[0], c[1]
        cols = [np.sin(w * t), np.cos(w * t), np.ones_like(t)] + ([t] if trend else [])
        cols.append(t * (a * np.cos(w * t) - b * np.sin(w * t)))
        X = np.column_stack(cols)
        model = a * np.sin(w * t) + b * np.cos(w * t) + c[2] + (c[3] * t if trend else 0)
        d, *_ = np.linalg.lstsq(X, y - model, rcond=None)
        w += d[-1]
        if abs(d[-1]) < 1e-15:
            break
    return w / (2 * math.pi)


def lag_from_fits(res, f, use_true=True):
    """Phase difference of the table and the cumulative gyro angle, as a
    time (s): positive when the gyro lags.  Times relative to the window's
    middle."""
    a, b = res["windows"][0]
    mid = 0.5 * (a + b)
    tt = res["table_t"]
    st = (tt >= a) & (tt <= b)
    ty = res["table_true"][:, 0] if use_true else res["table_deg"][:, 0]
    gt = res["frame_stamp"]
    sg = (gt >= a) & (gt <= b)
    gy = res["frame_theta"][:, 0] if use_true else np.cumsum(res["frame_pulses"][:, 0]) * res["pulse_deg"]
    _, ph_t, _ = fit3(tt[st] - mid, ty[st], f)
    _, ph_g, _ = fit3(gt[sg] - mid, gy[sg], f, trend=True)
    d = (ph_t - ph_g + math.pi) % (2 * math.pi) - math.pi
    return d / (2 * math.pi * f)


class Phase(unittest.TestCase):
    def check_lag(self, p, tol_s=1e-6, use_true=True):
        res = refgen.generate(p)
        f = res["swings"][0].f
        lag = lag_from_fits(res, f, use_true)
        true = (res["params"]["imu_delay_ms"] - res["params"]["table_read_delay_ms"]) * 1e-3
        self.assertAlmostEqual(lag, true, delta=tol_s, msg="lag %.9f s, true %.9f s" % (lag, true))
        return res

    def test_zero_noise_lag_is_imu_minus_read_delay(self):
        self.check_lag(quiet())

    def test_zero_noise_commensurate(self):
        self.check_lag(quiet(timing="commensurate"))

    def test_zero_noise_slow_swing_with_bias_and_earth(self):
        self.check_lag(quiet(bias_deg_h=3.0, segments=[{"axis": "x", "freq_hz": 0.1, "amp_deg": 10.0,
                                                          "duration_s": 40.0}]))

    def test_negative_lag(self):
        self.check_lag(quiet(imu_delay_ms=0.1, table_read_delay_ms=0.4))

    def test_acausal(self):
        self.check_lag(quiet(imu_delay_ms=-25.0, segments=[{"axis": "x", "freq_hz": 0.1, "amp_deg": 10.0,
                                                               "duration_s": 40.0}]))

    def test_other_axes_and_heading(self):
        for axis in "yz":
            p = quiet(heading_deg=33.0, segments=[{"axis": axis, "freq_hz": 0.7, "amp_deg": 5.0,
                                                  "duration_s": 15.0}])
            res = refgen.generate(p)
            a, b = res["windows"][0]
            i = "xyz".index(axis)
            mid = 0.5 * (a + b)
            f = res["swings"][0].f
            tt, gt = res["table_t"], res["frame_stamp"]
            st, sg = (tt >= a) & (tt <= b), (gt >= a) & (gt <= b)
            _, ph_t, _ = fit3(tt[st] - mid, res["table_true"][st, i], f)
            _, ph_g, _ = fit3(gt[sg] - mid, res["frame_theta"][sg, i], f, trend=True)
            lag = ((ph_t - ph_g + math.pi) % (2 * math.pi) - math.pi) / (2 * math.pi * f)
            self.assertAlmostEqual(lag, 0.45e-3, delta=1e-6)

    def test_written_data_lag_within_noise(self):
        # Quantised and noisy, as written: 1 Hz / 3 deg, 60 s.  The lag's
        # noise is ~0.2 us, so 1 us is a wide margin.
        p = refgen.case_params("nominal")
        self.check_lag(p, tol_s=1e-6, use_true=False)

    def test_numeric_integration_matches_the_analytic_angle(self):
        # The swing axis is the inner axis: the gyro angle is the table angle
        # tau earlier plus the Earth rate's constant component on that axis.
        p = quiet(fine_hz=10000.0)
        res = refgen.generate(p)
        sw = res["swings"][0]
        tau = p["imu_delay_ms"] * 1e-3
        tf = res["frame_t_true"]
        ang, _ = sw.eval(tf - tau)
        earth = OMEGA_DEG_S * math.cos(math.radians(40.0))
        expect = ang - ang[0] + earth * (tf - tf[0])
        got = res["frame_theta"][:, 0] - res["frame_theta"][0, 0]
        # The trapezoid rule has no phase error on a sinusoid; its gain is
        # 1 - (w dt)^2 / 12 (3e-8 at 1 Hz, 10 kHz): ~1e-7 deg on 3 deg.
        w_dt = 2 * math.pi * 1.0 * res["fine_dt_s"]
        self.assertLess(np.max(np.abs(got - expect)), 2 * 3.0 * w_dt**2 / 12 * 1.1)


class EarthRate(unittest.TestCase):
    def static_rates(self, **kw):
        p = quiet(segments=[{"axis": "z", "freq_hz": 1.0, "amp_deg": 0.0, "duration_s": 20.0}], **kw)
        res = refgen.generate(p)
        t = res["frame_t_true"]
        th = res["frame_theta"]
        return np.array([np.polyfit(t, th[:, i], 1)[0] for i in range(3)])

    def test_level_north(self):
        r = self.static_rates(latitude_deg=40.0)
        lat = math.radians(40.0)
        np.testing.assert_allclose(r, [OMEGA_DEG_S * math.cos(lat), 0.0, -OMEGA_DEG_S * math.sin(lat)],
                                   atol=1e-12)

    def test_heading_rotates_the_local_frame(self):
        psi, lat = math.radians(30.0), math.radians(52.0)
        r = self.static_rates(latitude_deg=52.0, heading_deg=30.0)
        om = OMEGA_DEG_S
        np.testing.assert_allclose(r, [om * math.cos(lat) * math.cos(psi), -om * math.cos(lat) * math.sin(psi),
                                       -om * math.sin(lat)], atol=1e-12)

    def test_z_up_east_north_up(self):
        # Heading 90 with z up: x east, y north, z up. The Earth rate
        # Omega (cos lat, 0, -sin lat) in NED reads (0, Omega cos lat,
        # +Omega sin lat) in these axes; the specific force at rest, -1 g
        # along down, is +1 g along the body's z (up).
        lat = math.radians(40.0)
        r = self.static_rates(latitude_deg=40.0, heading_deg=90.0, z_up=True)
        np.testing.assert_allclose(r, [0.0, OMEGA_DEG_S * math.cos(lat), OMEGA_DEG_S * math.sin(lat)], atol=1e-12)
        f = refgen.specific_force(np.zeros((1, 3)), quiet(heading_deg=90.0, z_up=True))[0]
        np.testing.assert_allclose(f, [0.0, 0.0, 1.0], atol=1e-15)
        f = refgen.specific_force(np.zeros((1, 3)), quiet())[0]
        np.testing.assert_allclose(f, [0.0, 0.0, -1.0], atol=1e-15)

    def test_z_up_at_heading_zero(self):
        # z up, heading 0: x north, y west, z up.
        lat = math.radians(52.0)
        r = self.static_rates(latitude_deg=52.0, z_up=True)
        np.testing.assert_allclose(r, [OMEGA_DEG_S * math.cos(lat), 0.0, OMEGA_DEG_S * math.sin(lat)], atol=1e-12)

    def test_tilted_inner_axis(self):
        # x (inner) at +90 deg: body y points Down, body z points West.
        r = self.static_rates(fixed_angles_deg=[90.0, 0.0, 0.0])
        lat = math.radians(40.0)
        np.testing.assert_allclose(r, [OMEGA_DEG_S * math.cos(lat), -OMEGA_DEG_S * math.sin(lat), 0.0],
                                   atol=1e-12)

    def test_swing_axis_component_in_truth_and_in_the_data(self):
        p = quiet(bias_deg_h=[2.0, 0.0, 0.0])
        res = refgen.generate(p)
        tr = refgen.truth(res)
        lat = math.radians(40.0)
        self.assertAlmostEqual(tr["test_points"][0]["earth_rate_on_swing_axis_deg_h"],
                               15.041067 * math.cos(lat), places=9)
        self.assertAlmostEqual(tr["test_points"][0]["expected_trend_deg_h"], 15.041067 * math.cos(lat) + 2.0,
                               places=9)
        # Trend of the cumulative swing-axis angle
        a, b = res["windows"][0]
        mid = 0.5 * (a + b)
        _, _, c = fit3(res["frame_stamp"] - mid, res["frame_theta"][:, 0], 1.0, trend=True)
        self.assertAlmostEqual(c[3] * 3600.0, 15.041067 * math.cos(lat) + 2.0, delta=1e-6)

    def test_cross_axis_sees_the_rotated_earth_rate(self):
        # Swinging x: body y sees -sin(angle) * Omega sin(lat) (NED, down component).
        p = quiet(segments=[{"axis": "x", "freq_hz": 0.2, "amp_deg": 20.0, "duration_s": 10.0}])
        res = refgen.generate(p)
        sw = res["swings"][0]
        tau = p["imu_delay_ms"] * 1e-3
        tf = res["frame_t_true"]
        fine = np.linspace(tf[0], tf[-1], 200001)
        ang, _ = sw.eval(fine - tau)
        ry = -np.sin(np.radians(ang)) * OMEGA_DEG_S * math.sin(math.radians(40.0))
        integ = np.concatenate([[0.0], np.cumsum(0.5 * (ry[1:] + ry[:-1]) * np.diff(fine))])
        got = res["frame_theta"][:, 1] - res["frame_theta"][0, 1]
        self.assertLess(abs(got[-1] - integ[-1]), 1e-9)
        self.assertGreater(np.ptp(got), 1e-5)


class Pulses(unittest.TestCase):
    def test_integer_pulses_carry_the_remainder(self):
        p = refgen.case_params("nominal")
        p["segments"][0]["duration_s"] = 10.0
        res = refgen.generate(p)
        pe = res["pulse_deg"]
        self.assertEqual(res["frame_pulses"].dtype.kind, "i")
        cum = np.cumsum(res["frame_pulses"], axis=0) * pe
        # frame_theta[0] is the end of the first written frame; the pulse
        # count before it is floor(theta_before / pe).
        true = res["frame_theta"] - (res["frame_theta"][0] - res["frame_pulses"][0] * pe)
        err = cum - true
        self.assertLess(np.max(np.abs(err)), pe * (1 + 1e-9))
        # the error is a sawtooth in [-(pe), pe]: no drift
        self.assertLess(abs(np.mean(err[-1000:, 0]) - np.mean(err[:1000, 0])), pe)

    def test_written_increments_are_whole_pulses(self):
        with tempfile.TemporaryDirectory() as d:
            p = refgen.case_params("nominal")
            p["segments"][0]["duration_s"] = 5.0
            res = refgen.generate(p)
            refgen.write_dir(res, os.path.join(d, "o"))
            pe = 0.18 / 3600.0
            with open(os.path.join(d, "o", "gyro.csv")) as fh:
                rows = [r for r in csv.reader(fh) if r and not r[0].startswith("#")]
            self.assertEqual(rows[0], ["time_s", "x_inc_deg", "y_inc_deg", "z_inc_deg"])
            v = np.array([[float(x) for x in r[1:]] for r in rows[1:]])
            n = v / pe
            self.assertLess(np.max(np.abs(n - np.round(n))), 1e-6)


class Defects(unittest.TestCase):
    def test_reversed_sign_negates(self):
        a = refgen.generate(quiet(gyro_sign=[1, 1, 1]))
        b = refgen.generate(quiet(gyro_sign=[-1, 1, 1]))
        ta = a["frame_theta"][:, 0] - a["frame_theta"][0, 0]
        tb = b["frame_theta"][:, 0] - b["frame_theta"][0, 0]
        np.testing.assert_allclose(tb, -ta, atol=1e-12)
        np.testing.assert_allclose(b["frame_theta"][:, 1:], a["frame_theta"][:, 1:], atol=1e-15)

    def test_reversed_case_gives_ratio_minus_one(self):
        p = refgen.case_params("reversed_axis")
        p["segments"][0]["duration_s"] = 10.0
        res = refgen.generate(p)
        a, b = res["windows"][0]
        mid = 0.5 * (a + b)
        st = (res["table_t"] >= a) & (res["table_t"] <= b)
        sg = (res["frame_stamp"] >= a) & (res["frame_stamp"] <= b)
        _, _, ct = fit3(res["table_t"][st] - mid, res["table_deg"][st, 0], 0.5)
        _, _, cg = fit3(res["frame_stamp"][sg] - mid, res["frame_theta"][sg, 0], 0.5, trend=True)
        ratio = (cg[0] * ct[0] + cg[1] * ct[1]) / (ct[0] ** 2 + ct[1] ** 2)
        self.assertAlmostEqual(ratio, -1.0, delta=1e-4)

    def test_clock_rate_50ppm_changes_the_fitted_period(self):
        p = quiet(clock_rate_ppm_gyro=50.0, segments=[{"axis": "x", "freq_hz": 1.0, "amp_deg": 3.0,
                                                       "duration_s": 20.0}])
        res = refgen.generate(p)
        a, b = res["windows"][0]
        mid = 0.5 * (a + b)
        st = (res["table_t"] >= a) & (res["table_t"] <= b)
        sg = (res["frame_stamp"] >= a) & (res["frame_stamp"] <= b)
        ft = fit4_freq(res["table_t"][st] - mid, res["table_true"][st, 0], 1.0)
        fg = fit4_freq(res["frame_stamp"][sg] - mid, res["frame_theta"][sg, 0], 1.0, trend=True)
        self.assertAlmostEqual(ft, 1.0, delta=1e-9)
        # gyro period longer by 50 ppm
        self.assertAlmostEqual((1 / fg) / (1 / ft) - 1, 50e-6, delta=0.1e-6)

    def test_imu_crystal_fast_means_shorter_frames(self):
        # the one sign convention with fogbench (ImuBoardParams::clockErrorPpm):
        # +ppm = the crystal runs fast = frames of imu_period_ms / (1 + ppm)
        res = refgen.generate(quiet(imu_clock_ppm=40.0, timing="commensurate"))
        mean = np.mean(np.diff(res["frame_stamp"]))
        self.assertAlmostEqual((mean / 2e-3 - 1.0) * 1e6, 1.0 / (1.0 + 40e-6) * 1e6 - 1e6, delta=1e-3)
        self.assertLess(mean, 2e-3)

    def test_table_frequency_error(self):
        p = quiet(table_freq_error_ppm=200.0)
        res = refgen.generate(p)
        a, b = res["windows"][0]
        st = (res["table_t"] >= a) & (res["table_t"] <= b)
        ft = fit4_freq(res["table_t"][st] - 0.5 * (a + b), res["table_true"][st, 0], 1.0)
        self.assertAlmostEqual(ft, 1.0002, delta=1e-9)
        self.assertAlmostEqual(lag_from_fits(res, ft), 0.45e-3, delta=1e-6)

    def test_jitter_rms(self):
        res = refgen.generate(quiet(gyro_stamp_jitter_us=20.0))
        d = res["frame_stamp"] - res["frame_t_true"]
        self.assertAlmostEqual(np.std(d) * 1e6, 20.0, delta=1.0)
        self.assertTrue(np.all(np.diff(res["frame_stamp"]) > 0))

    def test_bias_step(self):
        p = quiet(bias_step_deg_h=[36.0, 0, 0], bias_step_time_s=7.0,
                  segments=[{"axis": "x", "freq_hz": 1.0, "amp_deg": 0.0, "duration_s": 12.0}])
        res = refgen.generate(p)
        t, th = res["frame_t_true"], res["frame_theta"][:, 0]
        r1 = np.polyfit(t[(t > 2) & (t < 6.9)], th[(t > 2) & (t < 6.9)], 1)[0]
        r2 = np.polyfit(t[(t > 7.1) & (t < 12)], th[(t > 7.1) & (t < 12)], 1)[0]
        self.assertAlmostEqual((r2 - r1) * 3600.0, 36.0, delta=1e-6)

    def test_bias_instability_statistics(self):
        # stationary Gauss-Markov: variance sigma^2, autocorrelation exp(-lag/tau)
        p = refgen.resolve(quiet(bias_instability_deg_h=36.0, bias_correlation_s=10.0))
        t, x = refgen.gauss_markov(p, 0.0, 20000.0)
        self.assertAlmostEqual(t[1] - t[0], 0.1, places=12)
        self.assertAlmostEqual(np.std(x) * 3600.0 / 36.0, 1.0, delta=0.04)
        k = 100  # one correlation time
        r = np.mean([np.corrcoef(x[:-k, a], x[k:, a])[0, 1] for a in range(3)])
        self.assertAlmostEqual(r, math.exp(-1.0), delta=0.04)

    def test_bias_instability_reaches_the_gyros(self):
        # the wander is added to the measured rate: the angle difference to
        # the same session without it is the wander's integral
        seg = [{"axis": "x", "freq_hz": 1.0, "amp_deg": 0.0, "duration_s": 12.0}]
        base = refgen.generate(quiet(segments=seg))
        p = quiet(segments=seg, bias_instability_deg_h=360.0, bias_correlation_s=5.0)
        res = refgen.generate(p)
        t = res["frame_t_true"]
        grid, w = res["bias_wander"]
        self.assertLess(grid[0], t[0])
        self.assertGreater(grid[-1], t[-1])
        fine = np.linspace(t[0], t[-1], 200001)
        wf = np.interp(fine, grid, w[:, 1])
        expect = np.concatenate([[0.0], np.cumsum(0.5 * (wf[1:] + wf[:-1]) * np.diff(fine))])
        got = res["frame_theta"][:, 1] - base["frame_theta"][:, 1]
        got -= got[0]
        pe = p.get("pulse_arcsec", 0.18) / 3600.0
        self.assertLess(np.max(np.abs(got - np.interp(t, fine, expect))), 2 * pe + 1e-9)
        self.assertGreater(np.max(np.abs(got)), 100 * pe)

    def test_arw_level(self):
        # increments' scatter from ARW: std = ARW/60 * sqrt(frame period)
        p = quiet(arw_deg_sqrt_h=0.5, segments=[{"axis": "x", "freq_hz": 1.0, "amp_deg": 0.0,
                                                 "duration_s": 30.0}])
        res = refgen.generate(p)
        d = np.diff(res["frame_theta"][:, 0])
        self.assertAlmostEqual(np.std(d) / (0.5 / 60 * math.sqrt(2e-3)), 1.0, delta=0.03)

    def test_decay_and_drift_envelopes(self):
        res = refgen.generate(refgen.case_params("pendulum"))
        tr = refgen.truth(res)["test_points"][0]
        self.assertAlmostEqual(tr["amplitude_deg_at_end"], 10.0 * math.exp(-60.0 / 30.0), places=9)
        a, b = res["windows"][0]
        last = (res["table_t"] > b - 1.5) & (res["table_t"] <= b)
        self.assertAlmostEqual(np.max(np.abs(res["table_true"][last, 0])), 10 * math.exp(-59.3 / 30), delta=0.05)
        res = refgen.generate(refgen.case_params("amplitude_drift"))
        tr = refgen.truth(res)["test_points"][0]
        self.assertAlmostEqual(tr["amplitude_deg_at_end"] / tr["amplitude_deg_at_start"], 0.7, places=9)

    def test_repeated_decays_are_smooth(self):
        res = refgen.generate(refgen.case_params("repeated_decays"))
        sw = res["swings"][0]
        t = np.linspace(1.0, 61.0, 600001)
        e, de = sw.envelope(t)
        self.assertLess(np.max(np.abs(np.diff(e))), 1e-3)       # continuous
        self.assertLess(np.max(np.abs(np.diff(de))), 1e-2)      # C1
        # numeric derivative agrees with the analytic one
        num = np.gradient(e, t)
        self.assertLess(np.max(np.abs(num - de)[1:-1]), 1e-3)
        # re-excited: the amplitude is back near 10 deg every 15 s
        self.assertGreater(e[np.searchsorted(t, 1.0 + 15.0 + 0.01)], 9.5)

    def test_rates(self):
        p = quiet(rate_output="frame_average")
        res = refgen.generate(p)
        np.testing.assert_allclose(res["gyro_val"] * 2e-3, res["frame_pulses"] * res["pulse_deg"], atol=1e-15)
        p = quiet(rate_output="sample_at_stamp")
        res = refgen.generate(p)
        sw = res["swings"][0]
        _, r = sw.eval(res["frame_t_true"] - p["imu_delay_ms"] * 1e-3)
        earth = OMEGA_DEG_S * math.cos(math.radians(40.0))
        np.testing.assert_allclose(res["gyro_val"][:, 0], r + earth, atol=1e-12)

    def test_sample_and_hold_duplicates_rows(self):
        p = quiet(rate_output="frame_average", sample_hold_ms=1.0)
        res = refgen.generate(p)
        self.assertTrue(np.all(np.diff(res["gyro_t"]) > 0))
        src = res["gyro_from_frame"]
        counts = np.bincount(src - src[0])
        self.assertTrue(set(np.unique(counts[1:-1])) <= {1, 2, 3})
        self.assertAlmostEqual(np.mean(counts[1:-1]), 2.0, delta=0.01)
        # every row's stamp is at or after the frame it holds
        self.assertTrue(np.all(res["gyro_t"] >= res["frame_stamp"][src]))



def swing_fit(res, axis_i, f, use="gyro", h=1):
    """Complex amplitude (sin + i cos coefficients) of harmonic h of the
    true table angle or the continuous gyro angle on one axis, over the
    window; times from the window's start."""
    a, b = res["windows"][0]
    if use == "table":
        t, y = res["table_t"], res["table_true"][:, axis_i]
    elif use == "table_read":
        t, y = res["table_t"], res["table_deg"][:, axis_i]
    else:
        t, y = res["frame_stamp"], res["frame_theta"][:, axis_i]
    sel = (t >= a) & (t <= b)
    t, y = t[sel] - a, y[sel]
    w = 2 * math.pi * f
    cols = []
    for k in (1, 2, 3):
        cols += [np.sin(k * w * t), np.cos(k * w * t)]
    cols += [np.ones_like(t), t]
    c, *_ = np.linalg.lstsq(np.column_stack(cols), y, rcond=None)
    return complex(c[2 * h - 2], c[2 * h - 1]), c


def ratio_to_lag_gain(z_gyro, z_table, f):
    r = z_gyro / z_table      # gyro = table delayed by tau: ratio g e^{-i w tau}
    return -math.atan2(r.imag, r.real) / (2 * math.pi * f), abs(r)


OFF = {"base_tilt_deg": 0.0, "nonorth_inner_arcsec": 0.0, "nonorth_middle_arcsec": 0.0, "eccentricity_um": 0.0,
       "compliance_fn_hz": 0.0, "servo_unbalance_arcsec": 0.0, "mount_rpy_arcsec": [0.0, 0.0, 0.0],
       "register_period_ms": 0.0, "boxcar_ms": 0.0, "latency_p2": 0.0, "latency_sigma_us": 0.0,
       "rrw_deg_h_sqrt_h": 0.0, "flicker_deg_h": 0.0, "table_drop_per_mille": 0.0, "second_order_fn_hz": 0.0}


class PhysicalForms(unittest.TestCase):
    """Effects in their own physical parameterisation, each against a closed form."""

    def test_off_leaves_every_output_as_before(self):
        # every new parameter at its off value, other parameters changed
        # beside it (they must not be read): the same arrays bit for bit
        p = refgen.case_params("nominal")
        p["segments"][0]["duration_s"] = 5.0
        q = dict(p, **OFF, base_tilt_azimuth_deg=40.0, eccentricity_radius_mm=7.0, eccentricity_phase_deg=9.0,
                 compliance_zeta=0.3, servo_corner_hz=5.0, register_offset_ms=0.3, latency_delta_us=50.0,
                 latency_dwell_s=1.0, flicker_tau_range_s=[3.0, 30.0], second_order_zeta=0.2)
        a, b = refgen.generate(p), refgen.generate(q)
        for k in ("table_t", "table_deg", "gyro_t", "gyro_val", "frame_theta"):
            self.assertTrue(np.array_equal(a[k], b[k]), k)
        self.assertEqual(refgen.physical_effects(b), {})

    def test_base_tilt_turns_earth_rate_and_gravity(self):
        lat, beta = 40.0, 2.0
        om, sl, cl = OMEGA_DEG_S, math.sin(math.radians(lat)), math.cos(math.radians(lat))
        sb, cb = math.sin(math.radians(beta)), math.cos(math.radians(beta))
        z = np.zeros((1, 3))
        # about north (azimuth 0): R_x(beta)^T (a, 0, c) = (a, c sin b, c cos b)
        p = quiet(latitude_deg=lat, base_tilt_deg=beta, base_tilt_azimuth_deg=0.0)
        np.testing.assert_allclose(refgen.body_rates(z, z, p)[0], [om * cl, -om * sl * sb, -om * sl * cb],
                                   atol=1e-15)
        np.testing.assert_allclose(refgen.specific_force(z, p)[0], [0.0, -sb, -cb], atol=1e-15)
        # about east (azimuth 90): R_y(beta)^T (a, 0, c) = (a cos b - c sin b, 0, a sin b + c cos b)
        p = quiet(latitude_deg=lat, base_tilt_deg=beta, base_tilt_azimuth_deg=90.0)
        np.testing.assert_allclose(refgen.body_rates(z, z, p)[0],
                                   [om * cl * cb + om * sl * sb, 0.0, om * cl * sb - om * sl * cb], atol=1e-15)
        np.testing.assert_allclose(refgen.specific_force(z, p)[0], [sb, 0.0, -cb], atol=1e-15)

    def test_axis_nonorthogonality(self):
        ei, em = 20.0, 30.0
        si, ci = math.sin(math.radians(ei / 3600)), math.cos(math.radians(ei / 3600))
        sm, cm = math.sin(math.radians(em / 3600)), math.cos(math.radians(em / 3600))
        z = np.zeros((1, 3))
        p = quiet(nonorth_inner_arcsec=ei, nonorth_middle_arcsec=em)
        earth = refgen.body_rates(z, z, p)[0]
        # the middle axis' rate in the body: R_z(ei)^T e_y = (sin ei, cos ei, 0)
        np.testing.assert_allclose(refgen.body_rates(z, np.array([[0.0, 1.0, 0.0]]), p)[0] - earth,
                                   [si, ci, 0.0], atol=1e-15)
        # the outer axis': R_z(ei)^T R_x(em)^T e_z = R_z(-ei) (0, sin em, cos em)
        np.testing.assert_allclose(refgen.body_rates(z, np.array([[0.0, 0.0, 1.0]]), p)[0] - earth,
                                   [sm * si, sm * ci, cm], atol=1e-15)
        # in the data: a Y swing puts sin(ei) of its angle into gyro x, in phase
        res = refgen.generate(quiet(nonorth_inner_arcsec=ei, imu_delay_ms=0.0, table_read_delay_ms=0.0,
                                    latitude_deg=0.0,
                                    segments=[{"axis": "y", "freq_hz": 1.0, "amp_deg": 3.0, "duration_s": 6.0}]))
        zt, _ = swing_fit(res, 1, 1.0, "table")
        zx, _ = swing_fit(res, 0, 1.0)
        self.assertAlmostEqual((zx / zt).real, si, delta=1e-9)
        self.assertAlmostEqual((zx / zt).imag, 0.0, delta=1e-9)

    def test_encoder_eccentricity_once_per_revolution(self):
        e_um, r_mm, phi = 3.0, 60.0, 35.0
        res = refgen.generate(quiet(eccentricity_um=e_um, eccentricity_radius_mm=r_mm, eccentricity_phase_deg=phi,
                                    eccentricity_axes="x", fixed_angles_deg=[0.0, 0.0, 100.0]))
        th = res["table_true"]
        want = math.degrees(e_um * 1e-3 / r_mm) * np.sin(np.deg2rad(th[:, 0]) + math.radians(phi))
        np.testing.assert_allclose(res["table_deg"][:, 0] - th[:, 0], want, atol=1e-15)
        np.testing.assert_array_equal(res["table_deg"][:, 2], th[:, 2])   # z's encoder not eccentric
        self.assertAlmostEqual(refgen.physical_effects(res)["eccentricity_rad"], 5e-5, places=15)

    def test_compliance_is_a_spring_damper(self):
        fn, zeta, f = 20.0, 0.1, 2.0
        seg = [{"axis": "x", "freq_hz": f, "amp_deg": 3.0, "duration_s": 5.0}]
        res = refgen.generate(quiet(compliance_fn_hz=fn, compliance_zeta=zeta, segments=seg))
        rigid = refgen.generate(quiet(segments=seg))
        lag, gain = ratio_to_lag_gain(swing_fit(res, 0, f)[0], swing_fit(res, 0, f, "table")[0], f)
        lag0, gain0 = ratio_to_lag_gain(swing_fit(rigid, 0, f)[0], swing_fit(rigid, 0, f, "table")[0], f)
        s = 2j * math.pi * f / (2 * math.pi * fn)
        H = (2 * zeta * s + 1) / (s * s + 2 * zeta * s + 1)
        # within 1e-5 of the 1 % effect (the 0.25-ms grid, inputs linear between its points)
        self.assertAlmostEqual(gain / gain0, abs(H), delta=1e-7)
        self.assertAlmostEqual(lag - lag0, -np.angle(H) / (2 * math.pi * f), delta=1e-10)
        # the fixture's rate is the derivative of its angle (Hermite between grid points)
        p = res["params"]
        t = np.linspace(3.0, 3.01, 201)
        a, r = refgen.table_state(t, res["swings"], p, fixture=True)
        # (central differences of 50 us err by w^3 A h^2 / 6 = 2.5e-6 deg/s here)
        np.testing.assert_allclose(np.gradient(a[:, 0], t)[1:-1], r[1:-1, 0], rtol=0, atol=1e-5)

    def test_servo_unbalance(self):
        eps, phi = 20.0, 50.0
        # static: the motion is theta + eps sin(theta + phi), read and sensed alike
        res = refgen.generate(quiet(servo_unbalance_arcsec=eps, servo_unbalance_phase_deg=phi))
        p = res["params"]
        t = res["table_t"][:500]
        cmd, _ = refgen.commanded_state(t - p["table_read_delay_ms"] * 1e-3, res["swings"], p)
        want = eps / 3600 * np.sin(np.deg2rad(cmd[:, 0]) + math.radians(phi))
        np.testing.assert_allclose(res["table_true"][:500, 0] - cmd[:, 0], want, atol=1e-15)
        # through a first-order disturbance response of corner fc: the 2nd
        # harmonic eps sin(phi) A^2/4 (cos 2 psi) with gain 1/|1 + 2 i w tau|
        fc, f, A = 3.0, 1.0, 2.0
        res = refgen.generate(quiet(servo_unbalance_arcsec=eps, servo_unbalance_phase_deg=phi, servo_corner_hz=fc,
                                    timing="commensurate", table_read_delay_ms=0.0,
                                    segments=[{"axis": "x", "freq_hz": f, "amp_deg": A, "duration_s": 6.0,
                                               "start_phase_deg": 0.0}]))
        z2, _ = swing_fit(res, 0, f, "table", h=2)
        epsr, a = math.radians(eps / 3600), math.radians(A)
        want = -math.radians(0) + epsr * math.sin(math.radians(phi)) * a * a / 4 / (1 + 2j * f / fc)
        # cos(2 psi) is the cos coefficient: complex(sin coeff, cos coeff) = i * want
        got = complex(math.radians(z2.real), math.radians(z2.imag))
        self.assertAlmostEqual(abs(got - 1j * want) / abs(want), 0.0, delta=2e-3)
        # the rate is the angle's derivative
        t = np.linspace(3.0, 3.01, 201)
        a_, r_ = refgen.table_state(t, res["swings"], res["params"])
        np.testing.assert_allclose(np.gradient(a_[:, 0], t)[1:-1], r_[1:-1, 0], rtol=0, atol=1e-6)

    def test_mount_rotation_is_an_antisymmetric_misalignment(self):
        rpy = [40.0, -60.0, 80.0]
        seg = [{"axis": "x", "freq_hz": 1.0, "amp_deg": 3.0, "duration_s": 6.0}]
        res = refgen.generate(quiet(mount_rpy_arcsec=rpy, segments=seg, latitude_deg=0.0, imu_delay_ms=0.0,
                                    table_read_delay_ms=0.0))
        rigid = refgen.generate(quiet(segments=seg, latitude_deg=0.0, imu_delay_ms=0.0, table_read_delay_ms=0.0))
        # the trapezoid's own gain (1 - (w dt)^2 / 12) from the session without the rotation
        zt = swing_fit(res, 0, 1.0, "table")[0] * swing_fit(rigid, 0, 1.0)[0] / swing_fit(rigid, 0, 1.0, "table")[0]
        r_, p_, y_ = (math.radians(v / 3600) for v in rpy)
        Rm = refgen.rot("x", rpy[0] / 3600) @ refgen.rot("y", rpy[1] / 3600) @ refgen.rot("z", rpy[2] / 3600)
        for i in range(3):       # gyro i senses (R_m^T e_x)_i = R_m[0, i] of the X rate
            zg, _ = swing_fit(res, i, 1.0)
            self.assertAlmostEqual((zg / zt).real, Rm[0, i], delta=2e-9)
        # small angles: m_yx = -yaw, m_zx = +pitch
        self.assertAlmostEqual(Rm[0, 1], -y_, delta=1e-7)
        self.assertAlmostEqual(Rm[0, 2], p_, delta=1e-7)
        eq = refgen.physical_effects(res)["mount_equivalent_misalignment_urad"]
        self.assertAlmostEqual(eq[2], -y_ * 1e6, places=9)
        self.assertAlmostEqual(eq[4], p_ * 1e6, places=9)

    def test_g_sensitivity_per_gyro(self):
        k = [10.0, -20.0, 30.0]
        pos = [30.0, -15.0, 0.0]
        seg = [{"axis": "x", "freq_hz": 1.0, "amp_deg": 0.0, "duration_s": 6.0, "centre_deg": 0.0}]
        res = refgen.generate(quiet(g_sens_deg_h_g=k, fixed_angles_deg=pos, segments=seg))
        ang = np.array([pos])
        want = refgen.body_rates(ang, np.zeros((1, 3)), res["params"])[0] * 3600 + \
            np.array(k) * refgen.specific_force(ang, res["params"])[0]
        t, th = res["frame_t_true"], res["frame_theta"]
        for i in range(3):
            self.assertAlmostEqual(np.polyfit(t, th[:, i], 1)[0] * 3600, want[i], delta=1e-6)

    def test_register_update_is_a_pure_delay(self):
        # the register on the IMU crystal, updated every 0.5 ms, last 0.3 ms
        # before each frame's end: the frame reports the angle 0.3 ms old
        for timing in ("commensurate", "incommensurate"):
            res = refgen.generate(quiet(register_period_ms=0.5, register_offset_ms=0.3, timing=timing,
                                        segments=[{"axis": "x", "freq_hz": 2.0, "amp_deg": 3.0, "duration_s": 6.0}]))
            f = res["swings"][0].f
            self.assertAlmostEqual(lag_from_fits(res, f), 0.45e-3 + 0.3e-3, delta=1e-8)
            self.assertEqual(refgen.physical_effects(res)["register_extra_delay_ms"], 0.3)
        # its own clock 100 ppm fast: the delay walks from 0 to 0.5 ms and back every 0.5 ms / 100 ppm = 5 s
        res = refgen.generate(quiet(register_period_ms=0.5, register_offset_ms=0.0, register_clock_ppm=100.0,
                                    segments=[{"axis": "x", "freq_hz": 0.0, "amp_deg": 0.0, "duration_s": 6.0}],
                                    bias_deg_h=3600.0 * 10.0, latitude_deg=90.0))
        # a constant 10 deg/s (+ Earth rate along -z only): the held angle lags by u
        t, th = res["frame_t_true"], res["frame_theta"][:, 0]
        u = t - th / 10.0
        u = u - u[0]
        self.assertGreater(np.ptp(u), 0.45e-3)
        self.assertLess(np.ptp(u), 0.5e-3 + 1e-9)

    def test_boxcar_is_a_delay_and_a_sinc(self):
        T, f = 6e-3, 2.0
        seg = [{"axis": "x", "freq_hz": f, "amp_deg": 3.0, "duration_s": 6.0}]
        res = refgen.generate(quiet(boxcar_ms=T * 1e3, segments=seg))
        plain = refgen.generate(quiet(segments=seg))
        lag, gain = ratio_to_lag_gain(swing_fit(res, 0, f)[0], swing_fit(res, 0, f, "table")[0], f)
        lag0, gain0 = ratio_to_lag_gain(swing_fit(plain, 0, f)[0], swing_fit(plain, 0, f, "table")[0], f)
        x = math.pi * f * T
        Tt = 60 * res["fine_dt_s"]       # 60 fine steps of the IMU crystal (off round by up to 30 ppm)
        x = math.pi * f * Tt
        self.assertAlmostEqual(lag - lag0, Tt / 2, delta=1e-10)
        # (the boxcar's own trapezoid integral of the rate: (w dt)^2 / 12 = 1.3e-7 at 2 Hz)
        self.assertAlmostEqual(gain / gain0, math.sin(x) / x, delta=3e-7)
        # the same loss of gain as a first-order lag of T / sqrt(12), to O(f^2)
        tau = refgen.physical_effects(res)["boxcar_equivalent_lag_ms"] * 1e-3
        self.assertAlmostEqual(1 - gain / gain0, (2 * math.pi * f * tau) ** 2 / 2, delta=3e-7)  # O(f^4): 1e-7

    def test_second_order_filter_gain_and_phase(self):
        # a steady sinusoid through y'' + 2 zeta wn y' + wn^2 y = wn^2 x:
        # gyro / (the same without the filter) = 1 / (1 - r^2 + 2 i zeta r), r = f / fn
        fn = 40.0
        for zeta in (0.15, 0.7):
            for f in (2.0, 10.0, 30.0):
                seg = [{"axis": "x", "freq_hz": f, "amp_deg": 1.0, "duration_s": 2.0}]
                res = refgen.generate(quiet(second_order_fn_hz=fn, second_order_zeta=zeta, segments=seg))
                plain = refgen.generate(quiet(segments=seg))
                self.assertEqual(res["params"]["_gyro_offset_s"], plain["params"]["_gyro_offset_s"])
                r = swing_fit(res, 0, f)[0] / swing_fit(plain, 0, f)[0]
                q = f / fn            # the ODE runs in true time, like the swing
                h = 1.0 / complex(1.0 - q * q, 2.0 * zeta * q)
                # the rate linear between fine points: a gain of sinc^2(f dt) = 1 - (w dt)^2 / 12
                # (3e-5 at 30 Hz, 10 kHz), and nothing else
                x = math.pi * f * res["fine_dt_s"]
                msg = "zeta %g, %g Hz: ratio %r, closed form %r" % (zeta, f, r, h)
                self.assertAlmostEqual(abs(r) / abs(h), (math.sin(x) / x) ** 2, delta=1e-9, msg=msg)
                self.assertAlmostEqual(math.atan2(r.imag, r.real), math.atan2(h.imag, h.real), delta=1e-8, msg=msg)
                # its group delay at 0 Hz in physical_effects: 2 zeta / wn
                self.assertAlmostEqual(refgen.physical_effects(res)["second_order_low_frequency_delay_ms"],
                                       2 * zeta / (2 * math.pi * fn) * 1e3, delta=1e-15)
        with self.assertRaises(ValueError):
            refgen.generate(quiet(second_order_fn_hz=fn, second_order_zeta=1.0))

    def test_latency_mixture(self):
        p = refgen.resolve(quiet(latency_p2=0.2, latency_delta_us=30.0, latency_sigma_us=2.0))
        ft = 2e-3 * np.arange(300000)
        lat = refgen.frame_latency(p, ft) * 1e6
        self.assertAlmostEqual(np.mean(lat), 0.2 * 30.0, delta=0.1)
        self.assertAlmostEqual(np.var(lat), 0.2 * 0.8 * 900 + 4.0, delta=3.0)
        self.assertLess(abs(np.corrcoef(lat[:-1], lat[1:])[0, 1]), 0.01)       # white
        # a two-state Markov chain: stationary share p2, mean dwell in mode 2
        p = refgen.resolve(quiet(latency_p2=0.3, latency_delta_us=30.0, latency_dwell_s=0.1))
        mode = refgen.frame_latency(p, ft) > 15.0e-6
        self.assertAlmostEqual(mode.mean(), 0.3, delta=0.03)
        edges = np.diff(mode.astype(int))
        runs = np.diff(np.nonzero(edges)[0])[(mode[np.nonzero(edges)[0][:-1] + 1])]
        self.assertAlmostEqual(np.mean(runs) * 2e-3, 0.1, delta=0.01)
        # in the data: the stamps are late by it
        res = refgen.generate(quiet(latency_p2=0.2, latency_delta_us=30.0))
        d = (res["frame_stamp"] - res["frame_t_true"]) * 1e6
        self.assertTrue(set(np.round(d, 6)) <= {0.0, 30.0})

    def test_rate_random_walk(self):
        K = 2.0     # deg/h/sqrt(h): var(b(T) - b(0)) = K^2 T (T in h), in deg/h
        ends = []
        for seed in range(200):
            g, b = refgen.bias_noise(refgen.resolve(quiet(rrw_deg_h_sqrt_h=K, seed=seed)), 0.0, 360.0)
            ends.append((b[-1] - b[0]) * 3600.0)
        self.assertAlmostEqual(g[1] - g[0], 0.1, places=12)
        self.assertAlmostEqual(np.var(np.array(ends)) / (K * K * 0.1), 1.0, delta=0.2)

    def test_flicker_is_one_over_f(self):
        B = 1.0
        p = refgen.resolve(quiet(flicker_deg_h=B, flicker_tau_range_s=[1.0, 10000.0]))
        taus, sigma = refgen.flicker_taus(p)
        np.testing.assert_allclose(taus, [1, 10, 100, 1000, 10000])
        # closed form: the sum's one-sided PSD is B^2 / (2 pi f) within 10 %
        # inside the range's middle decades
        for f in np.logspace(math.log10(1 / (2 * math.pi * 1000)), math.log10(1 / (2 * math.pi * 10)), 9):
            S = np.sum(4 * sigma ** 2 * taus / (1 + (2 * math.pi * f * taus) ** 2))
            self.assertAlmostEqual(S / (B * B / (2 * math.pi * f)), 1.0, delta=0.1)
        # each process is the stationary Gauss-Markov one: sigma and exp(-h / tau)
        g, x = refgen.flicker_components(p, 0.0, 4000.0)
        h = g[1] - g[0]
        self.assertAlmostEqual(h, 0.02, places=12)
        c0 = x[:, :, 0] * 3600
        self.assertAlmostEqual(np.std(c0) / sigma, 1.0, delta=0.03)
        k = 50    # one correlation time of the 1-s process
        r = np.mean([np.corrcoef(c0[:-k, a], c0[k:, a])[0, 1] for a in range(3)])
        self.assertAlmostEqual(r, math.exp(-1.0), delta=0.03)

    def test_lost_table_rows(self):
        base = refgen.generate(quiet(segments=[{"axis": "x", "freq_hz": 1.0, "amp_deg": 3.0, "duration_s": 30.0}]))
        res = refgen.generate(quiet(table_drop_per_mille=5.0,
                                    segments=[{"axis": "x", "freq_hz": 1.0, "amp_deg": 3.0, "duration_s": 30.0}]))
        lost = base["table_t"].size - res["table_t"].size
        self.assertEqual(lost, res["table_rows_lost"])
        self.assertAlmostEqual(lost / base["table_t"].size * 1e3, 5.0, delta=1.5)
        kept = np.isin(base["table_t"], res["table_t"])
        np.testing.assert_array_equal(base["table_deg"][kept], res["table_deg"])
        np.testing.assert_array_equal(base["gyro_val"], res["gyro_val"])
        self.assertEqual(res["table_t"][0], base["table_t"][0])


class StandardDefinitions(unittest.TestCase):
    """The library's effects as the standards define them (docs/diagnosis.md,
    "Parameters and their definitions"), each against a closed form that a
    factor 2 or a sign in the definition fails."""

    def test_asymmetry_is_ieee_528(self):
        # (K+ - K-) / Kbar from the gyro's increments over the frames of
        # positive and of negative rate (frames where the rate turns are left
        # out); latitude 90: no Earth rate about the horizontal x axis.
        a_ppm, s_ppm = 800.0, 300.0
        p = quiet(sf_asymmetry_ieee_ppm=a_ppm, scale_factor_ppm=s_ppm, latitude_deg=90.0, pulse_arcsec=1e-7,
                  segments=[{"axis": "x", "freq_hz": 1.0, "amp_deg": 3.0, "duration_s": 6.0}])
        res = refgen.generate(p)
        sw = res["swings"][0]
        tt = res["frame_t_true"] - p["imu_delay_ms"] * 1e-3
        true_ang, true_rate = sw.eval(tt)
        d_true, d_gyro = np.diff(true_ang), np.diff(res["frame_theta"][:, 0])
        same = np.sign(true_rate[1:]) == np.sign(true_rate[:-1])
        pos, neg = same & (true_rate[1:] > 0), same & (true_rate[1:] < 0)
        k_plus = d_gyro[pos].sum() / d_true[pos].sum()
        k_minus = d_gyro[neg].sum() / d_true[neg].sum()
        k_bar = 0.5 * (k_plus + k_minus)
        self.assertAlmostEqual((k_plus - k_minus) / k_bar * 1e6, a_ppm, delta=0.5)
        self.assertAlmostEqual((k_bar - 1.0) * 1e6, s_ppm, delta=0.5)

    def test_table_harmonics_are_ratios_to_the_fundamental_with_phase_from_its_peak(self):
        h2, h3 = 400.0, -250.0        # ppm of the fundamental at 10 deg
        for amp, start, phases in ((10.0, 0.0, (0.0, 0.0)), (10.0, 37.0, (30.0, -60.0)), (3.0, 110.0, (0.0, 0.0))):
            p = quiet(table_harmonics_ppm=[h2, h3], table_harmonic_phases_deg=list(phases), timing="commensurate",
                      segments=[{"axis": "x", "freq_hz": 0.5, "amp_deg": amp, "duration_s": 8.0,
                                 "start_phase_deg": start}])
            res = refgen.generate(p)
            a, b = res["windows"][0]
            sel = (res["table_t"] >= a) & (res["table_t"] < a + 8.0)   # whole periods
            y = res["table_true"][sel, 0]
            spec = np.fft.rfft(y) / y.size * 2.0
            k1 = int(round(0.5 * 8.0))                # bin of the fundamental
            z1 = spec[k1]
            peak = -np.angle(z1)                      # fundamental |z1| cos(w t - peak): chi = w t - peak
            for n, h, ph in ((2, h2, phases[0]), (3, h3, phases[1])):
                zn = spec[n * k1] * np.exp(1j * n * peak)   # referred to chi
                want = h * 1e-6 * (amp / 10.0) ** (n - 1) * np.exp(1j * math.radians(ph))
                self.assertAlmostEqual(abs(zn / abs(z1) - want) * 1e6, 0.0, delta=0.02, msg=(amp, start, n))
            # the rate is the angle's derivative
            t = np.linspace(a + 1.0, a + 1.01, 201)
            ang, rate = refgen.table_state(t, res["swings"], res["params"])
            np.testing.assert_allclose(np.gradient(ang[:, 0], t)[1:-1], rate[1:-1, 0], rtol=0, atol=1e-6)

    def test_nonlinearity_is_ieee_528_over_100_deg_s(self):
        # The generator's static rate transfer over +-100 deg/s: the largest
        # deviation from its least-squares line, as a fraction of full scale.
        n_ppm = 500.0
        w = -100.0 + 200.0 * (np.arange(200000) + 0.5) / 200000      # midpoints: the continuous least squares
        out = refgen.scale_factor_transfer(w, {"scale_factor_ppm": 0.0, "sf_asymmetry_ieee_ppm": 0.0,
                                                "sf_nonlinearity_ieee_ppm": n_ppm})
        slope, icpt = np.polyfit(w, out, 1)
        dev = out - (slope * w + icpt)
        self.assertAlmostEqual(np.max(np.abs(dev)) / 100.0 * 1e6, n_ppm, delta=0.02)
        self.assertAlmostEqual((slope - 1.0) * 1e6, 1.5 * n_ppm, delta=0.01)
        # the library's cubic form: w + 2.5 N w^3 / 100^2
        np.testing.assert_allclose(out, w + 2.5 * n_ppm * 1e-6 * w ** 3 / 1e4, atol=1e-12)

    def test_version_one_parameters_are_refused(self):
        for key, v in (("sf_asymmetry_ppm", 100.0), ("table_poly_ppm", [1.0, 2.0]),
                       ("sf_nonlinearity_ppm_at_100", 10.0)):
            with self.assertRaises(ValueError):
                refgen.resolve(quiet(**{key: v}))


class Output(unittest.TestCase):
    def read_csv(self, path):
        with open(path) as fh:
            rows = [r for r in csv.reader(fh) if r and not r[0].startswith("#")]
        return rows[0], rows[1:]

    def test_import_directory(self):
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "o")
            p = refgen.case_params("nominal")
            p["segments"][0]["duration_s"] = 4.0
            tr = refgen.write_dir(refgen.generate(p), out)
            self.assertEqual(sorted(os.listdir(out)), ["gyro.csv", "metadata.json", "table.csv", "truth.json"])
            meta = load_json(os.path.join(out, "metadata.json"))
            self.assertEqual(set(meta["bench"]), {"table_read_delay_ms", "board_delay_ms", "pulse_equivalent_deg",
                                                  "latitude_deg"})
            self.assertEqual(meta["test_points"], [{"axis": "x", "frequency_hz": 1.0, "amplitude_deg": 3.0,
                                                    "duration_s": 4.0}])
            h, rows = self.read_csv(os.path.join(out, "table.csv"))
            self.assertEqual(h, ["time_s", "x_deg", "y_deg", "z_deg"])
            t = np.array([float(r[0]) for r in rows])
            self.assertTrue(np.all(np.diff(t) > 0))
            q = 0.36 / 3600
            x = np.array([float(r[1]) for r in rows]) / q
            self.assertLess(np.max(np.abs(x - np.round(x))), 1e-6)
            self.assertAlmostEqual(tr["true_lag_ms"], 0.45, places=12)
            self.assertAlmostEqual(tr["gyro_delay_ms"], 0.22, places=12)
            self.assertEqual(tr["rows"]["table"], len(rows))
            # refuses a non-empty directory
            with self.assertRaises(ValueError):
                refgen.write_dir(refgen.generate(p), out)
            refgen.write_dir(refgen.generate(p), out, overwrite=True)

    def test_rates_metadata_keys(self):
        with tempfile.TemporaryDirectory() as d:
            for conv in ("frame_average", "sample_at_stamp"):
                out = os.path.join(d, conv)
                p = refgen.case_params("rates_" + conv)
                p["segments"][0]["duration_s"] = 3.0
                refgen.write_dir(refgen.generate(p), out)
                meta = load_json(os.path.join(out, "metadata.json"))
                self.assertEqual(meta["bench"]["gyro_rate_convention"], conv)
                self.assertEqual(meta["bench"]["gyro_frame_period_ms"], 2.0)
                h, rows = self.read_csv(os.path.join(out, "gyro.csv"))
                self.assertEqual(h, ["time_s", "x_rate_deg_s", "y_rate_deg_s", "z_rate_deg_s"])

    def test_declared_frame_in_metadata(self):
        with tempfile.TemporaryDirectory() as d:
            p = refgen.case_params("nominal")
            p["segments"][0]["duration_s"] = 3.0
            refgen.write_dir(refgen.generate(p), os.path.join(d, "plain"))
            self.assertNotIn("imu_frame", load_json(os.path.join(d, "plain", "metadata.json"))["bench"])
            p.update(z_up=True, heading_deg=90.0, declare_frame="ENU")
            refgen.write_dir(refgen.generate(p), os.path.join(d, "enu"))
            self.assertEqual(load_json(os.path.join(d, "enu", "metadata.json"))["bench"]["imu_frame"], "ENU")

    def test_continuous_has_no_markers(self):
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "c")
            p = refgen.case_params("continuous")
            for s in p["segments"]:
                s["duration_s"] = 6.0
            res = refgen.generate(p)
            tr = refgen.write_dir(res, out)
            meta = load_json(os.path.join(out, "metadata.json"))
            self.assertEqual(meta["test_points"], [{"axis": "x"}])
            h, rows = self.read_csv(os.path.join(out, "table.csv"))
            self.assertNotIn("test_point", h)
            self.assertEqual(len(tr["test_points"]), 3)
            t = np.array([float(r[0]) for r in rows])
            x = np.array([float(r[1]) for r in rows])
            # at rest between the test points, swinging inside them
            (a1, b1), (a2, b2) = tr["test_points"][0]["window_s"], tr["test_points"][1]["window_s"]
            rest = (t > b1 + 2.5) & (t < a2 - 2.5)
            self.assertTrue(np.all(x[rest] == 0.0))
            self.assertAlmostEqual(np.max(np.abs(x[(t > a1) & (t < b1)])), 3.0, delta=0.01)
            self.assertAlmostEqual(b1 + 2 + 5 + 2, a2, places=9)

    def test_several_test_points_are_marked(self):
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "m")
            p = refgen.default_params()
            p["segments"] = [{"axis": "x", "freq_hz": 1.0, "amp_deg": 3.0, "duration_s": 3.0},
                             {"axis": "y", "freq_hz": 0.5, "amp_deg": 5.0, "duration_s": 4.0}]
            refgen.write_dir(refgen.generate(p), out)
            h, rows = self.read_csv(os.path.join(out, "gyro.csv"))
            self.assertEqual(h[0], "test_point")
            self.assertEqual({r[0] for r in rows}, {"1", "2"})

    def test_cli(self):
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "cli")
            rc = refgen.main(["--out", out, "--freq-hz", "2", "--amp-deg", "1", "--duration-s", "3",
                              "--imu-delay-ms", "0.7", "--bias-deg-h", "1,2,3", "--gyro-sign", "1,-1,1",
                              "--seed", "5", "--axes-out", "swing"])
            self.assertEqual(rc, 0)
            tr = load_json(os.path.join(out, "truth.json"))
            self.assertEqual(tr["params"]["bias_deg_h"], [1.0, 2.0, 3.0])
            self.assertEqual(tr["params"]["gyro_sign"], [1, -1, 1])
            self.assertAlmostEqual(tr["true_lag_ms"], 0.65, places=12)
            h, _ = self.read_csv(os.path.join(out, "table.csv"))
            self.assertEqual(h, ["time_s", "x_deg"])
            self.assertEqual(refgen.main(["--out", out, "--case", "nominal"]), 2)   # not empty

    def test_every_case_generates(self):
        for name in refgen.CASES:
            p = refgen.case_params(name)
            for s in p["segments"]:
                s["duration_s"] = min(s["duration_s"], 4.0)
            if p["rekick_period_s"]:
                p["rekick_period_s"] = 2.0
                p["rekick_duration_s"] = 0.5
            res = refgen.generate(p)
            self.assertGreater(res["table_t"].size, 1000, name)


if __name__ == "__main__":
    unittest.main()
