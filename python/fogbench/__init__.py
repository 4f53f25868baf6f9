"""fogbench: read fogbench session files (.fbs) from Python.

Pure Python (the standard library's sqlite3) and numpy, no build step.
It follows the layout docs/sessions.md documents (schema 1..5) and checks a
file the way the C++ reader (core/session/session_file.cpp) does, refusing a
damaged one with the same words.

    import fogbench
    s = fogbench.read_session("S.fbs")
    s.metadata["operator"], s.shown_result["verdict"]
    for p in s.test_points:
        p.index, p.axis, p.frequency_hz, p.table_time_s, p.gyro_increment_deg
"""

from .session import FogbenchError, Session, TestPoint, read_session

__all__ = ["FogbenchError", "Session", "TestPoint", "read_session"]
