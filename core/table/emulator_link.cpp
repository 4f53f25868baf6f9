#include "core/table/emulator_link.h"

#include <chrono>

#include "core/table/remote_table.h"

namespace fog::table {

namespace {

// Every line written is handled at once by the emulator at the current table
// time; its replies are read back.
class EmulatorLink : public ByteTransport {
 public:
  explicit EmulatorLink(const EmulatorLinkOptions& options)
      : table_(options.table), server_(table_), speed_(options.speed > 0.0 ? options.speed : 1.0) {}
  std::string description() const override { return "emulated"; }
  Status write(std::string_view bytes) override {
    pending_.append(bytes);
    const double wall = wallS();
    server_.tick(wall * speed_, wall);
    for (auto nl = pending_.find('\n'); nl != std::string::npos; nl = pending_.find('\n')) {
      const std::string line = pending_.substr(0, nl);
      pending_.erase(0, nl + 1);
      if (auto reply = server_.handleLine(line, wall * speed_, wall)) replies_ += *reply + "\n";
    }
    return Status::ok();
  }
  Result<std::size_t> read(std::string& out, std::chrono::milliseconds) override {
    const std::size_t n = replies_.size();
    out += replies_;
    replies_.clear();
    return n;
  }

 private:
  double wallS() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

  EmulatedTable table_;
  TableServer server_;
  double speed_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::string pending_, replies_;
};

}  // namespace

Result<std::unique_ptr<TableController>> connectEmulatedTable(EmulatorLinkOptions options) {
  RemoteOptions remote;
  remote.replyTimeout = std::chrono::milliseconds(200);
  remote.heartbeatTimeoutS = options.heartbeatTimeoutS;
  FOG_ASSIGN_OR_RETURN(auto table, RemoteTable::connect(std::make_unique<EmulatorLink>(options), remote));
  return std::unique_ptr<TableController>(std::move(table));
}

}  // namespace fog::table
