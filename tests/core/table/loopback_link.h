#pragma once
// The emulated controller behind an in-process transport: every line written
// is handled at once (table time `now`), replies are read back. Shared by the
// remote driver's tests and the plan runner's end-to-end tests.

#include <string>
#include <vector>

#include "core/table/emulated_table.h"
#include "core/table/transport.h"

namespace fog::table::testing {

class ServerLink : public ByteTransport {
 public:
  ServerLink(TableServer& server, double& now) : server_(server), now_(now) {}
  std::string description() const override { return "loopback"; }
  Status write(std::string_view bytes) override {
    if (closed) return ioError("table link loopback lost: closed");
    pending_.append(bytes);
    for (auto nl = pending_.find('\n'); nl != std::string::npos; nl = pending_.find('\n')) {
      const std::string line = pending_.substr(0, nl);
      pending_.erase(0, nl + 1);
      sent.push_back(line);
      if (auto reply = server_.handleLine(line, now_, now_)) replies_ += *reply + "\n";
    }
    return Status::ok();
  }
  Result<std::size_t> read(std::string& out, std::chrono::milliseconds) override {
    if (closed) return ioError("table link loopback lost: closed");
    const std::size_t n = replies_.size();
    out += replies_;
    replies_.clear();
    return n;
  }
  std::vector<std::string> sent;
  bool closed = false;

 private:
  TableServer& server_;
  double& now_;
  std::string pending_, replies_;
};

}  // namespace fog::table::testing
