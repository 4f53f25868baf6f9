"""fogbench.read_session against sessions the C++ code wrote (CTest: python.read_session).

    /usr/bin/python3 tests/python/test_read_session.py --cli build/release/app/fogbench-cli

Every expected value comes from fogbench-cli on the same file: its CSV export
(samples), `sessions --json` (the shown result) and `analyze` (the refusal
of a damaged file, on stderr). The CSV prints shortest round-trip decimals
(core/io/csv_export.cpp, Text::num: std::to_chars), so Python's float() of a
CSV field is the stored double and the comparisons are exact, no tolerance.
"""

import argparse
import csv
import json
import os
import shutil
import sqlite3
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
import fogbench  # noqa: E402

CLI = None  # set from --cli in main

# Two axes, two frequencies: a plan the presets do not have (short, fast to record).
TWO_AXES_PLAN = {"rest_between_s": 0.5, "points": [
    {"axis": "x", "frequency_hz": 1, "amplitude_deg": 3, "duration_s": 4, "settle_s": 1},
    {"axis": "y", "frequency_hz": 2, "amplitude_deg": 2, "duration_s": 3, "settle_s": 1, "start_phase_deg": 90}]}


def cli(*args, check=True):
    p = subprocess.run([CLI, *args], capture_output=True, text=True)
    if check and p.returncode != 0:
        raise AssertionError(f"fogbench-cli {' '.join(args)} exited {p.returncode}: {p.stderr}")
    return p


def read_csv(path):
    """Rows of a fogbench CSV (its '#' comment lines skipped), grouped by test_point."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    groups = {}
    for r in rows:
        groups.setdefault(int(r["test_point"]), []).append(r)
    return groups


def column(rows, name):
    return np.array([float(r[name]) for r in rows], dtype=np.float64)


class ReadSession(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="fogbench-py-")
        cls.quick = os.path.join(cls.dir, "quick.fbs")
        cli("run", "--preset", "quick", "--seed", "3", "--out", cls.quick, "--lot", "L-2026-11", "--bench-id", "bench 3")
        plan = os.path.join(cls.dir, "two_axes.json")
        with open(plan, "w") as f:
            json.dump(TWO_AXES_PLAN, f)
        cls.two = os.path.join(cls.dir, "two_axes.fbs")
        cli("run", "--plan", plan, "--seed", "7", "--out", cls.two)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def copy(self, source, name):
        """A copy in a folder of its own (sessions --json lists a folder)."""
        d = tempfile.mkdtemp(dir=self.dir)
        path = os.path.join(d, name)
        shutil.copyfile(source, path)
        return path

    def refusal(self, path):
        with self.assertRaises(fogbench.FogbenchError) as e:
            fogbench.read_session(path)
        return str(e.exception)

    def cli_refusal(self, path):
        """The C++ refusal: stderr of `export --csv`, which opens only a session
        (`analyze` reads a file that is not SQLite as a raw board stream)."""
        p = cli("export", path, "--csv", os.path.join(self.dir, "refused-export"), check=False)
        self.assertEqual(p.returncode, 2, p.stderr)
        return p.stderr.strip()

    # --- samples ---------------------------------------------------------

    def assert_samples_equal_csv(self, path, axes):
        out = os.path.join(self.dir, os.path.basename(path) + ".csv")
        cli("export", path, "--csv", out)
        table, gyro = read_csv(os.path.join(out, "table.csv")), read_csv(os.path.join(out, "gyro.csv"))
        s = fogbench.read_session(path)
        self.assertEqual([p.axis for p in s.test_points], axes)
        self.assertEqual(sorted(table), [p.index + 1 for p in s.test_points])
        for p in s.test_points:
            t, g = table[p.index + 1], gyro[p.index + 1]
            self.assertGreater(len(t), 1000)
            # Exact: the CSV's decimals are the doubles' shortest round trip.
            np.testing.assert_array_equal(p.table_time_s, column(t, "time_s"))
            np.testing.assert_array_equal(p.table_angle_deg, column(t, p.axis + "_deg"))
            np.testing.assert_array_equal(p.gyro_time_s, column(g, "time_s"))
            np.testing.assert_array_equal(p.gyro_increment_deg, column(g, p.axis + "_inc_deg"))
            for a in "xyz":
                np.testing.assert_array_equal(p.table[a], column(t, a + "_deg"))
                np.testing.assert_array_equal(p.imu[a], column(g, a + "_inc_deg"))
            np.testing.assert_array_equal(p.imu["temperature_c"], column(g, "temperature_c"))
            np.testing.assert_array_equal(p.imu["lost_before"], column(g, "lost_before"))
            # The swing is really there (not an all-zero column compared with itself).
            self.assertGreater(np.ptp(p.table_angle_deg), 1.0)
        with open(os.path.join(out, "metadata.json")) as f:
            meta = json.load(f)
        for key in ("operator", "lot", "bench_id", "source", "software_version", "created_utc", "notes"):
            self.assertEqual(s.metadata[key], meta[key], key)
        for key in ("table_read_delay_ms", "board_delay_ms", "latitude_deg", "pulse_equivalent_deg", "counter_hz"):
            self.assertEqual(s.metadata[key], meta["bench"][key], key)
        return s

    def test_quick_session_samples_equal_the_csv_export(self):
        s = self.assert_samples_equal_csv(self.quick, ["x"])
        self.assertEqual(s.metadata["state"], "complete")
        self.assertFalse(s.metadata["being_recorded"])
        self.assertEqual(s.metadata["schema_version"], 6)
        self.assertEqual((s.metadata["lot"], s.metadata["bench_id"]), ("L-2026-11", "bench 3"))

    def test_two_axes_session_samples_equal_the_csv_export(self):
        s = self.assert_samples_equal_csv(self.two, ["x", "y"])
        self.assertEqual([p.frequency_hz for p in s.test_points], [1.0, 2.0])

    # --- the shown result ------------------------------------------------

    def assert_shown_as_cli(self, path):
        listed = json.loads(cli("sessions", os.path.dirname(path), "--json").stdout)["sessions"]
        self.assertEqual(len(listed), 1)
        row = listed[0]
        shown = fogbench.read_session(path).shown_result
        self.assertEqual(shown["number"], row["shown_result"])
        self.assertEqual(shown["of"], row["results"])
        self.assertEqual(shown["damaged_results"], row["damaged_results"])
        self.assertEqual(shown["verdict"], row["verdict"])
        self.assertEqual(len(shown["points"]), len(row["test_points"]))
        for mine, theirs in zip(shown["points"], row["test_points"]):
            for key in ("index", "verdict", "lag_ms", "imu_delay_ms", "imu_delay_std_ms"):
                self.assertEqual(mine[key], theirs[key], key)
        return shown

    def test_shown_result_is_what_the_cli_shows(self):
        for path in (self.quick, self.two):
            shown = self.assert_shown_as_cli(self.copy(path, "s.fbs"))
            self.assertEqual(shown["number"], 1)
            self.assertIn(shown["verdict"], ("pass", "fail", "invalid"))
            self.assertEqual(shown["imu_delay_limit_ms"], shown["report"]["imu_delay_limit_ms"])

    def test_the_latest_intact_result_is_shown(self):
        path = self.copy(self.quick, "s.fbs")
        cli("analyze", path, "--limit-ms", "0.3")  # result 2: a FAIL against a tighter limit
        shown = self.assert_shown_as_cli(path)
        self.assertEqual((shown["number"], shown["of"], shown["verdict"]), (2, 2, "fail"))
        # Result 2's report changed behind its checksum: result 1 is shown again.
        with sqlite3.connect(path) as db:
            db.execute("UPDATE result SET report_json = replace(report_json, '\"fail\"', '\"pass\"') WHERE id = 2")
        db.close()
        shown = self.assert_shown_as_cli(path)
        self.assertEqual((shown["number"], shown["damaged_results"], shown["verdict"]), (1, 1, "pass"))

    # --- damaged files: the C++ reader's words ----------------------------

    def flip_inside(self, path, blob):
        """Flips one byte of `blob` where it lies in the file (not through SQLite)."""
        with open(path, "rb") as f:
            data = bytearray(f.read())
        at = data.find(blob[:64])
        self.assertGreater(at, 0)
        self.assertEqual(data.find(blob[:64], at + 1), -1)
        data[at + 40] ^= 0x01
        with open(path, "wb") as f:
            f.write(data)

    def first_blob(self, path, sql):
        db = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
        blob = db.execute(sql).fetchone()[0]
        db.close()
        return blob

    def test_a_flipped_byte_in_a_sample_block_is_refused(self):
        for table, what in (("imu_block", "an IMU"), ("table_block", "a table")):
            path = self.copy(self.quick, "s.fbs")
            self.flip_inside(path, self.first_blob(path, f"SELECT data FROM {table} ORDER BY rowid"))
            message = self.refusal(path)
            damage = f"decoded samples are damaged ({what} block fails its size or checksum check)"
            self.assertEqual(message, f"session '{path}': {damage}; analyse the raw stream instead")
            # The C++ analysis says the same damage and analyses the raw stream.
            p = cli("analyze", path, "--no-store")
            self.assertIn(f"is a damaged session ({damage}); analysed from the raw board stream", p.stderr)

    def test_a_flipped_byte_in_the_raw_stream_is_refused(self):
        path = self.copy(self.quick, "s.fbs")
        self.flip_inside(path, self.first_blob(path, "SELECT data FROM raw_chunk WHERE seq = 0"))
        message = self.refusal(path)
        prefix = f"session '{path}': "
        self.assertTrue(message.startswith(prefix + "raw stream chunk 0 (bytes 0.."), message)
        # The C++ analysis goes on from the stored samples and says the same damage.
        p = cli("analyze", path, "--no-store")
        self.assertIn("(" + message[len(prefix):] + ")", p.stderr)
        # Without the raw stream check the samples, which are intact, read.
        self.assertEqual(len(fogbench.read_session(path, check_raw_stream=False).test_points), 1)

    def test_damaged_files_are_refused_with_the_cli_words(self):
        def damaged(name, change):
            path = self.copy(self.quick, name)
            change(path)
            return path

        def write_at(offset, data):
            def change(path):
                with open(path, "r+b") as f:
                    f.seek(offset)
                    f.write(data)
            return change

        def metadata(path):  # a changed notes field, its checksum left as it was
            with sqlite3.connect(path) as db:
                db.execute("UPDATE session SET notes = 'changed afterwards' WHERE id = 1")
            db.close()

        def lot(path):  # one byte of the lot changed, its checksum left as it was
            with sqlite3.connect(path) as db:
                db.execute("UPDATE session SET lot = 'L-2026-12' WHERE id = 1")
            db.close()

        cases = {
            "lot": damaged("l.fbs", lot),
            "truncated": damaged("t.fbs", lambda p: os.truncate(p, os.path.getsize(p) // 2)),
            "metadata": damaged("m.fbs", metadata),
            "application id": damaged("a.fbs", write_at(68, b"\0\0\0\1")),
            "newer schema": damaged("n.fbs", write_at(60, b"\0\0\0\x09")),
            "header": damaged("h.fbs", write_at(0, b"\0" * 16)),
            "empty": damaged("e.fbs", lambda p: os.truncate(p, 0)),
        }
        text = os.path.join(tempfile.mkdtemp(dir=self.dir), "plan.fbs")
        with open(text, "w") as f:
            f.write("not a session, a text file long enough to have a header of a hundred bytes\n" * 3)
        cases["not SQLite"] = text
        expected_start = {"lot": "its metadata (who, bench constants, plan, state) fails its checksum",
                          "truncated": "is truncated", "metadata": "its metadata (who, bench constants, plan, "
                          "state) fails its checksum", "application id": "is an SQLite database but not a fogbench",
                          "newer schema": "was written by a newer fogbench (schema 9", "header":
                          "is a fogbench session whose SQLite header", "empty": "is empty (0 bytes)",
                          "not SQLite": "is not a fogbench session (not an SQLite database)"}
        for case, path in cases.items():
            with self.subTest(case):
                message = self.refusal(path)
                self.assertIn(expected_start[case], message)
                self.assertEqual("fogbench-cli: " + message, self.cli_refusal(path))
                if case not in ("empty", "not SQLite"):  # which analyze reads as raw streams
                    p = cli("analyze", path, "--no-store", check=False)
                    self.assertEqual((p.returncode, p.stderr.strip()), (2, "fogbench-cli: " + message))

    def test_a_fifo_a_device_a_folder_and_a_missing_file_are_refused(self):
        fifo = os.path.join(tempfile.mkdtemp(dir=self.dir), "fifo.fbs")
        os.mkfifo(fifo)
        self.assertEqual("fogbench-cli: " + self.refusal(fifo), self.cli_refusal(fifo))  # not opened: no block
        link = os.path.join(tempfile.mkdtemp(dir=self.dir), "zero.fbs")
        os.symlink("/dev/zero", link)
        self.assertEqual("fogbench-cli: " + self.refusal(link), self.cli_refusal(link))
        self.assertIn("(a link to /dev/zero) is a device", self.refusal(link))
        self.assertEqual(self.refusal(self.dir), f"'{self.dir}' is a folder, not a fogbench session file")
        missing = os.path.join(self.dir, "missing.fbs")
        self.assertEqual(self.refusal(missing), f"cannot open session '{missing}': no such file; check the path")

    # --- a session being recorded ----------------------------------------

    def test_a_session_being_recorded_is_read_without_disturbing_it(self):
        path = os.path.join(self.dir, "live.fbs")
        # quick is 25 s of data; at 5x real time the recording lasts ~5 s.
        recorder = subprocess.Popen([CLI, "run", "--preset", "quick", "--seed", "4", "--speed", "5", "--out", path],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        try:
            seen, deadline = None, time.monotonic() + 30.0  # the loop ends when the recorder does
            while time.monotonic() < deadline and recorder.poll() is None:
                try:
                    s = fogbench.read_session(path, samples=False)
                except fogbench.FogbenchError:
                    time.sleep(0.05)  # not created yet
                    continue
                if s.metadata["being_recorded"]:
                    seen = s
                    break
                time.sleep(0.05)
            self.assertIsNotNone(seen, "the recording was never seen in progress")
            self.assertEqual(seen.metadata["state"], "recording")
            self.assertTrue(seen.metadata["incomplete_reason"].startswith("being recorded now"))
            self.assertIsNone(seen.shown_result)
            if recorder.poll() is None:
                message = self.refusal(path)
                self.assertIn("holds no decoded samples yet (it is being recorded now)", message)
        finally:
            _, err = recorder.communicate(timeout=60)
        self.assertEqual(recorder.returncode, 0, err)
        s = fogbench.read_session(path)
        self.assertEqual(s.metadata["state"], "complete")
        self.assertEqual(s.shown_result["number"], 1)


def main():
    global CLI
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True, help="path of fogbench-cli")
    args, rest = parser.parse_known_args()
    CLI = os.path.abspath(args.cli)
    unittest.main(argv=[sys.argv[0], *rest], verbosity=2)


if __name__ == "__main__":
    main()
