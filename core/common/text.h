#pragma once
// Text that enters the bench from outside (command-line arguments, file
// names, session files written by other tools, serial ports) is not always
// UTF-8: an operator name typed on a Latin-1 terminal, a file name from an old
// Windows share. JSON output requires UTF-8, so such text is converted where
// it enters (docs/reliability.md, issue 15).

#include <string>
#include <string_view>

namespace fog {

// True when `text` is well-formed UTF-8 (no overlong forms, no surrogates,
// nothing above U+10FFFF).
bool isValidUtf8(std::string_view text);

// `text` unchanged when it is valid UTF-8; otherwise every byte that is not
// part of a well-formed UTF-8 sequence is read as Latin-1 (ISO 8859-1) and
// re-encoded, so "M\xFCller" becomes "Müller". Never fails.
std::string toValidUtf8(std::string_view text);

// For a terminal: control characters (ESC, BEL, CR, ... but newline and tab)
// that text from a file could carry are shown as "\xNN" instead of acting on
// the terminal (an escape sequence in an operator name or a CSV value must
// not move the cursor or retitle the window). Valid UTF-8 otherwise kept.
std::string forTerminal(std::string_view text);

// A number in a message, as printf writes it: `format` takes one double
// ("%g": 0.8, 1e+10; "%.2g"), fixed() a number of decimals ("0.25").
std::string printfNumber(const char* format, double v);
std::string fixed(double v, int decimals);

}  // namespace fog
