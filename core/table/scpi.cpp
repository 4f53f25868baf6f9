#include "core/table/scpi.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace fog::table::scpi {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string shown(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 60)) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u >= 0x7f) {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02X", u);
      out += b;
    } else {
      out += c;
    }
  }
  if (s.size() > 60) out += "...";
  return out;
}

}  // namespace

Result<Command> parseLine(std::string_view line) {
  if (!line.empty() && line.back() == '\n') line.remove_suffix(1);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line.size() > kMaxLineBytes)
    return corruptData("line of " + std::to_string(line.size()) + " bytes is longer than " +
                       std::to_string(kMaxLineBytes));
  for (char c : line) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\t') || u >= 0x7f) return corruptData("line '" + shown(line) + "' holds a control or non-ASCII byte");
  }
  Command cmd;
  cmd.text = std::string(line);
  std::string_view rest = trim(line);
  if (rest.empty()) return corruptData("empty line");
  const auto blank = rest.find_first_of(" \t");
  std::string_view header = rest.substr(0, blank);
  std::string_view args = blank == std::string_view::npos ? std::string_view() : trim(rest.substr(blank));
  if (!header.empty() && header.back() == '?') {
    cmd.query = true;
    header.remove_suffix(1);
  }
  if (header.find('?') != std::string_view::npos) return corruptData("misplaced '?' in '" + shown(line) + "'");
  if (!header.empty() && header.front() == ':') header.remove_prefix(1);  // SCPI allows a leading colon
  if (header.empty()) return corruptData("no header in '" + shown(line) + "'");
  std::size_t start = 0;
  for (;;) {
    const auto colon = header.find(':', start);
    const auto kw = header.substr(start, colon == std::string_view::npos ? std::string_view::npos : colon - start);
    if (kw.empty()) return corruptData("empty keyword in '" + shown(line) + "'");
    for (std::size_t i = 0; i < kw.size(); ++i) {
      const char c = kw[i];
      const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '_' || (c == '*' && i == 0 && start == 0);
      if (!ok) return corruptData("bad character '" + shown(std::string_view(&c, 1)) + "' in header '" + shown(header) + "'");
    }
    cmd.keywords.push_back(upper(kw));
    if (colon == std::string_view::npos) break;
    start = colon + 1;
  }
  if (!args.empty()) {
    std::size_t from = 0;
    for (;;) {
      const auto comma = args.find(',', from);
      auto a = trim(args.substr(from, comma == std::string_view::npos ? std::string_view::npos : comma - from));
      if (a.empty()) return corruptData("empty argument in '" + shown(line) + "'");
      cmd.args.emplace_back(a);
      if (comma == std::string_view::npos) break;
      from = comma + 1;
    }
  }
  return cmd;
}

bool keywordIs(std::string_view given, std::string_view keyword) {
  std::string shortForm;
  for (char c : keyword)
    if (std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '*')
      shortForm += c;
  const std::string g = upper(given);
  return g == upper(keyword) || g == shortForm;
}

bool matches(const Command& command, std::string_view patternText) {
  // "ERRor[:NEXT]" is written "ERRor:[NEXT]" for splitting.
  std::string normal(patternText);
  for (auto at = normal.find("[:"); at != std::string::npos; at = normal.find("[:")) normal.replace(at, 2, ":[");
  const std::string_view pattern(normal);
  std::vector<std::pair<std::string, bool>> parts;  // keyword, optional
  std::size_t start = 0;
  for (;;) {
    const auto colon = pattern.find(':', start);
    auto kw = pattern.substr(start, colon == std::string_view::npos ? std::string_view::npos : colon - start);
    bool optional = false;
    if (!kw.empty() && kw.front() == '[') {
      optional = true;
      kw.remove_prefix(1);
    }
    if (!kw.empty() && kw.back() == ']') kw.remove_suffix(1);
    parts.emplace_back(std::string(kw), optional);
    if (colon == std::string_view::npos) break;
    start = colon + 1;
  }
  std::size_t i = 0;
  for (const auto& [kw, optional] : parts) {
    if (i >= command.keywords.size()) {
      if (optional) continue;
      return false;
    }
    const std::string& given = command.keywords[i];
    const bool ok = kw == "#" ? (given == "X" || given == "Y" || given == "Z") : keywordIs(given, kw);
    if (!ok) {
      if (optional) continue;
      return false;
    }
    ++i;
  }
  return i == command.keywords.size();
}

Result<double> number(std::string_view text) {
  const std::string s(trim(text));
  if (s.empty()) return corruptData("empty number");
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(v))
    return corruptData("'" + shown(s) + "' is not a finite decimal number");
  // strtod also reads hex and "inf"; the protocol is decimal only.
  for (char c : s)
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E'))
      return corruptData("'" + shown(s) + "' is not a decimal number");
  return v;
}

std::string formatError(int code, std::string_view text) {
  std::string out = std::to_string(code) + ",\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

Result<ErrorEntry> parseError(std::string_view reply) {
  reply = trim(reply);
  const auto comma = reply.find(',');
  if (comma == std::string_view::npos) return corruptData("error reply '" + shown(reply) + "' is not CODE,\"TEXT\"");
  auto code = number(reply.substr(0, comma));
  if (!code || *code != std::floor(*code) || std::abs(*code) > 32767)
    return corruptData("error reply '" + shown(reply) + "' has no integer code");
  auto text = trim(reply.substr(comma + 1));
  if (text.size() < 2 || text.front() != '"' || text.back() != '"')
    return corruptData("error reply '" + shown(reply) + "' has no quoted text");
  ErrorEntry e;
  e.code = static_cast<int>(*code);
  text = text.substr(1, text.size() - 2);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '"' && i + 1 < text.size() && text[i + 1] == '"') ++i;
    e.text += text[i];
  }
  return e;
}

const char* standardErrorText(int code) {
  switch (code) {
    case kNoError: return "No error";
    case kCommandError: return "Command error";
    case kSyntaxError: return "Syntax error";
    case kParameterNotAllowed: return "Parameter not allowed";
    case kMissingParameter: return "Missing parameter";
    case kUndefinedHeader: return "Undefined header";
    case kExecutionError: return "Execution error";
    case kSettingsConflict: return "Settings conflict";
    case kDataOutOfRange: return "Data out of range";
    case kQueueOverflow: return "Queue overflow";
    case kInterlockOpen: return "Interlock open";
    case kEmergencyStop: return "Emergency stop engaged";
    case kHeartbeatLost: return "Heartbeat lost";
    case kRefusedByController: return "Refused by the controller";
  }
  return "Error";
}

std::vector<std::string> splitFields(std::string_view reply) {
  std::vector<std::string> out;
  std::size_t from = 0;
  for (;;) {
    const auto comma = reply.find(',', from);
    out.emplace_back(trim(reply.substr(from, comma == std::string_view::npos ? std::string_view::npos : comma - from)));
    if (comma == std::string_view::npos) break;
    from = comma + 1;
  }
  return out;
}

Result<std::vector<double>> numbers(std::string_view reply, std::size_t count) {
  const auto fields = splitFields(reply);
  if (fields.size() != count)
    return corruptData("reply '" + shown(reply) + "' has " + std::to_string(fields.size()) + " fields; expected " +
                       std::to_string(count) + " numbers");
  std::vector<double> out;
  for (const auto& f : fields) {
    auto v = number(f);
    if (!v) return corruptData("reply '" + shown(reply) + "': " + v.status().message());
    out.push_back(*v);
  }
  return out;
}

std::string formatNumber(double v) {
  char b[48];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

}  // namespace fog::table::scpi
