#!/usr/bin/python3
"""refgen: an independent reference data generator for fogbench.

Writes an import directory (docs/formats.md: metadata.json, table.csv,
gyro.csv) of a turntable swing test of a fiber-optic-gyro IMU, plus a
truth.json with every generator parameter and the true delays.

It is written from first principles and shares NO code with fogbench's C++
simulator (core/model); see tests/independent/README.md for the model.

Only the Python standard library and numpy are used.

Frames and conventions
----------------------
* Local frame: North-East-Down (NED).  Earth rate in it:
  Omega * (cos(lat), 0, -sin(lat)), Omega = 15.041067 deg/h.
* Table: three axes with angles (a_x, a_y, a_z) in degrees.  The rotation
  from the body (IMU) frame to the local frame is
      C(t) = L * R_axis1(a_1) * R_axis2(a_2) * R_axis3(a_3)
  with L = R_z(heading) for a table whose z axis points down at zero
  (z_up False) and L = R_z(heading) R_x(180 deg) for one whose z points up
  with the axes in `axis_order` (outer to inner, default "zyx":
  C = R_z(heading) R_z(a_z) R_y(a_y) R_x(a_x)).  R_k(a) is the proper
  right-handed rotation by +a about unit axis k.  With all angles and the
  heading at 0 the body axes are x North, y East, z Down (z up: x North,
  y West, z Up; heading 90 and z up: x East, y North, z Up).
* Body angular rate: omega_b = sum over table axes of the axis' rate
  expressed in the body frame, plus C(t)^T omega_ie^n (the Earth rate
  rotated into the body frame at every fine step).
* The gyro on body axis i measures
      sign_i * omega_b,i(t - tau_imu) + bias_i(t) + white rate noise,
  integrated numerically (trapezoid) on a fine grid that runs on the IMU's
  own crystal.  tau_imu (imu_delay_ms) covers everything from the rotation
  to the frame's arrival at the sampling board.
* Pulses: P(t) = floor(Theta(t) / pe); a frame reports P(t_k) - P(t_{k-1}).
* Times written to the CSV files are seconds on the sampling board's clock
  (= true time for the table stream; the gyro stream's stamps may run at
  1 + clock_rate_ppm_gyro * 1e-6 against it, an error case).
* Lag (what fogbench measures) = imu_delay_ms - table_read_delay_ms: the
  time by which the gyro output lags the stamped table reading.
* Effects in their own physical form (all off by default; README "Outside
  effects"): base tilt, table-axis non-orthogonality, encoder eccentricity,
  encoder-to-fixture compliance, a servo's unbalance, the IMU mount's
  rotation, g-sensitivity per gyro, the pulse register's update, a boxcar
  of the rate, a bimodal / Markov latency, rate random walk, flicker, lost
  table rows. truth.json's physical_effects states what each amounts to in
  closed form (extra delay, equivalent lag, equivalent library values).
"""

from __future__ import annotations

import argparse
import copy
import json
import math
import os
import sys
import time

import numpy as np

GENERATOR_VERSION = 2
EARTH_RATE_DEG_H = 15.041067
AXES = "xyz"
ARCSEC = 1.0 / 3600.0  # degrees per arc second


# --------------------------------------------------------------------------
# Parameters
# --------------------------------------------------------------------------

def default_segment():
    """One test point (one swing of one axis)."""
    return {
        "axis": "x",
        "freq_hz": 1.0,
        "amp_deg": 3.0,
        "duration_s": 30.0,
        # Swing phase at the start of the analysed window; None: 0 for
        # commensurate timing, random for incommensurate.
        "start_phase_deg": None,
        "centre_deg": 0.0,
    }


def default_params():
    """Every generator parameter with its default.  Units in the names."""
    return {
        "seed": 1,
        "case": None,
        # Test points.  One segment = one eternal sinusoid, the window
        # [lead_s, lead_s + duration_s] is recorded.  Several segments (or
        # continuous=True) = one timeline: rest, ramp up, steady swing
        # (the test point), ramp down, rest, ...
        "segments": [default_segment()],
        "lead_s": 1.0,          # time before the first test point (timeline starts at 0)
        "tail_s": 0.0,          # time after the last test point (single segment)
        "rest_s": 5.0,          # rest between test points (several segments)
        "ramp_s": 2.0,          # smooth amplitude ramp in and out (several segments)
        "settle_s": 0.0,        # several segments: steady swing after the ramp before the window
        "continuous": False,    # one record of the whole timeline, no test_point markers
        # Swing imperfections (apply to every segment)
        "table_freq_error_ppm": 0.0,
        "decay_tau_s": math.inf,
        "amp_drift_per_s": 0.0,       # A(t) *= 1 + amp_drift_per_s * (t - t_on)
        "h2": 0.0,                    # 2nd harmonic, fraction of A
        "h2_phase_deg": 0.0,
        "rekick_period_s": 0.0,       # >0: re-excited every this many s (repeated decays)
        "rekick_duration_s": 1.5,     # smooth re-excitation ramp at the end of each cycle
        # Other table axes
        "fixed_angles_deg": [0.0, 0.0, 0.0],   # x, y, z angles of the axes that do not swing
        "axis_order": "zyx",                   # outer to inner
        # Site
        "latitude_deg": 40.0,
        "heading_deg": 0.0,           # azimuth of the table's x axis at zero, from north toward east
        # The table's (and the square-mounted IMU's) z axis at zero angles:
        # False = down (x north, y east, z down at heading 0), True = up
        # (x at the heading, y 90 deg to its left, z up: east-north-up at
        # heading 90). The level frame is turned by L = R_z(heading) R_x(180).
        "z_up": False,
        # Written as bench.imu_frame when set (e.g. "ENU", "RFU:30"): what the
        # metadata states, which may differ from the truth (a wrong statement).
        "declare_frame": None,
        # Delays (ms)
        "imu_delay_ms": 0.5,
        "table_read_delay_ms": 0.05,
        "board_delay_ms": 0.28,
        # Gyro
        "fine_hz": 10000.0,
        "gyro_sign": [1, 1, 1],
        # Sensor errors of the reference simulator (docs/simulator.md): gyro i
        # senses misalignment_urad m_ij of the body rate about axis j, in the
        # order m_xy, m_xz, m_yx, m_yz, m_zx, m_zy; a rate error of
        # g_sens_deg_h_g times the specific force along its own axis; and its
        # output is the rate through a first-order lag of lag_tau_ms.
        "misalignment_urad": [0.0] * 6,
        "g_sens_deg_h_g": 0.0,     # one k for every gyro, or three (x, y, z): each gyro its own
        "lag_tau_ms": 0.0,
        # ... and a scale factor: Kbar = 1 + scale_factor_ppm, and the
        # scale-factor asymmetry a = (K+ - K-) / Kbar of IEEE Std 528 as
        # sf_asymmetry_ieee_ppm: the rate is multiplied by K+ = Kbar (1 + a/2)
        # where it is positive and by K- = Kbar (1 - a/2) where it is
        # negative; after the scale-factor nonlinearity N of IEEE Std 528 over
        # +-100 deg/s (sf_nonlinearity_ieee_ppm: the largest deviation from
        # the least-squares line over the range, fraction of full scale), the
        # rate written as its least-squares line (1 + 1.5 N) w plus the
        # deviation N 100 P3(w / 100), P3 the Legendre polynomial
        # (5 x^3 - 3 x) / 2 (orthogonal to every line on [-1, 1], |P3| <= 1
        # there, 1 at the ends); a bias growing by bias_drift_deg_h_per_min from the first
        # instant; IMU frames lost at random at drop_per_mille (the next row's
        # lost_before counts them).
        "scale_factor_ppm": 0.0,
        "sf_asymmetry_ieee_ppm": 0.0,
        "sf_nonlinearity_ieee_ppm": 0.0,
        "bias_drift_deg_h_per_min": 0.0,
        "drop_per_mille": 0.0,
        # Table errors: harmonics added to every swing's commanded motion
        # (seen by encoder and gyros alike), table_harmonics_ppm = [h2, h3]
        # of the fundamental at 10 deg amplitude with phases
        # table_harmonic_phases_deg = [p2, p3] from the fundamental's positive
        # peak: a swing e cos(chi) (chi = 0 at its positive peak, e its
        # envelope) gains h_n (e / 10 deg)^(n-1) e cos(n chi + p_n), the
        # amplitude law of a static distortion of the angle; and an encoder
        # reading error s sin(2 pi theta / 10 deg) + c cos(...)
        # (encoder_cyclic_arcsec = [s, c]).
        "table_harmonics_ppm": [0.0, 0.0],
        "table_harmonic_phases_deg": [0.0, 0.0],
        "encoder_cyclic_arcsec": [0.0, 0.0],
        # ---- Effects in their own physical form (README "Outside effects");
        # every one is off by default and then leaves every output as before.
        # Table base tilted by base_tilt_deg about the horizontal axis at
        # azimuth base_tilt_azimuth_deg (from north toward east): the level
        # frame becomes R_tilt L, for the Earth rate and gravity alike.
        "base_tilt_deg": 0.0,
        "base_tilt_azimuth_deg": 0.0,
        # Non-orthogonality of the table's axes (arcsec): the inner axis'
        # bearing tilted toward the middle axis by nonorth_inner_arcsec
        # (C = .. R_y(a_y) R_z(eps_i) R_x(a_x)), the middle axis' toward the
        # outer one by nonorth_middle_arcsec (R_z(a_z) R_x(eps_m) R_y(a_y));
        # only for axis_order zyx.
        "nonorth_inner_arcsec": 0.0,
        "nonorth_middle_arcsec": 0.0,
        # Encoder disk eccentricity: e (um) at the read head's radius r (mm)
        # gives a once-per-revolution reading error (e/r) sin(theta + phi) rad
        # on the axes in eccentricity_axes.
        "eccentricity_um": 0.0,
        "eccentricity_radius_mm": 100.0,
        "eccentricity_phase_deg": 0.0,
        "eccentricity_axes": "xyz",
        # Compliance between the encoder and the IMU fixture: the fixture's
        # angle follows the encoder's through a spring-damper,
        # (2 zeta wn s + wn^2) / (s^2 + 2 zeta wn s + wn^2); 0 Hz = rigid.
        "compliance_fn_hz": 0.0,
        "compliance_zeta": 0.05,
        # Table servo: an unbalance torque m g l sin(theta + phi) on the
        # horizontal axes (x, y) deflects the motion by
        # servo_unbalance_arcsec * sin(theta + phi) through the loop's
        # first-order disturbance response of corner servo_corner_hz
        # (0 Hz: static). Seen by encoder and gyros alike.
        "servo_unbalance_arcsec": 0.0,
        "servo_unbalance_phase_deg": 0.0,
        "servo_corner_hz": 0.0,
        # IMU mount rotated by roll, pitch, yaw (arcsec, about the body x, y,
        # z) against the table's inner frame: the gyros sense R_m^T omega_b
        # (and R_m^T f for the g-sensitivity).
        "mount_rpy_arcsec": [0.0, 0.0, 0.0],
        # The gyro's pulse register is updated every register_period_ms (0 =
        # continuously) on the IMU crystal, at register_offset_ms after each
        # frame end modulo the period, its own clock register_clock_ppm
        # faster than the frame clock; a frame reports the held value.
        "register_period_ms": 0.0,
        "register_offset_ms": 0.0,
        "register_clock_ppm": 0.0,
        # Moving average (boxcar) of the rate over boxcar_ms before the frame.
        "boxcar_ms": 0.0,
        # A resonant (second-order) rate filter after the first-order lag:
        # y'' + 2 zeta wn y' + wn^2 y = wn^2 x, wn = 2 pi second_order_fn_hz
        # (0 Hz = off), 0 < second_order_zeta < 1; exact for the rate linear
        # between fine points, at rest (steady) before the first instant.
        "second_order_fn_hz": 0.0,
        "second_order_zeta": 0.7,
        # Latency between a frame's end and its stamp, beyond the delays: 0
        # with probability 1 - latency_p2, latency_delta_us with latency_p2,
        # each mode with latency_sigma_us rms; latency_dwell_s > 0 makes the
        # mode a two-state Markov chain with that mean dwell in mode 2 (and
        # dwell (1 - p2) / p2 times it in mode 1): a non-white latency.
        "latency_p2": 0.0,
        "latency_delta_us": 0.0,
        "latency_sigma_us": 0.0,
        "latency_dwell_s": 0.0,
        # Rate random walk (deg/h/sqrt(h)) and flicker bias (deg/h, the
        # bias-instability coefficient B of S(f) = B^2 / (2 pi f)) made of one
        # Gauss-Markov process per decade of correlation time in
        # flicker_tau_range_s, per gyro.
        "rrw_deg_h_sqrt_h": 0.0,
        "flicker_deg_h": 0.0,
        "flicker_tau_range_s": [1.0, 10000.0],
        # Table rows lost at random (per mille): missing from table.csv.
        "table_drop_per_mille": 0.0,
        "bias_deg_h": [1.0, 1.0, 1.0],
        "bias_step_deg_h": [0.0, 0.0, 0.0],
        "bias_step_time_s": math.inf,
        # Bias instability: a first-order Gauss-Markov rate per gyro, 1 sigma
        # and correlation time, stationary from before the first instant
        # (exact AR(1) steps of at most 0.1 s, linear between them).
        "bias_instability_deg_h": 0.0,
        "bias_correlation_s": 300.0,
        "arw_deg_sqrt_h": 0.005,
        "pulse_arcsec": 0.18,
        "imu_period_ms": 2.0,
        "imu_clock_ppm": 0.0,          # >0: the IMU crystal runs fast (shorter frames)
        "gyro_stamp_jitter_us": 0.0,   # white, rms
        "clock_rate_ppm_gyro": 0.0,    # gyro stamps on a clock this much faster than the table's
        "rate_output": None,           # None (increments) | "frame_average" | "sample_at_stamp"
        "rate_lsb_deg_s": 0.0,         # sample_at_stamp: output resolution (0 = none)
        "sample_hold_ms": 0.0,         # >0: the board samples the latest gyro row at this period
        # Table
        "table_period_ms": 1.0,
        "encoder_arcsec": 0.36,
        "encoder_noise_arcsec": 0.0,   # white, rms, before quantisation
        # Time stamps
        "timing": "incommensurate",    # "commensurate" | "incommensurate"
        "nonround_ppm": 30.0,          # incommensurate: periods off round by up to this
        "stamp_quantum_us": 0.0,       # board counter resolution (0 = exact)
        # Output
        "axes_out": "all",             # "all" | "swing"
        "meta_minimal": False,         # metadata test points with only the axis
        "declare_gyro_sign": False,    # write bench.gyro_sign {"x": -1, ...} for the reversed axes
        "float_format": "repr",       # "repr" (shortest round-trip text) or a printf format
    }


# --------------------------------------------------------------------------
# Named cases
# --------------------------------------------------------------------------

def _seg(axis="x", f=1.0, a=3.0, d=60.0, phase=None):
    return {"axis": axis, "freq_hz": f, "amp_deg": a, "duration_s": d,
            "start_phase_deg": phase, "centre_deg": 0.0}


CASES = {
    "nominal": {
        "description": "1 Hz / 3 deg, 60 s, IMU delay 0.5 ms; no defect",
        "expected_verdict": "pass",
        "params": {"segments": [_seg(f=1.0, a=3.0, d=60.0)]},
    },
    "reversed_axis": {
        "description": "the gyro's swing axis is mounted reversed: its increments are negated (magnitude ratio -1)",
        "expected_verdict": "invalid",
        "params": {"segments": [_seg(f=0.5, a=3.0, d=60.0)], "gyro_sign": [-1, 1, 1]},
    },
    "reversed_axis_declared": {
        "description": "reversed_axis, but the metadata states it (bench.gyro_sign {\"x\": -1}): "
                       "the importer negates the axis and the delay is valid",
        "expected_verdict": "pass",
        "params": {"segments": [_seg(f=0.5, a=3.0, d=60.0)], "gyro_sign": [-1, 1, 1], "declare_gyro_sign": True},
    },
    "clock_rate": {
        "description": "gyro stamps from a clock 50 ppm fast against the table's: not one clock",
        "expected_verdict": "invalid",
        "params": {"segments": [_seg(f=0.1, a=10.0, d=300.0)], "clock_rate_ppm_gyro": 50.0},
    },
    "quantisation_dominated": {
        "description": "2 arcsec pulses, ARW 0.002 deg/sqrt(h): pulse quantisation dominates the gyro noise at 0.1 Hz / 10 deg",
        "expected_verdict": "pass",
        "params": {"segments": [_seg(f=0.1, a=10.0, d=120.0)], "pulse_arcsec": 2.0, "arw_deg_sqrt_h": 0.002},
    },
    "commensurate": {
        "description": "1 Hz at exactly 1 kHz table / 500 Hz gyro, stamps aligned with the swing, 3.6 arcsec encoder",
        "expected_verdict": "pass",
        "params": {"segments": [_seg(f=1.0, a=3.0, d=60.0, phase=0.0)], "timing": "commensurate",
                   "encoder_arcsec": 3.6},
    },
    "gyro_jitter": {
        "description": "20 us rms white jitter on the gyro stamps",
        "expected_verdict": None,
        "params": {"segments": [_seg(f=1.0, a=3.0, d=60.0)], "gyro_stamp_jitter_us": 20.0},
    },
    "pendulum": {
        "description": "free pendulum: 0.67 Hz, amplitude decaying from 10 deg with tau 30 s, 60 s",
        "expected_verdict": None,
        "params": {"segments": [_seg(f=0.67, a=10.0, d=60.0)], "decay_tau_s": 30.0},
    },
    "amplitude_drift": {
        "description": "amplitude drifting down by 30 % over the 60-s record (1 Hz / 3 deg)",
        "expected_verdict": None,
        "params": {"segments": [_seg(f=1.0, a=3.0, d=60.0)], "amp_drift_per_s": -0.30 / 60.0},
    },
    "repeated_decays": {
        "description": "repeated decays: 0.67 Hz / 10 deg re-excited every 15 s, decaying with tau 5 s, 60 s",
        "expected_verdict": None,
        "params": {"segments": [_seg(f=0.67, a=10.0, d=60.0)], "decay_tau_s": 5.0,
                   "rekick_period_s": 15.0, "rekick_duration_s": 1.5},
    },
    "acausal": {
        "description": "IMU delay -25 ms (a stamping error: the gyro appears to lead the table)",
        "expected_verdict": "invalid",
        "params": {"segments": [_seg(f=0.1, a=10.0, d=120.0)], "imu_delay_ms": -25.0},
    },
    "rates_frame_average": {
        "description": "gyro.csv holds x_rate_deg_s = increment / IMU frame period (2 ms), stamped at the frame's end; "
                       "the board samples the latest rate every 1 ms (sample-and-hold: every row twice)",
        "expected_verdict": "pass",
        "params": {"segments": [_seg(f=1.0, a=3.0, d=60.0)], "rate_output": "frame_average",
                   "sample_hold_ms": 1.0},
    },
    "rates_sample_at_stamp": {
        "description": "gyro.csv holds x_rate_deg_s = the instantaneous measured rate at the frame's end (stamp)",
        "expected_verdict": "pass",
        "params": {"segments": [_seg(f=1.0, a=3.0, d=60.0)], "rate_output": "sample_at_stamp"},
    },
    "continuous": {
        "description": "three test points on X (1 Hz/3 deg 30 s, 0.5 Hz/5 deg 30 s, 0.2 Hz/10 deg 50 s) in one record, "
                       "5-s rests, 2-s ramps, no test_point column; metadata lists one test point {axis: x}",
        "expected_verdict": "pass",
        "params": {"segments": [_seg(f=1.0, a=3.0, d=30.0), _seg(f=0.5, a=5.0, d=30.0),
                                _seg(f=0.2, a=10.0, d=50.0)],
                   "continuous": True, "rest_s": 5.0, "ramp_s": 2.0},
    },
}


def case_params(name):
    if name not in CASES:
        raise ValueError("unknown case %r; known: %s" % (name, ", ".join(CASES)))
    p = default_params()
    p.update(copy.deepcopy(CASES[name]["params"]))
    p["case"] = name
    return p


# --------------------------------------------------------------------------
# Rotations
# --------------------------------------------------------------------------

def rot(axis, angle_deg):
    """Proper rotations by +angle about a body axis: array (..., 3, 3)."""
    a = np.deg2rad(np.asarray(angle_deg, dtype=float))
    c, s = np.cos(a), np.sin(a)
    o, z = np.ones_like(a), np.zeros_like(a)
    if axis == "x":
        m = [[o, z, z], [z, c, -s], [z, s, c]]
    elif axis == "y":
        m = [[c, z, s], [z, o, z], [-s, z, c]]
    elif axis == "z":
        m = [[c, -s, z], [s, c, z], [z, z, o]]
    else:
        raise ValueError(axis)
    return np.moveaxis(np.array(m), (0, 1), (-2, -1))


def rot_about(u, angle_deg):
    """Proper rotation by +angle about the unit vector u (Rodrigues), (3, 3)."""
    u = np.asarray(u, dtype=float) / np.linalg.norm(u)
    a = math.radians(angle_deg)
    k = np.array([[0.0, -u[2], u[1]], [u[2], 0.0, -u[0]], [-u[1], u[0], 0.0]])
    return np.eye(3) + math.sin(a) * k + (1.0 - math.cos(a)) * (k @ k)


def level_to_table(p):
    """L: the table's axes at zero angles in the local NED frame, (3, 3);
    with a base tilt, R_tilt L (the tilt about the horizontal axis at its
    azimuth, from north toward east)."""
    r = rot("z", p["heading_deg"])
    r = r @ rot("x", 180.0) if p["z_up"] else r
    if p.get("base_tilt_deg", 0.0):
        az = math.radians(p["base_tilt_azimuth_deg"])
        r = rot_about([math.cos(az), math.sin(az), 0.0], p["base_tilt_deg"]) @ r
    return r


def axis_chain(p):
    """The table's rotations outer to inner: ("axis", "z") for a table axis,
    ("fixed", R) for a constant rotation between two axes (non-orthogonality:
    R_x(eps_middle) between z and y, R_z(eps_inner) between y and x)."""
    steps = [("axis", ax) for ax in p["axis_order"]]
    em, ei = p.get("nonorth_middle_arcsec", 0.0), p.get("nonorth_inner_arcsec", 0.0)
    if em or ei:
        if p["axis_order"] != "zyx":
            raise ValueError("axis non-orthogonality is modelled for axis_order zyx")
        steps = [("axis", "z")] + ([("fixed", rot("x", em * ARCSEC))] if em else []) + [("axis", "y")] + \
                ([("fixed", rot("z", ei * ARCSEC))] if ei else []) + [("axis", "x")]
    return steps


def earth_rate_ned_deg_s(lat_deg):
    om = EARTH_RATE_DEG_H / 3600.0
    lat = math.radians(lat_deg)
    return np.array([om * math.cos(lat), 0.0, -om * math.sin(lat)])


def specific_force(angles, p):
    """Specific force of gravity at rest in the body frame, in g, (n, 3):
    C(t)^T (0, 0, -1) in NED, through the same axis chain as body_rates."""
    n = angles.shape[0]
    u = np.tile(_rot_t(level_to_table(p), np.array([0.0, 0.0, -1.0])), (n, 1))
    for kind, ax in axis_chain(p):
        u = _rot_t(ax if kind == "fixed" else rot(ax, angles[:, AXES.index(ax)]), u)
    return u


def linear_mode(pole, u, h, y0):
    """y' = pole y + u(t) on samples u (n, ...) every h, u linear between
    samples (exact for that), y = y0 at the first sample; pole may be
    complex. Returns y at every sample. Summed in blocks short enough for
    |a|^-L to stay finite, a = exp(pole h)."""
    a = complex(np.exp(pole * h)) if isinstance(pole, complex) else math.exp(pole * h)
    i0 = (a - 1.0) / pole
    i1 = (a - 1.0) / pole ** 2 - h / pole
    inc = u[:-1] * i0 + (u[1:] - u[:-1]) * (i1 / h)
    dtype = np.complex128 if isinstance(pole, complex) else float
    y = np.empty(u.shape, dtype=dtype)
    y[0] = y0
    decay = max(-float(np.real(pole)) * h, 1e-12)
    L = max(1, int(30.0 / decay))
    prev = np.asarray(y[0]).copy()
    for b in range(0, inc.shape[0], L):
        ub = inc[b:b + L]
        k = np.arange(1, ub.shape[0] + 1).reshape((-1,) + (1,) * (u.ndim - 1))
        w = a ** (-k.astype(float))
        y[b + 1:b + 1 + ub.shape[0]] = a ** k * (prev + np.cumsum(ub * w, axis=0))
        prev = np.asarray(y[b + ub.shape[0]]).copy()
    return y


def hermite(t, t0, h, v, dv):
    """Cubic Hermite interpolation at times t of samples v with derivatives
    dv every h from t0 (columns: axes)."""
    x = np.clip((np.asarray(t, dtype=float) - t0) / h, 0.0, v.shape[0] - 1.0)
    j = np.clip(np.floor(x).astype(np.int64), 0, v.shape[0] - 2)
    s = (x - j)[:, None]
    h00, h10 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s
    h01, h11 = -2 * s**3 + 3 * s**2, s**3 - s**2
    val = h00 * v[j] + h10 * h * dv[j] + h01 * v[j + 1] + h11 * h * dv[j + 1]
    d00, d10 = (6 * s**2 - 6 * s) / h, 3 * s**2 - 4 * s + 1
    d01, d11 = (-6 * s**2 + 6 * s) / h, 3 * s**2 - 2 * s
    der = d00 * v[j] + d10 * dv[j] + d01 * v[j + 1] + d11 * dv[j + 1]
    return val, der


MOTION_GRID_S = 0.25e-3   # step of the servo and compliance states (cubic Hermite between)


def first_order_lag(x, dt, tau, y0, x0):
    """y' = (x - y) / tau on samples x (n, 3) every dt after a sample x0 with
    output y0, x linear between samples (exact for that): returns y (n, 3).
    The recursion y_j = a y_{j-1} + u_j is summed in blocks short enough for
    a^-L to stay finite."""
    a = math.exp(-dt / tau)
    c = tau / dt * (1.0 - a)
    xp = np.vstack([x0[None, :], x[:-1]])
    u = x - c * (x - xp) - a * xp          # y_j - a y_{j-1} for this input
    y = np.empty_like(x)
    L = max(1, int(40.0 / max(dt / tau, 1e-12)))
    prev = y0.copy()
    for b in range(0, x.shape[0], L):
        ub = u[b:b + L]
        k = np.arange(1, ub.shape[0] + 1)[:, None]
        w = a ** (-k.astype(float))
        y[b:b + L] = a ** k * (prev[None, :] + np.cumsum(ub * w, axis=0))
        prev = y[b + ub.shape[0] - 1].copy()
    return y


def _rot_t(r, u):
    """R^T u for rotation matrices r (n, 3, 3) or (3, 3) and vectors u (n, 3)
    or (3,): sum_j R[j, i] u[j]."""
    return (r * u[..., :, None]).sum(axis=-2)


def body_rates(angles, rates, p):
    """Body angular rate (deg/s), (n, 3), for table angles and angle rates
    (n, 3 each, columns x, y, z), including the Earth rate rotated into the
    body frame at every sample.

    With C = R_h R_1 R_2 R_3 (heading, then the table axes outer to inner):
        omega_b = C^T omega_n + sum_k (R_{k+1} .. R_3)^T e_k rate_k,
    evaluated as u = R_h^T omega_n; u = R_k^T u + e_k rate_k for k = 1, 2, 3
    with the proper 3x3 rotation matrices of rot()."""
    n = angles.shape[0]
    w_n = earth_rate_ned_deg_s(p["latitude_deg"])
    u = np.tile(_rot_t(level_to_table(p), w_n), (n, 1))
    for kind, ax in axis_chain(p):                   # outer .. inner
        if kind == "fixed":
            u = u @ ax
            continue
        i = AXES.index(ax)
        a = angles[:, i]
        if n and np.all(a == a[0]):
            u = u @ rot(ax, a[0])                    # an axis at rest: one matrix; (R^T u)^T = u^T R
        else:
            u = _rot_t(rot(ax, a), u)
        u[:, i] += rates[:, i]
    return u


# --------------------------------------------------------------------------
# The swing
# --------------------------------------------------------------------------

class Swing:
    """One test point's angle contribution on its axis, with its analytic
    time derivative."""

    def __init__(self, seg, p, t_on, gated):
        self.axis = seg["axis"]
        self.f_nom = float(seg["freq_hz"])
        self.f = self.f_nom * (1.0 + p["table_freq_error_ppm"] * 1e-6)
        self.amp = float(seg["amp_deg"])
        self.phi0 = math.radians(seg["start_phase_deg"])
        self.t_on = t_on
        self.dur = float(seg["duration_s"])
        self.gated = gated
        self.ramp = float(p["ramp_s"])
        self.tau = float(p["decay_tau_s"])
        self.drift = float(p["amp_drift_per_s"])
        self.h2 = float(p["h2"])
        self.h2_phase = math.radians(p["h2_phase_deg"])
        self.dist = [(n, float(h) * 1e-6, math.radians(ph)) for n, h, ph in
                     zip((2, 3), p["table_harmonics_ppm"], p["table_harmonic_phases_deg"]) if h]
        self.kick_period = float(p["rekick_period_s"])
        self.kick = float(p["rekick_duration_s"])
        if self.kick_period > 0:
            if not math.isfinite(self.tau):
                raise ValueError("rekick_period_s needs a finite decay_tau_s")
            if not 0 < self.kick < self.kick_period:
                raise ValueError("rekick_duration_s must be in (0, rekick_period_s)")
        if gated and self.ramp <= 0:
            raise ValueError("several test points need ramp_s > 0")

    def active_range(self):
        if not self.gated:
            return (-math.inf, math.inf)
        return (self.t_on - self.ramp, self.t_on + self.dur + self.ramp)

    def _decay(self, u):
        if not math.isfinite(self.tau):
            return np.ones_like(u), np.zeros_like(u)
        if self.kick_period <= 0:
            d = np.exp(-u / self.tau)
            return d, -d / self.tau
        P, k, tau = self.kick_period, self.kick, self.tau
        w = np.mod(u, P)
        d = np.exp(-w / tau)
        dd = -d / tau
        # Re-excitation: cubic Hermite from the decayed level to 1, matching
        # value and slope at both ends (the envelope is C1).
        kicking = w >= P - k
        if np.any(kicking):
            x = (w[kicking] - (P - k)) / k
            y0 = math.exp(-(P - k) / tau)
            m0 = -y0 / tau * k
            y1, m1 = 1.0, -1.0 / tau * k
            h00 = 2 * x**3 - 3 * x**2 + 1
            h10 = x**3 - 2 * x**2 + x
            h01 = -2 * x**3 + 3 * x**2
            h11 = x**3 - x**2
            d[kicking] = h00 * y0 + h10 * m0 + h01 * y1 + h11 * m1
            dd[kicking] = ((6 * x**2 - 6 * x) * y0 + (3 * x**2 - 4 * x + 1) * m0
                           + (-6 * x**2 + 6 * x) * y1 + (3 * x**2 - 2 * x) * m1) / k
        return d, dd

    def _gate(self, t):
        if not self.gated:
            return np.ones_like(t), np.zeros_like(t)
        g = np.zeros_like(t)
        dg = np.zeros_like(t)
        r = self.ramp
        a, b = self.t_on, self.t_on + self.dur
        up = (t > a - r) & (t < a)
        x = (t[up] - (a - r)) / r
        g[up] = 0.5 * (1 - np.cos(math.pi * x))
        dg[up] = 0.5 * math.pi * np.sin(math.pi * x) / r
        steady = (t >= a) & (t <= b)
        g[steady] = 1.0
        down = (t > b) & (t < b + r)
        x = (t[down] - b) / r
        g[down] = 0.5 * (1 + np.cos(math.pi * x))
        dg[down] = -0.5 * math.pi * np.sin(math.pi * x) / r
        return g, dg

    def envelope(self, t):
        u = t - self.t_on
        d, dd = self._decay(u)
        m = 1.0 + self.drift * u
        dm = self.drift
        g, dg = self._gate(t)
        e = self.amp * d * m * g
        de = self.amp * (dd * m * g + d * dm * g + d * m * dg)
        return e, de

    def eval(self, t):
        """Angle (deg) and rate (deg/s) at true times t."""
        t = np.asarray(t, dtype=float)
        e, de = self.envelope(t)
        w = 2 * math.pi * self.f
        psi = w * (t - self.t_on) + self.phi0
        ang = e * np.sin(psi)
        rate = de * np.sin(psi) + e * w * np.cos(psi)
        if self.h2:
            psi2 = 2 * psi + self.h2_phase
            ang = ang + self.h2 * e * np.sin(psi2)
            rate = rate + self.h2 * (de * np.sin(psi2) + e * 2 * w * np.cos(psi2))
        for n, h, ph in self.dist:
            # h (e / 10)^(n-1) e cos(n chi + ph), chi = psi - 90 deg
            arg = n * (psi - 0.5 * math.pi) + ph
            scale = h / 10.0 ** (n - 1)
            ang = ang + scale * e ** n * np.cos(arg)
            rate = rate + scale * (n * e ** (n - 1) * de * np.cos(arg) - e ** n * n * w * np.sin(arg))
        return ang, rate


def commanded_state(t, swings, p):
    """The swings and the fixed angles: angles and rates (n, 3) at true
    times t, before any table error."""
    t = np.asarray(t, dtype=float)
    ang = np.tile(np.asarray(p["fixed_angles_deg"], dtype=float), (t.size, 1))
    rate = np.zeros((t.size, 3))
    for sw in swings:
        lo, hi = sw.active_range()
        sel = (t > lo) & (t < hi)
        if not np.any(sel):
            continue
        i = AXES.index(sw.axis)
        if sel.all():
            a, r = sw.eval(t)
            ang[:, i] += a
            rate[:, i] += r
        else:
            a, r = sw.eval(t[sel])
            ang[sel, i] += a
            rate[sel, i] += r
    return ang, rate


SERVO_AXES = (0, 1)   # the unbalance acts on the horizontal axes x and y (z is vertical)


def _unbalance(ang, p):
    """The servo's static deflection eps sin(theta + phi) (deg) on x and y."""
    eps = p["servo_unbalance_arcsec"] * ARCSEC
    arg = np.deg2rad(ang[:, SERVO_AXES]) + math.radians(p["servo_unbalance_phase_deg"])
    return eps * np.sin(arg), eps * np.cos(arg)


def table_state(t, swings, p, fixture=False):
    """Table angles and angle rates (n, 3) at true times t: the motion that
    the encoder reads. fixture=True: the angles of the IMU's fixture, which
    follows the motion through the compliance (when there is one)."""
    t = np.asarray(t, dtype=float)
    ang, rate = commanded_state(t, swings, p)
    if p.get("servo_unbalance_arcsec", 0.0):
        d, dc = _unbalance(ang, p)
        if p["servo_corner_hz"] > 0:
            t0, h, v, dv = p["_servo"]
            delta, _ = hermite(t, t0, h, v, dv)
            ddelta = (d - delta) * (2.0 * math.pi * p["servo_corner_hz"])
        else:
            delta, ddelta = d, dc * np.deg2rad(rate[:, SERVO_AXES])
        ang[:, SERVO_AXES] += delta
        rate[:, SERVO_AXES] += ddelta
    if fixture and p.get("compliance_fn_hz", 0.0) > 0:
        t0, h, v, dv = p["_compliance"]
        e, de = hermite(t, t0, h, v, dv)
        ang, rate = ang + e, rate + de
    return ang, rate


def prepare_motion(p, swings, t_lo, t_hi):
    """The servo's and the compliance's states on a grid of MOTION_GRID_S
    from t_lo (at rest there) to t_hi, exact for inputs linear between grid
    points; stored in p["_servo"] / p["_compliance"] as (t0, h, value,
    derivative) for table_state's Hermite interpolation."""
    h = MOTION_GRID_S
    if p.get("compliance_fn_hz", 0.0) > 0:
        zeta = p["compliance_zeta"]
        if not 0 < zeta < 1:
            raise ValueError("compliance_zeta must be in (0, 1)")
        t_lo = t_lo - 25.0 / (zeta * 2.0 * math.pi * p["compliance_fn_hz"])  # the start's transient: exp(-25)
    if p.get("servo_unbalance_arcsec", 0.0) and p["servo_corner_hz"] > 0:
        tg = t_lo + h * np.arange(int(math.ceil((t_hi - t_lo) / h)) + 2)
        ang, _ = commanded_state(tg, swings, p)
        d, _ = _unbalance(ang, p)
        wc = 2.0 * math.pi * p["servo_corner_hz"]
        delta = linear_mode(-wc, d * wc, h, d[0])
        p["_servo"] = (t_lo, h, delta, (d - delta) * wc)
    if p.get("compliance_fn_hz", 0.0) > 0:
        zeta = p["compliance_zeta"]
        wn = 2.0 * math.pi * p["compliance_fn_hz"]
        tg = t_lo + h * np.arange(int(math.ceil((t_hi - t_lo) / h)) + 2)
        _, r1 = table_state(tg + 0.5 * h, swings, p)
        _, r0 = table_state(tg - 0.5 * h, swings, p)
        acc = (r1 - r0) / h                   # the motion's angular acceleration (deg/s^2)
        pole = complex(-zeta * wn, wn * math.sqrt(1.0 - zeta * zeta))
        # e'' + 2 zeta wn e' + wn^2 e = -acc: 1/((s - p)(s - p*)) = Im(y)/Im(p)
        # with y' = p y + u.
        y = linear_mode(pole, (-acc).astype(complex), h, np.zeros(3, dtype=complex))
        p["_compliance"] = (t_lo, h, y.imag / pole.imag, (pole * y).imag / pole.imag)


# --------------------------------------------------------------------------
# Generation
# --------------------------------------------------------------------------

def _vec3(v, name):
    if np.isscalar(v):
        return np.array([float(v)] * 3)
    v = np.asarray(v, dtype=float)
    if v.shape != (3,):
        raise ValueError("%s needs 1 or 3 values" % name)
    return v


# Version 1's parameters that copied the diagnosis library's form.
LEGACY_KEYS = {
    "sf_asymmetry_ppm": "give sf_asymmetry_ieee_ppm = (K+ - K-) / Kbar = 2 x its value",
    "table_poly_ppm": "give table_harmonics_ppm [h2, h3] = [c2 / 2, -c3 / 4] (phases 0)",
    "sf_nonlinearity_ppm_at_100": "give sf_nonlinearity_ieee_ppm = 0.4 x its value (IEEE Std 528 over +-100 deg/s)",
}


def scale_factor_transfer(w, p):
    """The gyro's static rate transfer (deg/s in, deg/s out): the IEEE Std 528
    nonlinearity N over +-100 deg/s as the least-squares line (1 + 1.5 N) w
    plus the deviation N 100 P3(w / 100), then the scale factor K+ = Kbar
    (1 + a/2) on positive and K- = Kbar (1 - a/2) on negative rates."""
    n_sf = p["sf_nonlinearity_ieee_ppm"] * 1e-6
    if n_sf:
        x = w / 100.0
        w = w * (1.0 + 1.5 * n_sf) + n_sf * 100.0 * 0.5 * (5.0 * x ** 3 - 3.0 * x)
    k_bar = 1.0 + p["scale_factor_ppm"] * 1e-6
    a = p["sf_asymmetry_ieee_ppm"] * 1e-6                   # (K+ - K-) / Kbar
    return w * np.where(w >= 0.0, k_bar * (1.0 + 0.5 * a), k_bar * (1.0 - 0.5 * a))


def resolve(params):
    """Fill the random and derived parameters; returns a new dict."""
    p = default_params()
    for old, new in LEGACY_KEYS.items():
        if old in params:
            raise ValueError("%s is no longer a parameter (generator version 1, the library's own form): %s"
                             % (old, new))
    p.update(copy.deepcopy(params))
    rng = np.random.default_rng([int(p["seed"]), 0x5EED])
    if p["timing"] not in ("commensurate", "incommensurate"):
        raise ValueError("timing must be commensurate or incommensurate")
    segs = []
    for s in p["segments"]:
        seg = default_segment()
        seg.update(s)
        if seg["axis"] not in AXES:
            raise ValueError("axis must be x, y or z")
        if seg["start_phase_deg"] is None:
            seg["start_phase_deg"] = 0.0 if p["timing"] == "commensurate" else float(rng.uniform(0, 360))
        segs.append(seg)
    p["segments"] = segs
    if p["continuous"] and len({s["axis"] for s in segs}) != 1:
        raise ValueError("continuous mode swings one axis (the metadata lists one test point)")
    p["gyro_sign"] = [int(x) for x in _vec3(p["gyro_sign"], "gyro_sign")]
    p["bias_deg_h"] = [float(x) for x in _vec3(p["bias_deg_h"], "bias_deg_h")]
    p["bias_step_deg_h"] = [float(x) for x in _vec3(p["bias_step_deg_h"], "bias_step_deg_h")]
    p["fixed_angles_deg"] = [float(x) for x in _vec3(p["fixed_angles_deg"], "fixed_angles_deg")]
    p["mount_rpy_arcsec"] = [float(x) for x in _vec3(p["mount_rpy_arcsec"], "mount_rpy_arcsec")]
    if not np.isscalar(p["g_sens_deg_h_g"]):
        p["g_sens_deg_h_g"] = [float(x) for x in _vec3(p["g_sens_deg_h_g"], "g_sens_deg_h_g")]
    if any(ax not in AXES for ax in p["eccentricity_axes"]):
        raise ValueError("eccentricity_axes takes letters of xyz")
    if sorted(p["axis_order"]) != ["x", "y", "z"]:
        raise ValueError("axis_order must be a permutation of xyz")
    if p["rate_output"] not in (None, "frame_average", "sample_at_stamp"):
        raise ValueError("rate_output must be frame_average or sample_at_stamp")
    # Stamp grids: offsets of the first stamp against the first test point's
    # start, and the true periods.
    if p["timing"] == "commensurate":
        p["_table_offset_s"] = 0.0
        p["_gyro_offset_s"] = 0.0
        p["_table_period_s"] = p["table_period_ms"] * 1e-3
        p["_imu_clock_ppm_total"] = p["imu_clock_ppm"]
    else:
        nr = p["nonround_ppm"] * 1e-6
        p["_table_offset_s"] = float(rng.uniform(0, 1)) * p["table_period_ms"] * 1e-3
        p["_gyro_offset_s"] = float(rng.uniform(0, 1)) * p["imu_period_ms"] * 1e-3
        p["_table_period_s"] = p["table_period_ms"] * 1e-3 * (1 + float(rng.uniform(-nr, nr)))
        p["_imu_clock_ppm_total"] = p["imu_clock_ppm"] + float(rng.uniform(-1, 1)) * p["nonround_ppm"]
    p["_pulse_phase"] = float(rng.uniform(0, 1))
    return p


def timeline(p):
    """Swings, analysed windows [t_on, t_on + duration] and the timeline end."""
    segs = p["segments"]
    gated = len(segs) > 1 or p["continuous"]
    swings, windows = [], []
    t = p["lead_s"]
    if not gated:
        s = segs[0]
        swings.append(Swing(s, p, t, False))
        windows.append((t, t + s["duration_s"]))
        return swings, windows, t + s["duration_s"] + p["tail_s"], gated
    settle = p.get("settle_s", 0.0)
    for i, s in enumerate(segs):
        t_on = t + p["ramp_s"]
        if settle > 0:
            # the swing steady from t_on, its window settle_s later (a
            # filter's ramp transient decays before it): phase at t_on
            swings.append(Swing(dict(s, duration_s=s["duration_s"] + settle), p, t_on, True))
            t_on += settle
        else:
            swings.append(Swing(s, p, t_on, True))
        windows.append((t_on, t_on + s["duration_s"]))
        t = t_on + s["duration_s"] + p["ramp_s"] + (p["rest_s"] if i + 1 < len(segs) else 0.0)
    return swings, windows, t + p["lead_s"], gated


def _grid(start, period, n):
    """start + n * period; when the rate 1/period and start/period are whole
    numbers (commensurate stamps) as (start*rate + n) / rate, so that 1 kHz
    stamps read 1.001, not 1.0009999999999999."""
    rate = 1.0 / period
    k = start * rate
    if abs(rate - round(rate)) < 1e-9 * rate and abs(k - round(k)) < 1e-6:
        return (round(k) + n) / float(round(rate))
    return start + n * period


def gauss_markov(p, start, end):
    """The bias instability on a grid from start to end: (times, rates in
    deg/s per gyro), or None when there is none. Its own random stream, so a
    session without it is the same as before it existed."""
    sigma = p["bias_instability_deg_h"] / 3600.0
    if sigma <= 0.0:
        return None
    tau = p["bias_correlation_s"]
    if not tau > 0.0:
        raise ValueError("bias_correlation_s must be > 0")
    h = min(0.1, tau / 50.0)
    n = int(math.ceil((end - start) / h)) + 1
    rng = np.random.default_rng([int(p["seed"]), 0xB1A5])
    phi = math.exp(-h / tau)
    kicks = rng.normal(0.0, sigma * math.sqrt(1.0 - phi * phi), (n, 3))
    x = np.empty((n, 3))
    x[0] = rng.normal(0.0, sigma, 3)
    for k in range(1, n):
        x[k] = phi * x[k - 1] + kicks[k]
    return start + h * np.arange(n), x


def ar1(phi, kicks, x0):
    """x_k = phi x_{k-1} + kicks_k from x_0 = x0 (kicks[0] unused); phi may
    be an array broadcast against kicks' trailing axes. Blocked sums."""
    phi = np.asarray(phi, dtype=float)
    x = np.empty_like(kicks)
    x[0] = x0
    L = max(1, int(30.0 / max(float(np.max(-np.log(phi))), 1e-12)))
    prev = x[0].copy()
    for b in range(1, kicks.shape[0], L):
        kb = kicks[b:b + L]
        k = np.arange(1, kb.shape[0] + 1).reshape((-1,) + (1,) * (kicks.ndim - 1)).astype(float)
        x[b:b + kb.shape[0]] = phi ** k * (prev + np.cumsum(kb * phi ** (-k), axis=0))
        prev = x[b + kb.shape[0] - 1].copy()
    return x


def flicker_taus(p):
    """Correlation times of the flicker's Gauss-Markov processes (one per
    decade from the range's low end) and each one's sigma (deg/h):
    B sqrt(ln 10 / (2 pi)), which makes the sum's one-sided PSD
    sum 4 sigma^2 tau / (1 + (2 pi f tau)^2) ~ B^2 / (2 pi f) inside the range."""
    lo, hi = (float(v) for v in p["flicker_tau_range_s"])
    if not 0 < lo <= hi:
        raise ValueError("flicker_tau_range_s must be 0 < low <= high")
    n = int(math.floor(math.log10(hi / lo) + 1e-9)) + 1
    taus = lo * 10.0 ** np.arange(n)
    return taus, p["flicker_deg_h"] * math.sqrt(math.log(10.0) / (2.0 * math.pi))


def flicker_components(p, start, end):
    """The flicker's processes on a grid from start to end: (times, deg/s
    (n, 3 gyros, decades)), stationary at the start; own random stream."""
    taus, sigma = flicker_taus(p)
    h = min(0.1, float(taus[0]) / 50.0)
    n = int(math.ceil((end - start) / h)) + 1
    rng = np.random.default_rng([int(p["seed"]), 0xF11C])
    phi = np.exp(-h / taus)
    sig = sigma / 3600.0
    kicks = rng.normal(0.0, 1.0, (n, 3, taus.size)) * (sig * np.sqrt(1.0 - phi * phi))
    x0 = rng.normal(0.0, sig, (3, taus.size))
    return start + h * np.arange(n), ar1(phi, kicks, x0)


def bias_noise(p, start, end):
    """Rate random walk plus flicker bias on one grid: (times, deg/s per
    gyro), or None when both are off. The walk starts at 0 at `start`; each
    has its own random stream."""
    k, b = p["rrw_deg_h_sqrt_h"], p["flicker_deg_h"]
    if k <= 0 and b <= 0:
        return None
    h = 0.1 if b <= 0 else min(0.1, float(flicker_taus(p)[0][0]) / 50.0)
    n = int(math.ceil((end - start) / h)) + 1
    grid = start + h * np.arange(n)
    total = np.zeros((n, 3))
    if k > 0:
        # K deg/h/sqrt(h) = K / 3600 deg/s per sqrt(3600 s)
        steps = np.random.default_rng([int(p["seed"]), 0x8A4D]).normal(0.0, k / 216000.0 * math.sqrt(h), (n, 3))
        steps[0] = 0.0
        total += np.cumsum(steps, axis=0)
    if b > 0:
        g, comps = flicker_components(p, start, end)
        total += comps.sum(axis=2)[:n]
    return grid, total


def frame_latency(p, frame_t):
    """Each frame's latency (s) from its end to its stamp beyond the fixed
    delays: mode 2 (latency_delta_us) with probability latency_p2, white or
    a two-state Markov chain with mean dwell latency_dwell_s in mode 2; plus
    latency_sigma_us rms in either. None when off; own random stream."""
    p2, sig = p["latency_p2"], p["latency_sigma_us"]
    if p2 <= 0 and sig <= 0:
        return None
    if not 0 <= p2 < 1:
        raise ValueError("latency_p2 must be in [0, 1)")
    rng = np.random.default_rng([int(p["seed"]), 0x1A7E])
    n = frame_t.size
    if p["latency_dwell_s"] <= 0 or p2 <= 0:
        mode = rng.uniform(size=n) < p2
    else:
        period = float(np.median(np.diff(frame_t))) if n > 1 else 1.0
        leave2 = min(1.0, period / p["latency_dwell_s"])           # per frame, out of mode 2
        leave1 = min(1.0, leave2 * p2 / (1.0 - p2))                  # out of mode 1
        mode = np.zeros(n, dtype=bool)
        state, i = bool(rng.uniform() < p2), 0
        while i < n:
            run = int(rng.geometric(leave2 if state else leave1))
            mode[i:i + run] = state
            i += run
            state = not state
    lat = mode * (p["latency_delta_us"] * 1e-6)
    if sig > 0:
        lat = lat + rng.normal(0.0, sig * 1e-6, n)
    return lat


def generate(params, chunk_frames=5000):
    """Runs the model; returns a dict of arrays (true and written values)."""
    p = resolve(params)
    rng = np.random.default_rng([int(p["seed"]), 1])
    swings, windows, t_end, gated = timeline(p)
    t0 = windows[0][0]   # stamp grids are anchored at the first test point's start
    if (p["servo_unbalance_arcsec"] and p["servo_corner_hz"] > 0) or p["compliance_fn_hz"] > 0:
        prepare_motion(p, swings, -2.0 - abs(p["imu_delay_ms"]) * 1e-3, t_end + 2.0)

    # ---------------- table stream ----------------
    Pt = p["_table_period_s"]
    j0 = math.ceil((0.0 - t0 - p["_table_offset_s"]) / Pt)
    j1 = math.floor((t_end - t0 - p["_table_offset_s"]) / Pt)
    tab_t = _grid(t0 + p["_table_offset_s"], Pt, np.arange(j0, j1 + 1))
    latch = tab_t - p["table_read_delay_ms"] * 1e-3
    tab_true, _ = table_state(latch, swings, p)
    q = p["encoder_arcsec"] * ARCSEC
    tab_meas = tab_true.copy()
    es, ec = (v * ARCSEC for v in p["encoder_cyclic_arcsec"])
    if es or ec:
        ph = 2.0 * math.pi * tab_true / 10.0
        tab_meas += es * np.sin(ph) + ec * np.cos(ph)
    if p["eccentricity_um"]:
        # (e / r) rad once per revolution: e in um, r in mm
        ecc = p["eccentricity_um"] * 1e-3 / p["eccentricity_radius_mm"]
        for ax in p["eccentricity_axes"]:
            i = AXES.index(ax)
            tab_meas[:, i] += math.degrees(ecc) * np.sin(
                np.deg2rad(tab_true[:, i]) + math.radians(p["eccentricity_phase_deg"]))
    if p["encoder_noise_arcsec"] > 0:
        tab_meas += rng.normal(0, p["encoder_noise_arcsec"] * ARCSEC, tab_meas.shape)
    if q > 0:
        tab_meas = np.round(tab_meas / q) * q
    tab_lost = 0
    if p["table_drop_per_mille"] > 0:
        # rows lost between the encoder and table.csv (the first is kept);
        # their own random stream
        keep = np.random.default_rng([int(p["seed"]), 0x7AB1E]).uniform(size=tab_t.size) >= \
            p["table_drop_per_mille"] * 1e-3
        keep[0] = True
        tab_lost = int(tab_t.size - keep.sum())
        tab_t, tab_true, tab_meas = tab_t[keep], tab_true[keep], tab_meas[keep]

    # ---------------- gyro: fine grid on the IMU crystal ----------------
    Pg = p["imu_period_ms"] * 1e-3 / (1 + p["_imu_clock_ppm_total"] * 1e-6)
    M_f = p["imu_period_ms"] * 1e-3 * p["fine_hz"]
    M = int(round(M_f))
    if M < 1 or abs(M - M_f) > 1e-9 * max(1.0, M_f):
        raise ValueError("imu_period_ms * fine_hz must be an integer (fine steps per frame)")
    dt = Pg / M
    k0 = math.ceil((0.0 - t0 - p["_gyro_offset_s"]) / Pg)
    k1 = math.floor((t_end - t0 - p["_gyro_offset_s"]) / Pg)
    # one extra frame before the first so that its increment is defined too
    frame_k = np.arange(k0 - 1, k1 + 1)
    frame_t = _grid(t0 + p["_gyro_offset_s"], Pg, frame_k)   # true end times
    nfr = frame_t.size
    tau = p["imu_delay_ms"] * 1e-3
    sign = np.array(p["gyro_sign"], dtype=float)
    bias = np.array(p["bias_deg_h"]) / 3600.0
    bstep = np.array(p["bias_step_deg_h"]) / 3600.0
    wander = gauss_markov(p, t0 - p["_gyro_offset_s"] - 1.0, t_end + 1.0)
    walk = bias_noise(p, t0 - p["_gyro_offset_s"] - 1.0, t_end + 1.0)
    arw_step = p["arw_deg_sqrt_h"] / 60.0 * math.sqrt(dt)   # deg per fine step
    pe = p["pulse_arcsec"] * ARCSEC

    theta = np.empty((nfr, 3))        # integrated measured angle at frame ends (deg)
    rate_at_end = np.empty((nfr, 3))  # measured rate at frame ends incl. noise (deg/s)
    theta[0] = p["_pulse_phase"] * pe
    t_first = frame_t[0]

    m = np.zeros((3, 3))
    for (i, j), v in zip([(0, 1), (0, 2), (1, 0), (1, 2), (2, 0), (2, 1)], p["misalignment_urad"]):
        m[i, j] = v * 1e-6
    lag_s = p["lag_tau_ms"] * 1e-3

    mount = None
    if any(p["mount_rpy_arcsec"]):
        r_, p_, y_ = (v * ARCSEC for v in p["mount_rpy_arcsec"])
        mount = rot("x", r_) @ rot("y", p_) @ rot("z", y_)   # the IMU's axes in the table's inner frame
    gsens = np.asarray(p["g_sens_deg_h_g"], dtype=float)

    def sensed_rate(tf):
        """What the gyros sense before the lag: body rate (of the fixture)
        through the mount's rotation and the misalignment, plus the
        g-sensitive rate error."""
        ang, r = table_state(tf - tau, swings, p, fixture=True)
        w = body_rates(ang, r, p)
        if mount is not None:
            w = w @ mount                                   # R_m^T omega, row-wise
        w = w + w @ m.T
        if np.any(gsens != 0.0):
            f_b = specific_force(ang, p)
            if mount is not None:
                f_b = f_b @ mount
            w = w + gsens / 3600.0 * f_b
        w = scale_factor_transfer(w, p)
        if p["bias_drift_deg_h_per_min"] != 0.0:
            w = w + (p["bias_drift_deg_h_per_min"] / 3600.0 / 60.0 * (tf - t_first))[:, None]
        return w

    lag_state = {}
    box_state = {}
    res_state = {}
    res_pole = None
    if p["second_order_fn_hz"] > 0:
        zeta = p["second_order_zeta"]
        if not 0 < zeta < 1:
            raise ValueError("second_order_zeta must be in (0, 1)")
        wn = 2.0 * math.pi * p["second_order_fn_hz"]
        res_pole = complex(-zeta * wn, wn * math.sqrt(1.0 - zeta * zeta))
    nbox = 0
    if p["boxcar_ms"] > 0:
        nb = p["boxcar_ms"] * 1e-3 * p["fine_hz"]
        nbox = int(round(nb))
        if nbox < 1 or abs(nbox - nb) > 1e-9 * nb:
            raise ValueError("boxcar_ms * fine_hz must be a whole number of fine steps")

    def measured_rate(tf):
        w = sensed_rate(tf)
        if lag_s > 0:
            if not lag_state:   # at rest before the first instant: output = input
                lag_state["x"] = w[0].copy()
                lag_state["y"] = w[0].copy()
            y = first_order_lag(w, dt, lag_s, lag_state["y"], lag_state["x"])
            lag_state["x"], lag_state["y"] = w[-1].copy(), y[-1].copy()
            w = y
        if res_pole is not None:
            # wn^2 / ((s - q)(s - q*)) = wn^2 Im(z) / Im(q) with z' = q z + x:
            # the complex mode of the ODE, exact for x linear between samples
            wn2 = abs(res_pole) ** 2
            if not res_state:   # at rest before the first instant: z = -x / q, output = input
                res_state["x"] = w[0].copy()
                res_state["z"] = -w[0].astype(complex) / res_pole
            z = linear_mode(res_pole, np.vstack([res_state["x"][None, :], w]).astype(complex), dt, res_state["z"])[1:]
            res_state["x"], res_state["z"] = w[-1].copy(), z[-1].copy()
            w = wn2 * z.imag / res_pole.imag
        out = w * sign + bias
        if np.any(bstep):
            out = out + np.where((tf >= p["bias_step_time_s"])[:, None], bstep, 0.0)
        if wander is not None:
            grid, values = wander
            out = out + np.stack([np.interp(tf, grid, values[:, a]) for a in range(3)], axis=1)
        if walk is not None:
            grid, values = walk
            out = out + np.stack([np.interp(tf, grid, values[:, a]) for a in range(3)], axis=1)
        if nbox:
            # boxcar: y(t) = (Theta(t) - Theta(t - T)) / T, Theta the trapezoid
            # integral of the rate on the fine grid, at rest before the start
            if not box_state:
                box_state["hist"] = -np.arange(nbox - 1, -1, -1)[:, None] * dt * out[0][None, :]
                box_state["cum"], box_state["last"] = np.zeros(3), out[0].copy()
                return out
            cum = box_state["cum"] + np.cumsum(0.5 * dt * (np.vstack([box_state["last"][None, :], out[:-1]]) + out),
                                               axis=0)
            allc = np.vstack([box_state["hist"], cum])
            y = (cum - allc[:cum.shape[0]]) / (nbox * dt)
            box_state["hist"], box_state["cum"], box_state["last"] = allc[-nbox:], cum[-1].copy(), out[-1].copy()
            return y
        return out

    reg_period = 0.0
    if p["register_period_ms"] > 0:
        if p["register_period_ms"] > p["imu_period_ms"] or not 0 <= p["register_offset_ms"] < p["register_period_ms"]:
            raise ValueError("register_period_ms must be at most imu_period_ms and 0 <= register_offset_ms < it")
        if p["rate_output"] == "sample_at_stamp":
            raise ValueError("the pulse register is modelled for increments and frame averages")
        crystal = Pg / (p["imu_period_ms"] * 1e-3)          # true seconds per IMU-clock second
        reg_period = p["register_period_ms"] * 1e-3 * crystal / (1.0 + p["register_clock_ppm"] * 1e-6)
        reg_start = t_first - p["register_offset_ms"] * 1e-3 * crystal
    prev_rate = measured_rate(np.array([t_first]))[0]
    rate_at_end[0] = prev_rate
    prev_theta = theta[0].copy()
    f = 1
    while f < nfr:
        nf = min(chunk_frames, nfr - f)
        # fine points after the previous frame end up to frame f + nf - 1
        jj = np.arange(1, nf * M + 1)
        tf = t_first + ((f - 1) * M + jj) * dt
        r = measured_rate(tf)
        inc = 0.5 * dt * (np.vstack([prev_rate[None, :], r[:-1]]) + r)
        noise = rng.normal(0.0, arw_step, inc.shape) if arw_step > 0 else np.zeros_like(inc)
        cum = prev_theta + np.cumsum(inc + noise, axis=0)
        ends = np.arange(M - 1, nf * M, M)
        if reg_period > 0:
            # the frame reads the register's value at its last update, u before the frame's end
            x = frame_t[f:f + nf] - reg_start
            u = x - reg_period * np.floor(x / reg_period + 1e-9)
            q = (ends + 1) - u / dt
            ql = np.minimum(np.floor(q).astype(np.int64), nf * M - 1)
            ext = np.vstack([prev_theta[None, :], cum])
            theta[f:f + nf] = ext[ql] + (q - ql)[:, None] * (ext[ql + 1] - ext[ql])
        else:
            theta[f:f + nf] = cum[ends]
        rate_at_end[f:f + nf] = r[ends] + noise[ends] / dt
        prev_rate = r[-1]
        prev_theta = cum[-1]
        f += nf

    pulses = np.floor(theta / pe).astype(np.int64)
    inc_pulses = np.diff(pulses, axis=0)           # frames 1 .. nfr-1
    frame_t = frame_t[1:]
    theta_out = theta[1:]
    rate_at_end = rate_at_end[1:]

    # stamps on the board clock
    latency = frame_latency(p, frame_t)
    stamp = (frame_t if latency is None else frame_t + latency) * (1 + p["clock_rate_ppm_gyro"] * 1e-6)
    if p["gyro_stamp_jitter_us"] > 0:
        stamp = stamp + rng.normal(0.0, p["gyro_stamp_jitter_us"] * 1e-6, stamp.shape)
    if p["stamp_quantum_us"] > 0:
        sq = p["stamp_quantum_us"] * 1e-6
        stamp = np.round(stamp / sq) * sq
        tab_t = np.round(tab_t / sq) * sq
    if np.any(np.diff(stamp) <= 0):
        raise ValueError("gyro stamps do not increase (jitter too large for the frame period)")

    # gyro values
    if p["rate_output"] is None:
        gvals = inc_pulses * pe
    elif p["rate_output"] == "frame_average":
        gvals = inc_pulses * pe / (p["imu_period_ms"] * 1e-3)
    else:
        gvals = rate_at_end.copy()
        if p["rate_lsb_deg_s"] > 0:
            gvals = np.round(gvals / p["rate_lsb_deg_s"]) * p["rate_lsb_deg_s"]
    gyro_t = stamp
    if p["sample_hold_ms"] > 0:
        Ph = p["sample_hold_ms"] * 1e-3
        hold_t = t0 + p["_table_offset_s"] + np.arange(
            math.ceil((stamp[0] - t0 - p["_table_offset_s"]) / Ph),
            math.floor((stamp[-1] - t0 - p["_table_offset_s"]) / Ph) + 1) * Ph
        idx = np.searchsorted(stamp, hold_t, side="right") - 1
        keep = idx >= 0
        hold_t, idx = hold_t[keep], idx[keep]
        gyro_t = hold_t
        gvals = gvals[idx]
        held_from = idx
    else:
        held_from = np.arange(stamp.size)
    lost_before = np.zeros(gyro_t.size, dtype=np.int64)
    if p["drop_per_mille"] > 0:
        if p["sample_hold_ms"] > 0 or p["rate_output"] is not None:
            raise ValueError("drop_per_mille works on increments without sample-and-hold")
        drop = rng.uniform(size=gyro_t.size) < p["drop_per_mille"] * 1e-3
        drop[0] = False
        kept = np.nonzero(~drop)[0]
        lost_before = np.diff(np.concatenate([[-1], kept])) - 1
        gyro_t, gvals, held_from = gyro_t[kept], gvals[kept], held_from[kept]

    return {
        "params": p,
        "swings": swings,
        "windows": windows,
        "gated": gated,
        "t_end": t_end,
        "table_t": tab_t,
        "table_true": tab_true,
        "table_deg": tab_meas,
        "frame_t_true": frame_t,
        "bias_wander": wander,            # None, or (times, deg/s per gyro)
        "frame_stamp": stamp,
        "frame_theta": theta_out,
        "frame_pulses": inc_pulses,
        "frame_rate": rate_at_end,
        "gyro_t": gyro_t,
        "gyro_val": gvals,
        "gyro_from_frame": held_from,
        "gyro_lost_before": lost_before,
        "table_rows_lost": tab_lost,
        "frame_latency": latency,         # None, or s per frame (true, before the board's clock)
        "pulse_deg": pe,
        "fine_dt_s": dt,
        "frame_period_true_s": Pg,
    }


# --------------------------------------------------------------------------
# Truth
# --------------------------------------------------------------------------

def physical_effects(res):
    """What the effects in their physical form amount to, in closed form
    (README "Outside effects"); only those that are on."""
    p, out = res["params"], {}
    if p["register_period_ms"] > 0:
        out["register_extra_delay_ms"] = p["register_offset_ms"] if not p["register_clock_ppm"] else \
            "varies from 0 to %g ms" % p["register_period_ms"]
    if p["second_order_fn_hz"] > 0:
        # its group delay at 0 Hz: 2 zeta / wn
        out["second_order_low_frequency_delay_ms"] = \
            2.0 * p["second_order_zeta"] / (2.0 * math.pi * p["second_order_fn_hz"]) * 1e3
    if p["boxcar_ms"] > 0:
        out["boxcar_extra_delay_ms"] = p["boxcar_ms"] / 2.0
        out["boxcar_equivalent_lag_ms"] = p["boxcar_ms"] / math.sqrt(12.0)   # same loss of gain to O(f^2)
    if p["latency_p2"] > 0 or p["latency_sigma_us"] > 0:
        d, q, sg = p["latency_delta_us"], p["latency_p2"], p["latency_sigma_us"]
        out["latency_mean_us"] = q * d
        out["latency_variance_us2"] = q * (1 - q) * d * d + sg * sg
    if p["eccentricity_um"]:
        out["eccentricity_rad"] = p["eccentricity_um"] * 1e-3 / p["eccentricity_radius_mm"]
    if p["servo_unbalance_arcsec"]:
        eps = math.radians(p["servo_unbalance_arcsec"] * ARCSEC)
        phi = math.radians(p["servo_unbalance_phase_deg"])
        ten = math.radians(10.0)
        # eps sin(theta + phi) about 0 (static servo), theta = 10 deg cos(chi):
        # -eps sin(phi) theta^2 / 2 gives the 2nd harmonic -eps sin(phi) (10 deg)^2 / 4 cos(2 chi),
        # -eps cos(phi) theta^3 / 6 the 3rd -eps cos(phi) (10 deg)^3 / 24 cos(3 chi) (rad), each
        # relative to the fundamental's 10 deg: the table's 2nd and 3rd harmonics (phase 0 at its peak)
        out["servo_equivalent_table_harmonics_ppm"] = [-eps * math.sin(phi) * ten / 4.0 * 1e6,
                                                       -eps * math.cos(phi) * ten * ten / 24.0 * 1e6]
    if any(p["mount_rpy_arcsec"]):
        r_, q_, y_ = (math.radians(v * ARCSEC) * 1e6 for v in p["mount_rpy_arcsec"])
        out["mount_equivalent_misalignment_urad"] = [y_, -q_, -y_, r_, q_, -r_]
    if res.get("table_rows_lost"):
        out["table_rows_lost"] = int(res["table_rows_lost"])
    return out


def truth(res):
    p = res["params"]
    lag = p["imu_delay_ms"] - p["table_read_delay_ms"]
    pts = []
    for i, (sw, (a, b)) in enumerate(zip(res["swings"], res["windows"])):
        ax = AXES.index(sw.axis)
        # Earth rate on the swing axis at the centre angle (constant when the
        # swing axis is the table's inner axis or the other axes are at 0).
        ang = np.array([p["fixed_angles_deg"]])
        w = body_rates(ang, np.zeros((1, 3)), p)[0]
        earth = w[ax] * 3600.0
        trend = p["gyro_sign"][ax] * earth + p["bias_deg_h"][ax]
        mid = 0.5 * (a + b)
        e0, _ = sw.envelope(np.array([a]))
        e1, _ = sw.envelope(np.array([b]))
        apparent = lag + p["clock_rate_ppm_gyro"] * 1e-6 * mid * 1e3
        pts.append({
            "test_point": i + 1,
            "axis": sw.axis,
            "frequency_hz_nominal": sw.f_nom,
            "frequency_hz_true": sw.f,
            "amplitude_deg": sw.amp,
            "amplitude_deg_at_start": float(e0[0]),
            "amplitude_deg_at_end": float(e1[0]),
            "start_phase_deg": math.degrees(sw.phi0),
            "window_s": [a, b],
            "duration_s": b - a,
            "periods": (b - a) * sw.f,
            "earth_rate_on_swing_axis_deg_h": earth,
            "expected_trend_deg_h": trend,
            "expected_magnitude_ratio": p["gyro_sign"][ax],
            "apparent_lag_ms_at_middle": apparent,
        })
    case = p.get("case")
    return {
        "physical_effects": physical_effects(res),
        "generator": "tests/independent/refgen.py",
        "generator_version": GENERATOR_VERSION,
        "shares_code_with_core_model": False,
        "case": case,
        "case_description": CASES[case]["description"] if case in CASES else None,
        "expected_verdict": CASES[case]["expected_verdict"] if case in CASES else None,
        "imu_delay_ms": p["imu_delay_ms"],
        "table_read_delay_ms": p["table_read_delay_ms"],
        "board_delay_ms": p["board_delay_ms"],
        "true_lag_ms": lag,
        "gyro_delay_ms": p["imu_delay_ms"] - p["board_delay_ms"],
        "lag_definition": "imu_delay_ms - table_read_delay_ms: the time by which the gyro output lags the stamped "
                          "table reading",
        "clock_note": ("gyro stamps run %g ppm against the table's: the lag is not defined; apparent lag grows "
                       "with time" % p["clock_rate_ppm_gyro"]) if p["clock_rate_ppm_gyro"] else None,
        "pulse_equivalent_deg": res["pulse_deg"],
        "fine_step_s": res["fine_dt_s"],
        "imu_frame_period_true_s": res["frame_period_true_s"],
        "table_period_true_s": p["_table_period_s"],
        "table_first_stamp_offset_s": p["_table_offset_s"],
        "gyro_first_frame_offset_s": p["_gyro_offset_s"],
        "imu_clock_ppm_total": p["_imu_clock_ppm_total"],
        "timeline_end_s": res["t_end"],
        "test_points": pts,
        "rows": {"table": int(res["_rows_table"]) if "_rows_table" in res else None,
                 "gyro": int(res["_rows_gyro"]) if "_rows_gyro" in res else None},
        "params": {k: v for k, v in p.items() if not k.startswith("_")},
    }


# --------------------------------------------------------------------------
# Writing
# --------------------------------------------------------------------------

def _jsonable(x):
    if isinstance(x, float) and not math.isfinite(x):
        return "inf" if x > 0 else ("-inf" if x < 0 else "nan")
    if isinstance(x, dict):
        return {k: _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, np.generic):
        return x.item()
    return x


def metadata(res):
    p = res["params"]
    bench = {
        "table_read_delay_ms": p["table_read_delay_ms"],
        "board_delay_ms": p["board_delay_ms"],
        "pulse_equivalent_deg": res["pulse_deg"],
        "latitude_deg": p["latitude_deg"],
    }
    if p["rate_output"] is not None:
        bench["gyro_rate_convention"] = p["rate_output"]
        bench["gyro_frame_period_ms"] = p["imu_period_ms"]
    if p["declare_gyro_sign"] and any(sg < 0 for sg in p["gyro_sign"]):
        bench["gyro_sign"] = {ax: -1 for ax, sg in zip(AXES, p["gyro_sign"]) if sg < 0}
    if p["declare_frame"]:
        bench["imu_frame"] = p["declare_frame"]
    if p["continuous"]:
        tps = [{"axis": p["segments"][0]["axis"]}]
    elif p["meta_minimal"]:
        tps = [{"axis": s["axis"]} for s in p["segments"]]
    else:
        tps = [{"axis": s["axis"], "frequency_hz": s["freq_hz"], "amplitude_deg": s["amp_deg"],
                "duration_s": s["duration_s"]} for s in p["segments"]]
    meta = {
        "format": "fogbench-csv",
        "format_version": 1,
        "source": "refgen.py independent reference generator%s, seed %d" % (
            (", case " + p["case"]) if p.get("case") else "", p["seed"]),
        "notes": "synthetic data; the truth is in truth.json",
        "bench": bench,
        "test_points": tps,
    }
    if len(p["segments"]) > 1 and not p["continuous"]:
        meta["rest_between_s"] = p["rest_s"] + 2 * p["ramp_s"]
    return meta


def _write_csv(path, comment, header, cols, fmts):
    """Writes columns (1-D arrays).  Format "repr" = the shortest text that
    reads back to the same double (as fogbench's exports); "%d" = integer;
    any other printf format as given."""
    def text(c, f):
        if f == "repr":
            return list(map(repr, np.asarray(c, dtype=float).tolist()))
        if f == "%d":
            return list(map(str, np.asarray(c, dtype=np.int64).tolist()))
        return [f % v for v in np.asarray(c, dtype=float).tolist()]
    with open(path, "w", newline="\n") as fh:
        fh.write("# " + comment + "\n")
        fh.write(",".join(header) + "\n")
        if cols[0].size:
            fh.write("\n".join(map(",".join, zip(*[text(c, f) for c, f in zip(cols, fmts)]))))
            fh.write("\n")


def write_dir(res, out, overwrite=False):
    p = res["params"]
    if os.path.exists(out):
        if not os.path.isdir(out):
            raise ValueError("%s exists and is not a directory" % out)
        if os.listdir(out) and not overwrite:
            raise ValueError("%s is not empty; give --overwrite to write into it" % out)
    else:
        os.makedirs(out)
    axes_out = AXES if p["axes_out"] == "all" else sorted({s["axis"] for s in p["segments"]})
    ff = p["float_format"]
    many = len(p["segments"]) > 1 and not p["continuous"]

    # rows inside the windows (or the whole timeline when continuous)
    def select(t):
        if p["continuous"]:
            return [np.nonzero((t >= 0.0) & (t <= res["t_end"]))[0]]
        return [np.nonzero((t >= a) & (t <= b))[0] for (a, b) in res["windows"]]

    def stream_columns(times):
        """test_point (several test points) and time_s columns of one stream, and the rows kept."""
        sel = select(times)
        cols, header, fmts = [], [], []
        if many:
            cols.append(np.concatenate([np.full(s.size, i + 1) for i, s in enumerate(sel)]))
            header.append("test_point")
            fmts.append("%d")
        idx = np.concatenate(sel)
        cols.append(times[idx]); header.append("time_s"); fmts.append(ff)
        return cols, header, fmts, idx

    # table
    cols, header, fmts, idx = stream_columns(res["table_t"])
    for ax in axes_out:
        cols.append(res["table_deg"][idx, AXES.index(ax)]); header.append(ax + "_deg"); fmts.append(ff)
    _write_csv(os.path.join(out, "table.csv"),
               "refgen table stream: angles (deg) stamped when read; docs/formats.md",
               header, cols, fmts)
    res["_rows_table"] = idx.size

    # gyro
    cols, header, fmts, idx = stream_columns(res["gyro_t"])
    suffix = "_inc_deg" if p["rate_output"] is None else "_rate_deg_s"
    for ax in axes_out:
        cols.append(res["gyro_val"][idx, AXES.index(ax)]); header.append(ax + suffix); fmts.append(ff)
    if np.any(res["gyro_lost_before"]):
        cols.append(res["gyro_lost_before"][idx]); header.append("lost_before"); fmts.append("%d")
    what = ("angle increments (deg) over the frame ending at time_s" if p["rate_output"] is None else
            "rates (deg/s), convention %s" % p["rate_output"])
    _write_csv(os.path.join(out, "gyro.csv"), "refgen gyro stream: " + what + "; docs/formats.md",
               header, cols, fmts)
    res["_rows_gyro"] = idx.size

    with open(os.path.join(out, "metadata.json"), "w") as fh:
        json.dump(_jsonable(metadata(res)), fh, indent=2)
        fh.write("\n")
    with open(os.path.join(out, "truth.json"), "w") as fh:
        json.dump(_jsonable(truth(res)), fh, indent=2)
        fh.write("\n")
    return truth(res)


# --------------------------------------------------------------------------
# CLI
# --------------------------------------------------------------------------

def _floats(text):
    v = [float(x) for x in text.split(",")]
    return v[0] if len(v) == 1 else v


def build_parser():
    ap = argparse.ArgumentParser(
        prog="refgen.py",
        description="Independent reference data generator for fogbench (writes an import directory "
                    "per docs/formats.md plus truth.json). Shares no code with core/model.")
    ap.add_argument("--out", required=False, help="output directory (created; must be empty unless --overwrite)")
    ap.add_argument("--overwrite", action="store_true")
    ap.add_argument("--case", help="named preset: " + ", ".join(CASES))
    ap.add_argument("--list-cases", action="store_true", help="list the named cases and exit")
    ap.add_argument("--seed", type=int)
    g = ap.add_argument_group("swing (one test point; use --segments-json for several)")
    g.add_argument("--axis", choices=list(AXES))
    g.add_argument("--freq-hz", type=float)
    g.add_argument("--amp-deg", type=float)
    g.add_argument("--duration-s", type=float)
    g.add_argument("--start-phase-deg", type=float)
    g.add_argument("--centre-deg", type=float)
    g.add_argument("--segments-json", help='JSON list of test points, e.g. \'[{"axis":"x","freq_hz":1,'
                   '"amp_deg":3,"duration_s":30}, ...]\'')
    g.add_argument("--continuous", action="store_true", default=None,
                   help="one record, no test_point column, metadata with one test point {axis}")
    g.add_argument("--lead-s", type=float)
    g.add_argument("--tail-s", type=float)
    g.add_argument("--rest-s", type=float)
    g.add_argument("--ramp-s", type=float)
    g.add_argument("--table-freq-error-ppm", type=float)
    g.add_argument("--decay-tau-s", type=float)
    g.add_argument("--amp-drift-per-s", type=float)
    g.add_argument("--h2", type=float, help="2nd harmonic as a fraction of the amplitude")
    g.add_argument("--h2-phase-deg", type=float)
    g.add_argument("--rekick-period-s", type=float)
    g.add_argument("--rekick-duration-s", type=float)
    g.add_argument("--fixed-angles-deg", type=_floats, help="x,y,z angles of the axes that do not swing")
    g.add_argument("--axis-order", help="table axes outer to inner (default zyx)")
    g = ap.add_argument_group("table errors in their physical form (all off by default)")
    g.add_argument("--base-tilt-deg", type=float, help="the table's base tilted by this much ...")
    g.add_argument("--base-tilt-azimuth-deg", type=float, help="... about the horizontal axis at this azimuth")
    g.add_argument("--nonorth-inner-arcsec", type=float, help="inner (x) axis tilted toward the middle (y) axis")
    g.add_argument("--nonorth-middle-arcsec", type=float, help="middle (y) axis tilted toward the outer (z) axis")
    g.add_argument("--eccentricity-um", type=float, help="encoder disk eccentricity (um) ...")
    g.add_argument("--eccentricity-radius-mm", type=float, help="... at the read head's radius (mm)")
    g.add_argument("--eccentricity-phase-deg", type=float)
    g.add_argument("--eccentricity-axes", help="axes whose encoders are eccentric (default xyz)")
    g.add_argument("--compliance-fn-hz", type=float, help="encoder-to-fixture spring-damper: natural frequency")
    g.add_argument("--compliance-zeta", type=float, help="... and damping ratio (0 < zeta < 1)")
    g.add_argument("--servo-unbalance-arcsec", type=float, help="servo deflection by an unbalance, eps sin(theta+phi)")
    g.add_argument("--servo-unbalance-phase-deg", type=float)
    g.add_argument("--servo-corner-hz", type=float, help="the loop's first-order disturbance response (0: static)")
    g.add_argument("--table-drop-per-mille", type=float, help="table rows lost at random")
    g.add_argument("--table-harmonics-ppm", type=_floats,
                   help="h2,h3: 2nd and 3rd harmonics of the table's motion, ppm of the fundamental at 10 deg")
    g.add_argument("--table-harmonic-phases-deg", type=_floats,
                   help="p2,p3: their phases from the fundamental's positive peak (default 0,0)")
    g.add_argument("--encoder-cyclic-arcsec", type=_floats, help="s,c: s sin(2 pi theta / 10 deg) + c cos(..)")
    g = ap.add_argument_group("site")
    g.add_argument("--latitude-deg", type=float)
    g.add_argument("--heading-deg", type=float, help="azimuth of the table's x axis at zero")
    g.add_argument("--z-up", action="store_true", default=None,
                   help="the table's z axis points up at zero angles (heading 90: east-north-up)")
    g.add_argument("--declare-frame", help='write bench.imu_frame, e.g. "NED", "ENU", "RFU:30"')
    g = ap.add_argument_group("delays (ms)")
    g.add_argument("--imu-delay-ms", type=float)
    g.add_argument("--table-read-delay-ms", type=float)
    g.add_argument("--board-delay-ms", type=float)
    g = ap.add_argument_group("gyro")
    g.add_argument("--fine-hz", type=float)
    g.add_argument("--gyro-sign", type=_floats, help="1 or 3 values of +1/-1 (x,y,z)")
    g.add_argument("--bias-deg-h", type=_floats, help="1 or 3 values")
    g.add_argument("--bias-step-deg-h", type=_floats, help="1 or 3 values")
    g.add_argument("--bias-step-time-s", type=float)
    g.add_argument("--arw", "--arw-deg-sqrt-h", dest="arw_deg_sqrt_h", type=float)
    g.add_argument("--pulse-arcsec", type=float)
    g.add_argument("--imu-period-ms", type=float)
    g.add_argument("--imu-clock-ppm", type=float)
    g.add_argument("--gyro-stamp-jitter-us", type=float)
    g.add_argument("--clock-rate-ppm-gyro", type=float)
    g.add_argument("--rate-output", choices=["frame_average", "sample_at_stamp"])
    g.add_argument("--rate-lsb-deg-s", type=float)
    g.add_argument("--sample-hold-ms", type=float)
    g.add_argument("--scale-factor-ppm", type=float)
    g.add_argument("--sf-asymmetry-ieee-ppm", type=float, help="(K+ - K-) / Kbar, IEEE Std 528")
    g.add_argument("--sf-nonlinearity-ieee-ppm", type=float,
                   help="IEEE Std 528 nonlinearity over +-100 deg/s (least-squares line, fraction of full scale)")
    g.add_argument("--bias-drift-deg-h-per-min", type=float)
    g.add_argument("--drop-per-mille", type=float, help="IMU frames lost at random (lost_before column)")
    g.add_argument("--bias-instability-deg-h", type=float, help="Gauss-Markov bias, 1 sigma ...")
    g.add_argument("--bias-correlation-s", type=float, help="... and its correlation time")
    g.add_argument("--misalignment-urad", type=_floats, help="six: m_xy,m_xz,m_yx,m_yz,m_zx,m_zy")
    g.add_argument("--mount-rpy-arcsec", type=_floats, help="IMU mount rotated by roll,pitch,yaw")
    g.add_argument("--g-sens-deg-h-g", type=_floats, help="1 value, or 3 (each gyro its own)")
    g.add_argument("--lag-tau-ms", type=float)
    g.add_argument("--second-order-fn-hz", type=float, help="resonant rate filter: natural frequency (0: off)")
    g.add_argument("--second-order-zeta", type=float, help="... and damping ratio (0 < zeta < 1)")
    g.add_argument("--register-period-ms", type=float, help="pulse register updated every (0: continuous)")
    g.add_argument("--register-offset-ms", type=float, help="time from its last update to a frame's end")
    g.add_argument("--register-clock-ppm", type=float, help="its clock against the frame clock")
    g.add_argument("--boxcar-ms", type=float, help="moving average of the rate before the frame")
    g.add_argument("--latency-p2", type=float, help="probability of the latency's second mode")
    g.add_argument("--latency-delta-us", type=float, help="second mode's extra latency")
    g.add_argument("--latency-sigma-us", type=float, help="rms within either mode")
    g.add_argument("--latency-dwell-s", type=float, help="mean dwell in mode 2 (0: white, drawn per frame)")
    g.add_argument("--rrw", "--rrw-deg-h-sqrt-h", dest="rrw_deg_h_sqrt_h", type=float, help="rate random walk")
    g.add_argument("--flicker-deg-h", type=float, help="flicker bias coefficient B")
    g.add_argument("--flicker-tau-range-s", type=_floats, help="low,high correlation times of its processes")
    g = ap.add_argument_group("table")
    g.add_argument("--table-period-ms", type=float)
    g.add_argument("--encoder-arcsec", type=float)
    g.add_argument("--encoder-noise-arcsec", type=float)
    g = ap.add_argument_group("stamps and output")
    g.add_argument("--timing", choices=["commensurate", "incommensurate"])
    g.add_argument("--nonround-ppm", type=float)
    g.add_argument("--stamp-quantum-us", type=float)
    g.add_argument("--axes-out", choices=["all", "swing"])
    g.add_argument("--meta-minimal", action="store_true", default=None,
                   help="metadata test points with only the axis (frequency and amplitude unknown)")
    g.add_argument("--declare-gyro-sign", action="store_true", default=None,
                   help='write bench.gyro_sign {"x": -1} for the axes given -1 in --gyro-sign')
    g.add_argument("--float-format")
    return ap


_SEG_KEYS = {"axis": "axis", "freq_hz": "freq_hz", "amp_deg": "amp_deg", "duration_s": "duration_s",
             "start_phase_deg": "start_phase_deg", "centre_deg": "centre_deg"}


def params_from_args(a):
    p = case_params(a.case) if a.case else default_params()
    if a.segments_json:
        p["segments"] = json.loads(a.segments_json)
    for k in _SEG_KEYS:
        v = getattr(a, k)
        if v is not None:
            for s in p["segments"]:
                s[k] = v
    skip = set(_SEG_KEYS) | {"out", "overwrite", "case", "list_cases", "segments_json"}
    for k, v in vars(a).items():
        if k in skip or v is None:
            continue
        if k not in p:
            raise SystemExit("internal: option %s has no parameter" % k)
        p[k] = v
    return p


def main(argv=None):
    a = build_parser().parse_args(argv)
    if a.list_cases:
        for name, c in CASES.items():
            print("%-24s %s (expected verdict: %s)" % (name, c["description"], c["expected_verdict"]))
        return 0
    if not a.out:
        print("refgen.py: --out DIR is required", file=sys.stderr)
        return 2
    try:
        p = params_from_args(a)
        t = time.perf_counter()
        res = generate(p)
        t_gen = time.perf_counter() - t
        tr = write_dir(res, a.out, a.overwrite)
        t_all = time.perf_counter() - t
    except ValueError as e:
        print("refgen.py: %s" % e, file=sys.stderr)
        return 2
    print("wrote %s: %d table rows, %d gyro rows; true lag %.6g ms (IMU delay %.6g ms); "
          "%.2f s (model %.2f s)" % (a.out, tr["rows"]["table"], tr["rows"]["gyro"], tr["true_lag_ms"],
                                     tr["imu_delay_ms"], t_all, t_gen))
    return 0


if __name__ == "__main__":
    sys.exit(main())
