#pragma once
// The table controller's remote protocol (docs/table-control.md): SCPI /
// IEEE 488.2 style text lines, one command or query per line, terminated by
// "\n" (a "\r" before it is ignored). This file is the one parser and
// formatter both ends use: the remote driver (client) and the table emulator
// (server). Pure functions; no I/O; nothing throws.
//
// A line:   HEADER[?] [ARG[,ARG...]]
//   HEADER: keywords separated by ':' ("AXIS:X:SWING", "SYST:ERR"), or a
//           common command ("*IDN"); case-insensitive; each keyword may be
//           given in its short form (the upper-case part of "SYSTem", "ERRor").
//   '?' right after the header makes it a query (a reply line follows).
//   ARGs: decimal numbers or bare words, comma-separated, blanks ignored.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/status.h"

namespace fog::table::scpi {

inline constexpr std::size_t kMaxLineBytes = 256;

// SCPI standard error numbers (IEEE 488.2 / SCPI-99) and the device's own.
enum ErrorCode : int {
  kNoError = 0,
  kCommandError = -100,
  kSyntaxError = -102,
  kParameterNotAllowed = -108,
  kMissingParameter = -109,
  kUndefinedHeader = -113,
  kExecutionError = -200,
  kSettingsConflict = -221,
  kDataOutOfRange = -222,
  kQueueOverflow = -350,
  // Device-specific (positive).
  kInterlockOpen = 201,
  kEmergencyStop = 202,
  kHeartbeatLost = 203,
  kRefusedByController = 204,  // the emulator's injected refusal
};

struct Command {
  std::vector<std::string> keywords;  // upper-cased as given: {"AXIS", "X", "SWING"}; {"*IDN"}
  bool query = false;
  std::vector<std::string> args;      // trimmed, as given
  std::string text;                   // the line without its terminator
};

// Ok, or kCorruptData saying why (empty, too long, control characters, an
// empty keyword, text after a query mark without a blank, ...).
Result<Command> parseLine(std::string_view line);

// Whether `given` (upper-cased) names `keyword` written as in SCPI manuals,
// "SYSTem": the long form or its short form (the upper-case letters), whole.
bool keywordIs(std::string_view given, std::string_view keyword);
// Whether the command's keywords are exactly `pattern` ("SYSTem:ERRor"; a
// '#' in the pattern matches an axis letter X, Y or Z). Optional trailing
// keywords in [] ("SYSTem:ERRor[:NEXT]") may be left out.
bool matches(const Command& command, std::string_view pattern);

// A number argument: finite, the whole text a decimal number.
Result<double> number(std::string_view text);

// "-113,\"Undefined header\"" (quotes inside the text doubled).
std::string formatError(int code, std::string_view text);
struct ErrorEntry {
  int code = 0;
  std::string text;
};
// Parses a SYST:ERR? reply; kCorruptData when it is not one.
Result<ErrorEntry> parseError(std::string_view reply);
// The standard text of an error number ("Undefined header").
const char* standardErrorText(int code);

// Comma-separated fields of a reply, trimmed.
std::vector<std::string> splitFields(std::string_view reply);
// Exactly `count` numbers; kCorruptData naming the reply otherwise.
Result<std::vector<double>> numbers(std::string_view reply, std::size_t count);

// %.9g: enough digits to round-trip the values the protocol carries.
std::string formatNumber(double v);

}  // namespace fog::table::scpi
