#include "app/cli_arguments.h"

#include <cmath>
#include <cstdlib>

namespace fog::app {

Result<CliArguments> CliArguments::parse(const std::vector<std::string>& args, const std::set<std::string>& flags) {
  CliArguments out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) != 0 || a.size() == 2) {
      out.positionals_.push_back(a);
      continue;
    }
    std::string name = a.substr(2), value;
    const auto eq = name.find('=');
    if (eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    } else if (flags.count(name)) {
      out.flags_.insert(name);
      continue;
    } else {
      if (i + 1 >= args.size()) return invalidArgument("option --" + name + " needs a value");
      value = args[++i];
    }
    if (flags.count(name)) return invalidArgument("option --" + name + " takes no value");
    out.values_[name] = value;
  }
  return out;
}

bool CliArguments::flag(const std::string& name) {
  used_.insert(name);
  return flags_.count(name) > 0;
}

std::optional<std::string> CliArguments::text(const std::string& name) {
  used_.insert(name);
  auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

Result<double> CliArguments::number(const std::string& name, double fallback) {
  auto t = text(name);
  if (!t) return fallback;
  char* end = nullptr;
  const double v = std::strtod(t->c_str(), &end);
  if (t->empty() || *end != '\0' || !std::isfinite(v))
    return invalidArgument("option --" + name + " needs a number, got '" + *t + "'");
  return v;
}

Status CliArguments::checkAllUsed() const {
  for (const auto& [name, value] : values_)
    if (!used_.count(name)) return invalidArgument("unknown option --" + name + " (see fogbench-cli help)");
  for (const auto& name : flags_)
    if (!used_.count(name)) return invalidArgument("unknown option --" + name + " (see fogbench-cli help)");
  return Status::ok();
}

}  // namespace fog::app
