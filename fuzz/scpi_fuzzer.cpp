// libFuzzer entry for the table controller's remote protocol
// (docs/table-control.md): arbitrary bytes as protocol lines.
//
// Each line goes through the one parser both ends use (scpi::parseLine, the
// header matching, number parsing, the reply helpers) and then to the
// emulated controller (TableServer::handleLine), as a host or a damaged link
// would send it. Every call must return a value or a Status with a message,
// never crash or hang; a parsed line keeps the parser's promises (no empty
// keyword, nothing over 256 bytes); an error entry the formatter writes reads
// back the same (CR and LF as blanks: a reply is one line); a number the formatter writes reads back within its digits.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/table/emulated_table.h"
#include "core/table/scpi.h"

namespace {

using namespace fog::table;

void check(bool ok) {
  if (!ok) std::abort();
}

constexpr const char* kPatterns[] = {"*IDN",          "*RST",         "*CLS",          "*OPC",
                                     "SYSTem:ERRor[:NEXT]", "SYSTem:STATus", "SYSTem:HEARTbeat",
                                     "SYSTem:HEARTbeat:TIMeout", "SYSTem:ESTOP", "SYSTem:ESTOP:RESet", "STOP",
                                     "AXIS:#:SWING",  "AXIS:#:START", "AXIS:#:STOP",   "AXIS:#:POSition",
                                     "AXIS:#:STATe",  "AXIS:#:LIMits"};

void parseOne(std::string_view line) {
  auto parsed = scpi::parseLine(line);
  if (!parsed) {
    check(!parsed.status().message().empty());
  } else {
    const scpi::Command& c = *parsed;
    check(!c.keywords.empty());
    for (const auto& k : c.keywords) check(!k.empty());
    check(c.text.size() <= scpi::kMaxLineBytes);
    for (const char* p : kPatterns) (void)scpi::matches(c, p);
    for (const auto& a : c.args) {
      auto v = scpi::number(a);
      if (v) {
        check(std::isfinite(*v));
        // What the formatter writes, the parser reads back (9 digits).
        auto back = scpi::number(scpi::formatNumber(*v));
        check(back.isOk() && std::abs(*back - *v) <= 1e-8 * std::max(1.0, std::abs(*v)));
      } else {
        check(!v.status().message().empty());
      }
    }
  }
  // The same text as a reply.
  (void)scpi::splitFields(line);
  for (std::size_t n = 1; n <= 5; ++n) {
    auto v = scpi::numbers(line, n);
    check(v.isOk() ? v->size() == n : !v.status().message().empty());
  }
  if (auto e = scpi::parseError(line); e.isOk()) {
    // A reply is one line: the formatter writes CR and LF as blanks.
    std::string oneLine = e->text;
    for (char& ch : oneLine)
      if (ch == '\r' || ch == '\n') ch = ' ';
    auto again = scpi::parseError(scpi::formatError(e->code, e->text));
    check(again.isOk() && again->code == e->code && again->text == oneLine);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  EmulatedTable table;
  TableServer server(table);
  double t = 0.0;
  std::size_t start = 0;
  while (start <= input.size()) {
    std::size_t end = input.find('\n', start);
    if (end == std::string_view::npos) end = input.size();
    const std::string_view line = input.substr(start, end - start);
    parseOne(line);
    t += 0.01;
    auto reply = server.handleLine(std::string(line), t, t);
    if (reply) check(reply->find('\n') == std::string::npos);
    server.tick(t, t);
    start = end + 1;
  }
  // The error queue stays bounded and readable whatever came before.
  for (int i = 0; i < 20; ++i) {
    auto reply = server.handleLine("SYST:ERR?", t, t);
    check(reply.has_value() && scpi::parseError(*reply).isOk());
  }
  return 0;
}
