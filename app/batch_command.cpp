#include "app/batch_command.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <random>
#include <set>
#include <thread>

#include "app/catalog_command.h"
#include "app/cli_common.h"
#include "core/common/text.h"
#include "core/common/version.h"
#include "core/session/session_api.h"
#include "core/session/session_file.h"

namespace fog::app {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The constant options batch takes (those of `analyze`); the numeric ones
// are written into the header as numbers, so "0.30" and "0.3" are one setting.
const char* const kNumericConstants[] = {"read-delay-ms",  "read-delay-std-ms",    "board-delay-ms",
                                         "board-delay-std-ms", "pulse-equivalent-deg", "gain-tolerance"};
const char* const kTextConstants[] = {"gyro-sign", "imu-frame"};

std::string errnoText() { return std::strerror(errno); }

// Writes all of `text` at the end of `fd` and fsyncs it: a line is on the
// disk before the next file's work is counted as done.
Status appendDurably(int fd, const std::string& text, const std::string& path) {
  std::size_t at = 0;
  while (at < text.size()) {
    const ssize_t n = ::write(fd, text.data() + at, text.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return ioError("cannot write '" + path + "': " + errnoText());
    at += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) return ioError("cannot write '" + path + "' to the disk (fsync): " + errnoText());
  return Status::ok();
}

// The record's settings are these (exactly: the settings JSON keeps every
// double to the last bit).
bool sameSettings(const session::StoredResultRecord& r, const BenchConstants& c, double limitMs, double k) {
  return r.constants.tableReadDelayMs == c.tableReadDelayMs &&
         r.constants.tableReadDelayStdMs == c.tableReadDelayStdMs && r.constants.boardDelayMs == c.boardDelayMs &&
         r.constants.boardDelayStdMs == c.boardDelayStdMs &&
         r.constants.pulseEquivalentDeg == c.pulseEquivalentDeg &&
         r.constants.gainToleranceFraction == c.gainToleranceFraction && r.constants.gyroSign == c.gyroSign &&
         r.imuDelayLimitMs == limitMs && r.coverageK == k;
}

std::string newBatchId() {
  std::random_device rd;
  std::mt19937_64 g((static_cast<std::uint64_t>(rd()) << 32) ^ rd() ^
                    static_cast<std::uint64_t>(std::chrono::system_clock::now().time_since_epoch().count()));
  char id[17];
  std::snprintf(id, sizeof id, "%016llx", static_cast<unsigned long long>(g()));
  return id;
}

// OUT opened for appending, and what an earlier run of the same batch left.
struct BatchOutput {
  int fd = -1;
  std::string batchId;
  std::set<std::string> listed;  // the files OUT already has a line for
  bool resumed = false;
  std::string note;  // said on stderr: a partial last line discarded
};

Status refuseOut(const std::string& path, const std::string& why) {
  return invalidArgument("--jsonl '" + path + "' " + why + "; name another --jsonl or remove it");
}

// Creates OUT with its header, or reopens it to resume the same batch. OUT is
// locked (flock) for the whole batch: two batches never append to one file.
Result<BatchOutput> openBatchOutput(const std::string& path, const BatchSettings& settings) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return invalidArgument("--jsonl '" + path + "' is a folder; give a file name");
  if (fs::exists(path, ec) && session::isSqliteFile(path))
    return invalidArgument("--jsonl '" + path + "' is a session (or another database), never written by batch: "
                           "name another --jsonl");
  BatchOutput out;
  out.fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (out.fd < 0) return ioError("cannot open --jsonl '" + path + "': " + errnoText());
  auto closeWith = [&](Status s) -> Result<BatchOutput> {
    ::close(out.fd);
    return s;
  };
  if (::flock(out.fd, LOCK_EX | LOCK_NB) != 0)
    return closeWith(invalidArgument("--jsonl '" + path + "' is being written by another batch right now; wait for "
                                     "it to finish (then run this one again to resume) or name another --jsonl"));
  // Every header this writes starts so; a file that does not is someone
  // else's, refused after its first bytes (never read whole, never written).
  const std::string start = "{\"batch\":";
  auto startsLikeABatch = [&](const std::string& text) {
    const std::size_t n = std::min(text.size(), start.size());
    return text.compare(0, n, start, 0, n) == 0;
  };
  const Status foreign = refuseOut(path, "exists and is not the output of fogbench-cli batch (its first line is not "
                                         "a batch header)");
  std::string text;
  char buf[1 << 16];
  for (off_t at = 0;;) {
    const ssize_t n = ::pread(out.fd, buf, sizeof buf, at);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return closeWith(ioError("cannot read --jsonl '" + path + "': " + errnoText()));
    if (n == 0) break;
    text.append(buf, static_cast<std::size_t>(n));
    at += n;
    if (!startsLikeABatch(text)) return closeWith(foreign);
  }
  const std::size_t complete = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  const std::string partial = text.substr(complete);
  if (complete == 0) {
    // Nothing, or a header cut short by a kill (it starts like one): no line
    // of a file is lost by starting the batch anew.
    if (!partial.empty() && ::ftruncate(out.fd, 0) != 0)
      return closeWith(ioError("cannot truncate --jsonl '" + path + "': " + errnoText()));
    out.batchId = settings.batchId;
    const nlohmann::ordered_json header = {
        {"batch", 1},
        {"batch_id", out.batchId},
        {"settings", nlohmann::ordered_json::parse(settings.settingsJson().dump())},
        {"software_version", FOG_VERSION},
        {"started_utc", session::utcNow()}};
    if (auto s = appendDurably(out.fd, header.dump() + "\n", path); !s.isOk()) return closeWith(s);
    // The new file's name on the disk too (the folder's entry).
    const fs::path parent = fs::absolute(fs::path(path), ec).parent_path();
    if (int dfd = ::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dfd >= 0) {
      (void)::fsync(dfd);
      ::close(dfd);
    }
    return out;
  }
  // The header: the same batch (its settings), or refused.
  std::size_t lineStart = 0, lineNumber = 0;
  while (lineStart < complete) {
    const std::size_t end = text.find('\n', lineStart);
    const std::string line = text.substr(lineStart, end - lineStart);
    lineStart = end + 1;
    ++lineNumber;
    const json doc = json::parse(line, nullptr, false);
    auto has = [&](const char* key, json::value_t type) {
      return doc.is_object() && doc.contains(key) && doc.at(key).type() == type;
    };
    if (lineNumber == 1) {
      if (!has("batch", json::value_t::number_unsigned) || doc.at("batch") != 1 ||
          !has("settings", json::value_t::object) || !has("batch_id", json::value_t::string))
        return closeWith(foreign);
      if (doc.at("settings") != settings.settingsJson())
        return closeWith(invalidArgument("--jsonl '" + path + "' holds a batch with other settings (" +
                                         doc.at("settings").dump() + ", not " + settings.settingsJson().dump() +
                                         "); name another --jsonl or remove it"));
      out.batchId = doc.at("batch_id").get<std::string>();
      continue;
    }
    if (!has("path", json::value_t::string))
      return closeWith(refuseOut(path, "has a damaged line " + std::to_string(lineNumber) +
                                           " (not a batch line; only a last line cut short is discarded by itself)"));
    out.listed.insert(doc.at("path").get<std::string>());
  }
  out.resumed = true;
  if (!partial.empty()) {
    // A batch killed while writing a line: the line is discarded, and its
    // file (whose result may be stored) is done again (already_stored then).
    if (::ftruncate(out.fd, static_cast<off_t>(complete)) != 0 || ::fsync(out.fd) != 0)
      return closeWith(ioError("cannot truncate --jsonl '" + path + "' to its last complete line: " + errnoText()));
    out.note = "'" + path + "' ended in a line cut short (" + std::to_string(partial.size()) +
               " bytes: a batch stopped while writing it); discarded, that file is done again";
  }
  return out;
}

// Finds the *.fbs files under `dir`, recursively, sorted.
Status findSessions(const std::string& dir, std::vector<std::string>& files) {
  std::vector<std::string> found;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code fileEc;
    if (it->path().extension() == ".fbs" && it->is_regular_file(fileEc)) found.push_back(it->path().string());
  }
  if (ec) return ioError("cannot list '" + dir + "': " + ec.message());
  std::sort(found.begin(), found.end());
  files.insert(files.end(), found.begin(), found.end());
  return Status::ok();
}

// The one name of a file: absolute, symbolic links resolved, "." and ".."
// gone (as the catalog names it).
std::string canonicalPath(const std::string& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  if (ec) return path;
  const fs::path c = fs::weakly_canonical(absolute, ec);
  return ec ? absolute.lexically_normal().string() : c.string();
}

std::string durationText(double s) {
  char buf[48];
  if (s < 90) std::snprintf(buf, sizeof buf, "%.0f s", std::max(1.0, s));
  else if (s < 90 * 60) std::snprintf(buf, sizeof buf, "%.0f min", s / 60);
  else std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  return buf;
}

}  // namespace

json BatchSettings::settingsJson() const {
  nlohmann::json constants = nlohmann::json::object();
  for (const auto& [name, value] : constantOptions) {
    const bool numeric = std::find_if(std::begin(kNumericConstants), std::end(kNumericConstants),
                                      [&](const char* n) { return name == n; }) != std::end(kNumericConstants);
    constants[name] = numeric ? nlohmann::json(std::strtod(value.c_str(), nullptr)) : nlohmann::json(value);
  }
  return {{"constants", constants}, {"imu_delay_limit_ms", imuDelayLimitMs}, {"coverage_factor_k", coverageK}};
}

const char* batchStatusName(BatchLine::Status status) {
  switch (status) {
    case BatchLine::Status::kStored: return "stored";
    case BatchLine::Status::kAlreadyStored: return "already_stored";
    case BatchLine::Status::kRefused: break;
  }
  return "refused";
}

nlohmann::ordered_json BatchLine::toJson() const {
  nlohmann::ordered_json line = {{"path", toValidUtf8(path)}, {"status", batchStatusName(status)}};
  if (status != Status::kRefused) {
    line["result"] = result;
    line["verdict"] = session::shownVerdictName(verdict.verdict);
    if (verdict.verdict == session::ShownVerdictKind::kIncomplete)
      line["data_verdict"] = session::shownVerdictName(verdict.dataVerdict);
    line["points"] = nlohmann::ordered_json::array();
    for (const auto& p : verdict.points) {
      nlohmann::ordered_json point = {{"index", p.index}, {"verdict", session::shownVerdictName(p.verdict)}};
      // Only a vouched delay is written as a number (shown_verdict.h).
      if (p.vouched()) {
        point["imu_delay_ms"] = p.imuDelayMs;
        point["imu_delay_std_ms"] = p.imuDelayStdMs;
      } else {
        point["refusal"] = p.refusal();
      }
      line["points"].push_back(point);
    }
  }
  if (!error.empty()) line["error"] = toValidUtf8(error);
  if (!note.empty()) line["note"] = toValidUtf8(note);
  return line;
}

BatchLine batchOneFile(const std::string& path, const BatchSettings& settings) {
  BatchLine line;
  line.path = path;
  // The constants as `analyze` takes them: those given over the session's own.
  std::vector<std::string> given;
  for (const auto& [name, value] : settings.constantOptions) {
    given.push_back("--" + name);
    given.push_back(value);
  }
  auto options = CliArguments::parse(given, {});
  if (!options) {
    line.error = options.status().message();
    return line;
  }
  session::OpenOptions open = session::OpenOptions::session();  // a raw stream is no session to store into
  if (options->has("pulse-equivalent-deg")) {
    auto pulse = options->number("pulse-equivalent-deg", 0.0);
    if (pulse) open.pulseEquivalentDeg = *pulse;
  }
  auto opened = session::openSessionOrStream(path, open);
  if (!opened) {
    line.error = opened.status().message();
    return line;
  }
  line.note = opened->damageNote();
  // Never analysed half-recorded: its result would be a partial run's, and
  // the recorder holds the write lock anyway (analyseAndStore would not store).
  if (opened->beingRecorded) {
    line.error = "session '" + path + "' is being recorded right now; when the recording has finished, analyse it "
                 "with analyze or a batch with another --jsonl (this one lists it)";
    return line;
  }
  auto constants = readConstants(*options, opened->info.bench);
  if (!constants) {
    line.error = constants.status().message();
    return line;
  }
  // Stored by this batch before a kill took its line: listed, not stored twice.
  if (!opened->results.empty()) {
    const auto& newest = opened->results.back();
    if (newest.usable && newest.analysedBy == settings.producedBy() &&
        sameSettings(newest, *constants, settings.imuDelayLimitMs, settings.coverageK)) {
      line.status = BatchLine::Status::kAlreadyStored;
      line.result = static_cast<int>(opened->results.size());
      line.verdict = session::judgeShown(&newest, nullptr, opened->complete, opened->incompleteReason,
                                         settings.imuDelayLimitMs);
      return line;
    }
  }
  session::AnalysisSettings analysis;
  analysis.constants = *constants;
  analysis.imuDelayLimitMs = settings.imuDelayLimitMs;
  analysis.producedBy = settings.producedBy();
  analysis.coverageK = settings.coverageK;
  analysis.operatorName = settings.operatorName;
  analysis.command = settings.command;
  const auto made = session::analyseAndStore(*opened, analysis, true);
  if (!made.report) {
    line.error = made.report.status().message();
    return line;
  }
  if (!made.storeStatus.isOk() || !made.stored) {
    line.error = !made.storeStatus.isOk() ? made.storeStatus.message()
                 : made.notStored.empty() ? "the result was not stored"
                                          : made.notStored;
    return line;
  }
  line.status = BatchLine::Status::kStored;
  line.result = static_cast<int>(made.results.size());  // the new one is the last
  line.verdict = session::judgeShown(&made.results.back(), &*made.report, opened->complete,
                                     opened->incompleteReason, settings.imuDelayLimitMs);
  return line;
}

int batchCommand(CliArguments& args) {
  const auto outPath = args.text("jsonl");
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  auto jobs = args.number("jobs", std::min(cores, 8u));
  if (!jobs) return fail(jobs.status(), 2);
  BatchSettings settings;
  for (const char* name : kNumericConstants)
    if (auto v = args.text(name)) settings.constantOptions.emplace_back(name, *v);
  for (const char* name : kTextConstants)
    if (auto v = args.text(name)) settings.constantOptions.emplace_back(name, *v);
  // The constants given are checked once, before any file (their ranges,
  // their form); a session's own are checked with it.
  if (auto c = readConstants(args); !c) return fail(c.status(), 2);
  auto limit = readDelayLimit(args);
  if (!limit) return fail(limit.status(), 2);
  settings.imuDelayLimitMs = *limit;
  auto coverageK = readCoverageK(args);
  if (!coverageK) return fail(coverageK.status(), 2);
  settings.coverageK = *coverageK;
  settings.operatorName = toValidUtf8(args.text("operator").value_or(""));
  settings.command = auditCommandLine();
  const std::string catalogDb = args.text("db").value_or("");
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (!outPath)
    return fail(invalidArgument("batch needs --jsonl OUT.jsonl: the file that gets one line per session"), 2);
  if (!(*jobs >= 1 && *jobs <= 64) || *jobs != std::floor(*jobs))
    return fail(invalidArgument("--jobs must be a whole number in 1 .. 64 (files analysed at a time)"), 2);
  if (args.positionals().empty())
    return fail(invalidArgument("batch needs at least one DIR (its *.fbs sessions, recursively) or FILE"), 2);

  std::vector<std::string> found;
  for (const auto& p : args.positionals()) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      if (auto s = findSessions(p, found); !s.isOk()) return fail(s, 2);
    } else if (!fs::exists(fs::symlink_status(p, ec))) {
      // A typo, most likely: said before OUT is made or written.
      return fail(invalidArgument("'" + p + "' does not exist; give folders of sessions or session files"), 2);
    } else {
      found.push_back(p);  // a FILE as given; if it is no session its line says so
    }
  }
  // One file, however it was named ("in" and "./in", a symbolic link, a
  // folder and a file in it): analysed once, never by two jobs at once. The
  // first name given is the one its line states.
  std::vector<std::string> files;
  std::set<std::string> seen;
  for (auto& f : found)
    if (seen.insert(canonicalPath(f)).second) files.push_back(std::move(f));
  if (files.empty())
    return fail(invalidArgument("no *.fbs session found under " + args.positionals()[0] +
                                (args.positionals().size() > 1 ? " and the others given" : "")),
                2);

  settings.batchId = newBatchId();
  auto out = openBatchOutput(*outPath, settings);
  if (!out) return fail(out.status(), 2);
  settings.batchId = out->batchId;  // resuming: the id of the batch in OUT
  if (!out->note.empty()) std::cerr << "fogbench-cli: note: " << forTerminal(out->note) << "\n";

  // Listed by an earlier run under another name of the same file: done too.
  std::set<std::string> listedFiles;
  for (const auto& l : out->listed) listedFiles.insert(canonicalPath(l));
  std::vector<std::string> todo;
  for (const auto& f : files)
    if (!out->listed.count(toValidUtf8(f)) && !listedFiles.count(canonicalPath(f))) todo.push_back(f);
  const std::size_t skipped = files.size() - todo.size();

  const bool terminal = ::isatty(2) == 1;
  const auto started = std::chrono::steady_clock::now();
  std::mutex lock;
  std::size_t doneNow = 0, refused = 0, stored = 0, alreadyStored = 0;
  std::map<session::ShownVerdictKind, std::size_t> verdicts;
  Status writeStatus;
  std::atomic<bool> stop{false};
  auto lastDrawn = started - std::chrono::seconds(1);
  auto drawProgress = [&](bool force) {
    const auto now = std::chrono::steady_clock::now();
    if (!terminal || (!force && now - lastDrawn < std::chrono::milliseconds(200))) return;
    lastDrawn = now;
    const double s = std::chrono::duration<double>(now - started).count();
    const double rate = s > 0 ? static_cast<double>(doneNow) / s : 0.0;
    char line[200];
    int n = std::snprintf(line, sizeof line, "batch: %zu/%zu files, %zu refused", skipped + doneNow, files.size(),
                          refused);
    if (doneNow > 0 && rate > 0) {
      n += std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), ", %.1f files/s", rate);
      if (doneNow < todo.size())
        std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), ", about %s left",
                      durationText(static_cast<double>(todo.size() - doneNow) / rate).c_str());
    }
    std::cerr << "\r" << line << "\x1b[K" << std::flush;
  };
  drawProgress(true);

  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < todo.size() && !stop; i = next++) {
      const BatchLine line = batchOneFile(todo[i], settings);
      const std::string text = line.toJson().dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
      std::lock_guard<std::mutex> guard(lock);
      if (stop) return;
      if (auto s = appendDurably(out->fd, text, *outPath); !s.isOk()) {
        writeStatus = s;
        stop = true;
        return;
      }
      ++doneNow;
      switch (line.status) {
        case BatchLine::Status::kStored: ++stored; break;
        case BatchLine::Status::kAlreadyStored: ++alreadyStored; break;
        case BatchLine::Status::kRefused: ++refused; break;
      }
      if (line.status != BatchLine::Status::kRefused) ++verdicts[line.verdict.verdict];
      drawProgress(false);
    }
  };
  // One session in memory per job.
  const int threads = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(*jobs), std::max<std::size_t>(todo.size(), 1)));
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  drawProgress(true);
  if (terminal) std::cerr << "\n";
  ::close(out->fd);  // releases the lock
  if (!writeStatus.isOk())
    return fail(Status(writeStatus.code(), writeStatus.message() + "; " + std::to_string(doneNow) +
                                               " files were listed; run the same batch again to go on"),
                2);

  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("batch of %zu file%s into %s: %zu stored, %zu already stored, %zu refused, %zu skipped (listed before)\n",
              files.size(), files.size() == 1 ? "" : "s", forTerminal(*outPath).c_str(), stored, alreadyStored, refused,
              skipped);
  std::string byVerdict;
  for (auto kind : {session::ShownVerdictKind::kPass, session::ShownVerdictKind::kFail,
                    session::ShownVerdictKind::kInvalid, session::ShownVerdictKind::kIncomplete,
                    session::ShownVerdictKind::kNone})
    if (verdicts[kind] > 0)
      byVerdict += (byVerdict.empty() ? "" : ", ") + std::to_string(verdicts[kind]) + " " +
                   session::shownVerdictWord(kind);
  std::printf("verdicts of the results listed now: %s\n", byVerdict.empty() ? "none" : byVerdict.c_str());
  char wallText[32];
  std::snprintf(wallText, sizeof wallText, wall < 10 ? "%.2f s" : wall < 600 ? "%.1f s" : "%.0f s", wall);
  std::printf("wall time %s (%.2f files/s, %d job%s)\n", wallText, wall > 0 ? static_cast<double>(doneNow) / wall : 0.0,
              threads, threads == 1 ? "" : "s");
  std::fflush(stdout);
  // The catalog follows the new results (docs/catalog.md).
  std::error_code ec;
  const std::string& first = args.positionals()[0];
  const std::string folder = fs::is_directory(first, ec) ? first : fs::path(first).parent_path().string();
  if (Status s = updateCatalogAfterBatch(catalogDb, folder, files); !s.isOk())
    return fail(Status(s.code(), s.message() + "; the new results are stored in the sessions: run fogbench-cli "
                                                "catalog index when the catalog can be reached"),
                3);
  return refused > 0 ? 1 : 0;
}

}  // namespace fog::app
