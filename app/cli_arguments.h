#pragma once
// A small command-line parser: "--name value", "--flag" and positionals.
// Every option a command reads is marked as used; anything left unread is an
// error, so a typo never silently falls back to a default.

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace fog::app {

class CliArguments {
 public:
  // flags: option names that take no value.
  static Result<CliArguments> parse(const std::vector<std::string>& args, const std::set<std::string>& flags);

  bool flag(const std::string& name);
  std::optional<std::string> text(const std::string& name);
  // Missing: fallback; present but not a finite number: an error.
  Result<double> number(const std::string& name, double fallback);
  // Whether an option was given at all (does not mark it used).
  bool has(const std::string& name) const { return values_.count(name) > 0 || flags_.count(name) > 0; }
  const std::vector<std::string>& positionals() const { return positionals_; }
  // An error naming the first option nobody asked for, if any.
  Status checkAllUsed() const;

 private:
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_;
  std::set<std::string> used_;
  std::vector<std::string> positionals_;
};

}  // namespace fog::app
