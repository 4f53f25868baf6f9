#pragma once
// The delay breakdown of a shown result as CSV: the Results table's rows with
// each point's shown verdict beside its numbers, so a refused delay never
// leaves without its mark. Written by the GUI's "Delay table (CSV)" and by
// `fogbench-cli export --csv` (delays.csv); docs/formats.md. Qt-free.

#include <string>

#include "core/analysis/delay_analysis.h"
#include "core/session/shown_verdict.h"

namespace fog::session {

// Comment lines ('#': what it holds, the source, the result's verdict and
// limit), then the header
//   test_point,axis,frequency_hz,quantity,value_ms,std_ms,verdict,vouched,reason
// and five rows a test point (measured_lag, table_read_delay, imu_delay,
// processing_board_delay, gyro_delay), in the Results table's order. verdict
// is the point's shown verdict (pass, fail, invalid, incomplete; "" for
// none), vouched false when its delays are refused, reason its verdict's
// reasons (RFC 4180 quoting). Numbers in io::formatDouble's shortest form.
std::string delayBreakdownCsv(const analysis::DelayReport& report, const ShownVerdict& verdict,
                              const std::string& source);

// `text` on one line (a line break becomes a space), for a '#' comment line.
std::string oneLine(std::string text);

// One CSV field (RFC 4180): quoted when it holds a comma, quote or line break
// (a line break becomes a space).
std::string csvField(const std::string& text);

// One CSV field of text a person typed or a file states (an IMU serial, a
// lot, an operator, a path): csvField, and when it starts with '=', '+',
// '-', '@', a tab or a carriage return, a single quote before it, so that a
// spreadsheet shows it as text and never runs it as a formula ("=HYPERLINK(…)"
// shows as "'=HYPERLINK(…)"). Numbers are never written through it: a
// negative delay stays a number.
std::string csvTextField(const std::string& text);

}  // namespace fog::session
