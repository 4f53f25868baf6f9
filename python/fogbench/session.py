"""Reading a fogbench session file (.fbs): docs/sessions.md, "File layout".

The checks and their words follow the C++ reader, SessionReader in
core/session/session_file.cpp; which stored result is shown follows
newestUsable() in core/session/stored_result.cpp. A message names the file
as it was given, like the C++ reader's.
"""

import fcntl
import json
import math
import os
import sqlite3
import stat
import urllib.parse
from dataclasses import dataclass, field

import numpy as np

APPLICATION_ID = 0x464F4742  # "FOGB": PRAGMA application_id of a session
SCHEMA_VERSION = 6  # the newest layout read (PRAGMA user_version)
SAMPLES_PER_BLOCK = 65536  # at most this many records per table_block/imu_block row
MAX_TEST_POINT_INDEX = 0xFFFF  # the board numbers test points with 16 bits
READER_BUSY_TIMEOUT_S = 5.0  # as the C++ reader: a recorder may be checkpointing

# Sample records, packed little-endian (docs/sessions.md, table_block/imu_block).
TABLE_RECORD = np.dtype([("time_s", "<f8"), ("x", "<f8"), ("y", "<f8"), ("z", "<f8")])
IMU_RECORD = np.dtype([("time_s", "<f8"), ("x", "<f8"), ("y", "<f8"), ("z", "<f8"),
                       ("temperature_c", "<f8"), ("lost_before", "<u4")])
assert TABLE_RECORD.itemsize == 32 and IMU_RECORD.itemsize == 44

_FNV_OFFSET = 0xCBF29CE484222325
_FNV_PRIME = 0x100000001B3
_MASK64 = 0xFFFFFFFFFFFFFFFF

# The metadata columns metadata_fnv1a covers, in order (kMetadataColumns).
_METADATA_COLUMNS = ["operator", "imu_model", "imu_serial", "source", "software_version", "created_utc", "notes",
                     "table_read_delay_ms", "table_read_delay_std_ms", "board_delay_ms", "board_delay_std_ms",
                     "latitude_deg", "pulse_equivalent_deg", "counter_hz", "counter_bits", "test_plan_json", "state",
                     "incomplete_reason", "finished_utc"]
_METADATA_COLUMNS_V4 = ["gyro_sign_x", "gyro_sign_y", "gyro_sign_z", "import_json"]
_METADATA_COLUMNS_V5 = ["imu_frame"]
_METADATA_COLUMNS_V6 = ["lot", "bench_id"]  # the production lot, the bench (station) id
# sqlite3_column_type() codes, which the metadata checksum covers.
_SQLITE_TYPE = {"integer": 1, "real": 2, "text": 3, "blob": 4, "null": 5}


class FogbenchError(Exception):
    """A file that is not a readable fogbench session; str() is the C++ reader's refusal."""


@dataclass
class TestPoint:
    """One decoded test point (a row of `test_point` and its sample blocks).

    index: the point's index in the plan, 0-based (the CSV export's
    `test_point` column is index + 1). axis: "x", "y" or "z", the swung axis.
    frequency_hz, amplitude_deg: the plan's nominal values.
    table_time_s, gyro_time_s: seconds on the sampling board's counter from
    the stream's first frame. table_angle_deg: the table's angle on `axis`
    (deg). gyro_increment_deg: the gyro's angle increment on `axis` over the
    frame ending at gyro_time_s (deg), as recorded: a gyro sign of -1 in the
    bench constants is applied by the analysis, not here.
    table: every table record (fields time_s, x, y, z in deg);
    imu: every IMU record (time_s, x, y, z increments in deg, temperature_c,
    lost_before = IMU frames lost just before it).
    """
    index: int
    axis: str
    frequency_hz: float
    amplitude_deg: float
    table_time_s: np.ndarray
    table_angle_deg: np.ndarray
    gyro_time_s: np.ndarray
    gyro_increment_deg: np.ndarray
    table: np.ndarray = field(repr=False)
    imu: np.ndarray = field(repr=False)


@dataclass
class Session:
    """A session file's content.

    metadata: the `session` row (who, bench constants in ms / deg / Hz, the
    plan as parsed JSON under "test_plan", state) plus "schema_version",
    "being_recorded" (a recorder holds the file now) and "incomplete_reason"
    as the C++ reader words it ("" for a complete session).
    shown_result: the stored result every fogbench view shows (the latest
    intact one), or None when no stored result is intact; a dict with
    "number" (1-based among the file's results), "of", "id", "created_utc",
    "damaged_results", "verdict", "verdict_reasons", "imu_delay_limit_ms",
    "constants" (the settings' bench constants), "points" (per point: index,
    verdict, reasons, lag_ms, lag_std_ms, imu_delay_ms, imu_delay_std_ms; 1
    sigma; NaN where the row states none), and the parsed "settings" and
    "report" (docs/report.md).
    decoded: the `decoded` row (counter, pulse equivalent, stream health).
    test_points: the decoded test points in recording order.
    """
    path: str
    metadata: dict
    shown_result: dict
    decoded: dict
    test_points: list


def fnv1a64(data, h=_FNV_OFFSET):
    """FNV-1a 64 of bytes (continued from h): the checksum of every stored blob."""
    p, m = _FNV_PRIME, _MASK64
    for b in data:
        h = ((h ^ b) * p) & m
    return h


def _signed(h):
    """The uint64 hash as SQLite stores it (a signed 64-bit integer)."""
    return h - (1 << 64) if h >= (1 << 63) else h


def _text(v):
    """Text as read with text_factory=bytes; stray non-UTF-8 bytes replaced."""
    return v.decode("utf-8", errors="replace") if isinstance(v, bytes) else v


def _session_damage(path):
    """The C++ sessionDamage(): a session whose SQLite header or first page is lost."""
    with open(path, "rb") as f:
        head = f.read(64 * 1024)
    if b"CREATE TABLE raw_chunk" in head and b"CREATE TABLE session" in head:
        return "header"
    page = 4096
    size = os.path.getsize(path)
    pages = size >= 2 * page and size % page == 0 and len(head) > page and head[page] in (0x0D, 0x05)
    if pages and b'"rest_between_s"' in head and b'"points"' in head:
        return "first page"
    return None


def _damaged_session_message(path, damage):
    if damage == "first page":
        return (f"'{path}' is a fogbench session whose first page (the SQLite header and the list of its tables, "
                "4 KiB) is damaged; it is not analysed as a raw stream (the stream inside is cut into database "
                "pages). Restore it from a backup")
    return (f"'{path}' is a fogbench session whose SQLite header (its first 100 bytes) is damaged; it is not "
            "analysed as a raw stream. Restore it from a backup, or repair a copy: printf 'SQLite format 3\\0' | "
            "dd of=COPY.fbs conv=notrunc (when only the header's first bytes were hit, the copy opens again)")


def _is_being_recorded(path):
    """A recorder holds an exclusive flock() from create() until finish()."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_CLOEXEC)
    except OSError:
        return False
    try:
        fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
        return False
    except BlockingIOError:
        return True
    except OSError:
        return False
    finally:
        os.close(fd)


def _check_header(path):
    """The first 100 bytes, before SQLite sees the file (C++ readHeader/checkHeader).

    Returns (user_version, truncated message or "", truncated but a -wal may hold the rest)."""
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise FogbenchError(f"cannot open session '{path}': no such file; check the path") from None
    if stat.S_ISDIR(st.st_mode):
        raise FogbenchError(f"'{path}' is a folder, not a fogbench session file")
    if not stat.S_ISREG(st.st_mode):
        # A FIFO would block the read and a device never ends (C++ checkRegularFile).
        kind = ("a FIFO (named pipe)" if stat.S_ISFIFO(st.st_mode) else
                "a device" if stat.S_ISCHR(st.st_mode) or stat.S_ISBLK(st.st_mode) else
                "a socket" if stat.S_ISSOCK(st.st_mode) else "not a regular file")
        link = f" (a link to {os.readlink(path)})" if os.path.islink(path) else ""
        raise FogbenchError(f"{path}{link} is {kind}, not a fogbench session file: only regular files are read (a "
                            "pipe or a device may never end); copy the data into a file first")
    if st.st_size == 0:
        raise FogbenchError(f"'{path}' is empty (0 bytes), not a fogbench session; it was never written")
    try:
        with open(path, "rb") as f:
            h = f.read(100)
    except OSError:
        raise FogbenchError(f"cannot read '{path}'; check its permissions") from None
    if len(h) < 100 or not h.startswith(b"SQLite format 3\0"):
        damage = _session_damage(path)
        if damage:
            raise FogbenchError(_damaged_session_message(path, damage))
        raise FogbenchError(f"'{path}' is not a fogbench session (not an SQLite database)")
    be32 = lambda at: int.from_bytes(h[at:at + 4], "big")
    app_id = be32(68)
    if app_id != APPLICATION_ID:
        raise FogbenchError(f"'{path}' is an SQLite database but not a fogbench session (application_id "
                            f"0x{app_id:08X})")
    user_version = be32(60)
    # Truncation: the header's page count is trusted when its "version valid
    # for" equals the change counter (SQLite file format, 1.3.7).
    page_size = (h[16] << 8) | h[17]
    if page_size == 1:
        page_size = 65536
    pages = be32(28)
    truncated, with_wal = "", False
    if pages != 0 and be32(24) == be32(92) and st.st_size < pages * page_size:
        truncated = (f"'{path}' is truncated: it holds {st.st_size} of its {pages * page_size} bytes; copy it "
                     "again from the original or restore a backup")
        try:
            with_wal = os.path.getsize(path + "-wal") > 32 + 24
        except OSError:
            with_wal = False
        # A live recording's main file lags its -wal: SQLite decides then.
        with_wal = with_wal or _is_being_recorded(path)
        if not with_wal:
            raise FogbenchError(truncated)
    if user_version > SCHEMA_VERSION:
        raise FogbenchError(_newer_schema(path, user_version))
    return truncated, with_wal


def _newer_schema(path, version):
    return (f"'{path}' was written by a newer fogbench (schema {version}; this one reads up to "
            f"{SCHEMA_VERSION}): update fogbench")


class _Reader:
    def __init__(self, path):
        self.path = path
        truncated, truncated_with_wal = _check_header(path)
        self.live = _is_being_recorded(path)
        uri = "file:" + urllib.parse.quote(os.path.abspath(path)) + "?mode=ro"
        try:
            self.db = sqlite3.connect(uri, uri=True, timeout=READER_BUSY_TIMEOUT_S)
        except sqlite3.Error as e:
            raise FogbenchError(f"cannot open session '{path}': {e}; check its permissions") from None
        self.db.text_factory = bytes  # text checksummed as stored; decoded by _text()
        if truncated_with_wal:
            row = self._one("PRAGMA quick_check(1)", what=None)
            if not row or row[0] != b"ok":
                raise FogbenchError(truncated + " (its -wal does not hold the missing pages)")
        # Authoritative identity and version, through SQLite (the header may
        # predate changes still in the WAL).
        try:
            app = self.db.execute("PRAGMA application_id").fetchone()[0]
        except sqlite3.Error as e:
            raise FogbenchError(f"cannot read session '{path}': {e}; the file is damaged, restore it from a "
                                "backup") from None
        if app != APPLICATION_ID:
            raise FogbenchError(f"'{path}' is not a fogbench session")
        try:
            self.version = self.db.execute("PRAGMA user_version").fetchone()[0]
        except sqlite3.Error as e:
            raise FogbenchError(f"cannot read session '{path}': {e}") from None
        if self.version > SCHEMA_VERSION:
            raise FogbenchError(_newer_schema(path, self.version))
        if self.version < 1:
            raise FogbenchError(f"'{path}' has no session schema (user_version {self.version}); it was not "
                                "written completely")

    def read_error(self, what, e):
        return FogbenchError(f"cannot read session '{self.path}' ({what}): {e}; the file is damaged, restore it "
                             "from a backup")

    def _all(self, sql, args=(), what="reading its metadata"):
        try:
            return self.db.execute(sql, args).fetchall()
        except sqlite3.Error as e:
            raise self.read_error(what, e) from None

    def _one(self, sql, args=(), what="reading its metadata"):
        rows = self._all(sql, args, what) if what else self.db.execute(sql, args).fetchall()
        return rows[0] if rows else None

    def metadata(self):
        columns = _METADATA_COLUMNS + (_METADATA_COLUMNS_V4 if self.version >= 4 else []) + \
            (_METADATA_COLUMNS_V5 if self.version >= 5 else []) + \
            (_METADATA_COLUMNS_V6 if self.version >= 6 else [])
        if self.version >= 2:
            stored = self._one("SELECT metadata_fnv1a FROM session WHERE id = 1")
            if stored is None:
                raise self.read_error("reading its metadata", "no metadata row")
            if stored[0] is not None and self._metadata_checksum(columns) != stored[0]:
                raise FogbenchError(f"session '{self.path}': its metadata (who, bench constants, plan, state) fails "
                                    "its checksum; the file is damaged, restore it from a backup")
        row = self._one("SELECT " + ", ".join(columns) + " FROM session WHERE id = 1")
        if row is None:
            raise FogbenchError(f"session '{self.path}' has no metadata row; the file is damaged")
        meta = {c: _text(v) for c, v in zip(columns, row)}
        try:
            meta["test_plan"] = json.loads(meta["test_plan_json"])
        except (ValueError, TypeError) as e:
            raise FogbenchError(f"session '{self.path}': its stored test plan is unreadable ({e})") from None
        if self.version < 4:  # older schemas have no signs: +1, what their analyses used
            meta.update(gyro_sign_x=1, gyro_sign_y=1, gyro_sign_z=1, import_json="")
        if self.version < 5:
            meta["imu_frame"] = ""
        if self.version < 6:  # older schemas state neither
            meta.update(lot="", bench_id="")
        meta["schema_version"] = self.version
        meta["being_recorded"] = self.live
        state = meta["state"]
        if state == "complete":
            meta["incomplete_reason"] = ""
        elif state != "incomplete":
            meta["incomplete_reason"] = (
                "being recorded now: the session is not finished yet" if self.live else
                "recording was interrupted: the recording program stopped without finishing the session "
                "(crash, kill, power cut or a full disk); everything committed until then is kept")
        return meta

    def _metadata_checksum(self, columns):
        """FNV-1a 64 over each column's SQLite type byte and value: integer and
        real as 8 little-endian bytes, text as its byte length (8 bytes) and bytes."""
        sql = "SELECT " + ", ".join(f"typeof({c}), {c}" for c in columns) + " FROM session WHERE id = 1"
        row = self._one(sql)
        h = _FNV_OFFSET
        for kind, value in zip(row[0::2], row[1::2]):
            kind = _text(kind)
            code = _SQLITE_TYPE[kind]
            h = fnv1a64(bytes([code]), h)
            if kind == "integer":
                h = fnv1a64(int(value).to_bytes(8, "little", signed=True), h)
            elif kind == "real":
                h = fnv1a64(np.float64(value).tobytes(), h)
            elif kind != "null":
                data = value if isinstance(value, bytes) else str(value).encode()
                h = fnv1a64(len(data).to_bytes(8, "little") + data, h)
        return _signed(h)

    def check_raw_stream(self):
        """Every raw chunk in sequence, without a gap, passing its checksum (C++ checkRawStream)."""
        at = 0
        rows = self._all("SELECT seq, byte_offset, data, data_fnv1a FROM raw_chunk ORDER BY seq",
                         what="reading the raw stream")
        for expect, (seq, offset, data, checksum) in enumerate(rows):
            if seq != expect or offset != at:
                raise FogbenchError(f"session '{self.path}': the raw stream has a gap at byte {at} (chunk {expect}); "
                                    "the file is damaged")
            if _signed(fnv1a64(data)) != checksum:
                raise FogbenchError(f"session '{self.path}': raw stream chunk {expect} (bytes {at}..{at + len(data)}) "
                                    "fails its checksum; the file is damaged, restore it from a backup")
            at += len(data)

    def damaged(self, what):
        return FogbenchError(f"session '{self.path}': decoded samples are damaged ({what}); analyse the raw stream "
                             "instead")

    def decoded(self, meta):
        what = "reading the decoded samples"
        if self._one("SELECT count(*) FROM decoded", what=what)[0] == 0:
            # Samples are stored when a recording finishes; before that (or
            # after a crash) the C++ reader decodes the raw stream. This
            # reader has no decoder of the board protocol.
            why = "it is being recorded now" if self.live else "its recording did not finish"
            raise FogbenchError(f"session '{self.path}' holds no decoded samples yet ({why}): the Python reader "
                                "does not decode the raw stream; read_session(path, samples=False) reads its "
                                "metadata and results, fogbench-cli export --csv its samples")
        names = ["counter_hz", "counter_bits", "pulse_equivalent_deg", "table_frames", "imu_frames", "status_frames",
                 "checksum_failures", "bytes_skipped", "lost_frames", "duplicate_frames", "out_of_order_frames",
                 "counter_wraps"]
        row = self._one("SELECT " + ", ".join(names) + " FROM decoded WHERE id = 1", what=what)
        if row is None:
            raise self.read_error(what, "no decoded row 1")
        dec = dict(zip(names, row))
        hz, bits, pulse = float(dec["counter_hz"]), int(dec["counter_bits"]), float(dec["pulse_equivalent_deg"])
        if not math.isfinite(hz) or hz < 0 or bits < 0 or bits > 64 or not math.isfinite(pulse):
            raise self.damaged(f"counter {hz:f} Hz, {bits} bits")  # std::to_string's %f

        points = []
        rows = self._all("SELECT position, point_index, axis, nominal_frequency_hz, nominal_amplitude_deg, "
                         "table_samples, imu_samples FROM test_point ORDER BY position", what=what)
        for pos, index, axis, freq, amp, n_table, n_imu in rows:
            if index < 0 or index >= MAX_TEST_POINT_INDEX:
                raise self.damaged(f"test point index {index} outside 0..{MAX_TEST_POINT_INDEX - 1}")
            axis = _text(axis)
            if axis not in ("x", "y", "z", "X", "Y", "Z"):
                raise self.damaged(f"axis '{axis}'")
            if not (math.isfinite(freq) and math.isfinite(amp)):
                raise self.damaged(f"nominal frequency or amplitude of test point {pos} is not a number")
            if n_table < 0 or n_imu < 0:
                raise self.damaged("negative sample count")
            table = self._blocks("table_block", pos, n_table, TABLE_RECORD, "a table")
            imu = self._blocks("imu_block", pos, n_imu, IMU_RECORD, "an IMU")
            points.append((int(index), axis.lower(), float(freq), float(amp), table, imu))
        # Sessions stored before the builder resolved the pulse equivalent kept
        # raw pulse counts (pulse_equivalent_deg 0): the bench constant turns
        # them into degrees, as the C++ reader does.
        if any(len(p[5]) for p in points) and not pulse > 0.0:
            bench = meta["pulse_equivalent_deg"]
            if not (bench is not None and math.isfinite(bench) and bench > 0.0):
                raise FogbenchError(f"session '{self.path}': the stream does not state its gyro pulse equivalent "
                                    "(degrees per pulse): give --pulse-equivalent-deg or set it in the bench "
                                    "constants")
            for p in points:
                for a in "xyz":
                    p[5][a] *= bench
        out = []
        for index, axis, freq, amp, table, imu in points:
            out.append(TestPoint(index=index, axis=axis, frequency_hz=freq, amplitude_deg=amp,
                                 table_time_s=table["time_s"].copy(), table_angle_deg=table[axis].copy(),
                                 gyro_time_s=imu["time_s"].copy(), gyro_increment_deg=imu[axis].copy(),
                                 table=table, imu=imu))
        return dec, out

    def _blocks(self, name, pos, expected, record, what):
        """One test point's blocks, each checked against its size and checksum."""
        rows = self._all(f"SELECT samples, data, data_fnv1a FROM {name} WHERE test_point = ? ORDER BY block",
                         (pos,), what="reading the decoded samples")
        parts, total = [], 0
        for stored, data, checksum in rows:
            if stored < 0 or stored > SAMPLES_PER_BLOCK:
                raise self.damaged(f"{what} block claims {stored} samples (at most {SAMPLES_PER_BLOCK} per block)")
            if not isinstance(data, bytes) or len(data) != stored * record.itemsize or \
                    _signed(fnv1a64(data)) != checksum:
                raise self.damaged(f"{what} block fails its size or checksum check")
            total += stored
            if total > expected:
                break
            parts.append(np.frombuffer(data, dtype=record))
        if total != expected:
            held = "more" if total > expected else str(total)
            raise self.damaged(f"sample count of test point {pos}: it says {expected} {what.split(' ', 1)[1]} "
                               f"samples, its blocks hold {held}")
        return np.concatenate(parts) if parts else np.zeros(0, dtype=record)

    def shown_result(self):
        """The newest usable stored result (intact, settings and report JSON objects)."""
        what = "reading the results"
        sql = ("SELECT id, created_utc, settings_json, report_json, fnv1a FROM result ORDER BY id"
               if self.version >= 2 else
               "SELECT id, created_utc, settings_json, report_json, NULL FROM result ORDER BY id")
        rows = self._all(sql, what=what)
        usable = []
        for rid, created, settings, report, checksum in rows:
            if checksum is not None:
                h = _FNV_OFFSET
                for t in (created, settings, report):  # each followed by a NUL byte
                    h = fnv1a64((t or b"") + b"\0", h)
                if _signed(h) != checksum:
                    continue
            try:
                settings, report = json.loads(_text(settings)), json.loads(_text(report))
            except (ValueError, TypeError):
                continue
            if isinstance(settings, dict) and isinstance(report, dict):
                usable.append((rid, _text(created), settings, report))
        if not usable:
            return None
        rid, created, settings, report = usable[-1]
        number = 1 + [r[0] for r in rows].index(rid)
        reported = report.get("constants") if isinstance(report.get("constants"), dict) else {}
        keys = ["table_read_delay_ms", "table_read_delay_std_ms", "board_delay_ms", "board_delay_std_ms",
                "pulse_equivalent_deg", "gain_tolerance"]
        constants = {k: settings.get(k, reported.get(k)) for k in keys}
        constants["gyro_sign"] = settings.get("gyro_sign")
        limit = report.get("imu_delay_limit_ms", settings.get("imu_delay_limit_ms"))
        nan = float("nan")
        points = [{"index": tp["index"], "verdict": tp.get("verdict", ""),
                   "reasons": tp.get("verdict_reasons", []),
                   "lag_ms": tp.get("lag_ms", nan), "lag_std_ms": tp.get("lag_std_ms", nan),
                   "imu_delay_ms": tp.get("imu_delay_ms", nan), "imu_delay_std_ms": tp.get("imu_delay_std_ms", nan)}
                  for tp in report.get("test_points", []) if isinstance(tp, dict) and isinstance(tp.get("index"), int)]
        return {"number": number, "of": len(rows), "id": rid, "created_utc": created,
                "damaged_results": len(rows) - len(usable),
                "verdict": report.get("verdict", ""), "verdict_reasons": report.get("verdict_reasons", []),
                "data_verdict": report.get("data_verdict", ""), "imu_delay_limit_ms": limit,
                "constants": constants, "points": points, "settings": settings, "report": report}


def read_session(path, samples=True, check_raw_stream=True):
    """Reads a fogbench session file (.fbs) and returns a Session.

    The file is opened read-only (an SQLite `mode=ro` URI), so a session that
    is being recorded can be read: what the recorder committed so far is
    read, and the recorder is never disturbed.

    Checked as the C++ reader does, and refused with its words (FogbenchError):
    what the file is (a regular, non-empty SQLite file with fogbench's
    application_id, not truncated, a schema this reader knows), the
    metadata row's FNV-1a 64 checksum, every sample block's size and FNV-1a 64
    checksum and the sample counts, and every stored result's checksum (a
    result that fails it is skipped, like in every fogbench view).
    check_raw_stream: also check every raw stream chunk's checksum and that
    the chunks leave no gap (the C++ analysis says so in a note and goes on;
    this reader refuses the file). False saves about half the time.
    samples=False: the metadata and the shown result only (test_points is
    empty, decoded None; nothing of the samples is read or checked): the
    way to look at a session being recorded, whose samples are stored only
    when the recording finishes.
    """
    path = os.fspath(path)
    r = _Reader(path)
    try:
        meta = r.metadata()
        decoded, points = r.decoded(meta) if samples else (None, [])
        if samples and check_raw_stream:
            r.check_raw_stream()
        shown = r.shown_result()
    finally:
        r.db.close()
    return Session(path=path, metadata=meta, shown_result=shown, decoded=decoded, test_points=points)
