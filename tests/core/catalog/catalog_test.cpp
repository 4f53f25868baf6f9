// The catalog (core/catalog/catalog.h) on both back ends: the same tests run
// on a SQLite file and on a throwaway PostgreSQL server (CTest label
// `postgres`; tests/core/catalog/postgres_server.sh starts it and writes its
// address to the file FOG_TEST_POSTGRES_DSN_FILE names).

#include "core/catalog/catalog.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "../session/session_test_util.h"
#include "core/protocol/recording_builder.h"
#include "core/session/session_api.h"

namespace fog::catalog {
namespace {

using fog::test::ScratchDir;

// The server's address, from the file the fixture wrote; a Postgres test
// without it fails (never skips): the CTest fixture must have run.
std::string postgresBaseDsn() {
  const char* file = std::getenv("FOG_TEST_POSTGRES_DSN_FILE");
  if (!file) return "";
  std::ifstream in(file);
  std::string dsn;
  std::getline(in, dsn);
  return dsn;
}

// A fresh database per test on the server (tests may run side by side).
std::string freshPostgresDatabase(const std::string& which) {
  const std::string base = postgresBaseDsn();
  EXPECT_FALSE(base.empty()) << "FOG_TEST_POSTGRES_DSN_FILE is not set or empty: run the Postgres tests through "
                                "ctest (label postgres), which starts the throwaway server";
  if (base.empty()) return "";
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = "t_";
  for (char c : std::string(info->name())) name += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : '_';
  name = name.substr(0, 50) + "_" + which;
  // The address is a libpq URI without a database (postgres_server.sh).
  auto admin = CatalogDb::open(base + "&dbname=postgres");
  EXPECT_TRUE(admin.isOk()) << admin.status().message();
  if (!admin) return "";
  EXPECT_TRUE((*admin)->exec("DROP DATABASE IF EXISTS " + name).isOk());
  EXPECT_TRUE((*admin)->exec("CREATE DATABASE " + name).isOk());
  return base + "&dbname=" + name;
}

// A SQLite catalog file, opened (created when new).
std::unique_ptr<Catalog> catalogFile(const std::string& path) {
  auto db = CatalogDb::open(path);
  EXPECT_TRUE(db.isOk()) << db.status().message();
  if (!db) return nullptr;
  auto c = Catalog::open(std::move(db).value());
  EXPECT_TRUE(c.isOk()) << c.status().message();
  return c ? std::move(c).value() : nullptr;
}

class CatalogTest : public ::testing::TestWithParam<std::string> {
 protected:
  // A new, empty catalog on this test's back end; `n` tells several apart.
  std::string target(const std::string& n = "cat") {
    if (GetParam() == "sqlite") return dir_.file(n + ".sqlite");
    if (!pgTargets_.count(n)) pgTargets_[n] = freshPostgresDatabaseFor(n);
    return pgTargets_[n];
  }
  std::unique_ptr<Catalog> openCatalog(const std::string& n = "cat") {
    auto db = CatalogDb::open(target(n));
    EXPECT_TRUE(db.isOk()) << db.status().message();
    if (!db) return nullptr;
    auto c = Catalog::open(std::move(*db));
    EXPECT_TRUE(c.isOk()) << c.status().message();
    return c ? std::move(*c) : nullptr;
  }

  // A session of the short simulated run with this identity, analysed once
  // with `constants` (result stored); returns its path.
  std::string session(const std::string& name, const std::string& serial, const std::string& createdUtc,
                      const BenchConstants& constants = {}, bool complete = true, double limitMs = 0.8) {
    SessionInfo info;
    info.source = "simulator, seed 3";
    info.plan = fog::test::shortPlan();
    info.imuSerial = serial;
    info.imuModel = "FOG-3";
    info.lot = "L7";
    info.benchId = "bench-1";
    info.operatorName = "ann";
    info.createdUtc = createdUtc;
    const std::string path = fog::test::recordedSession(dir_, name, info, complete);
    analyse(path, constants, limitMs);
    return path;
  }
  // Analyses and stores; returns the IMU delay of the one test point.
  double analyse(const std::string& path, const BenchConstants& constants, double limitMs = 0.8) {
    auto opened = session::openSessionOrStream(path);
    EXPECT_TRUE(opened.isOk()) << opened.status().message();
    if (!opened) return NAN;
    session::AnalysisSettings s;
    s.constants = constants;
    s.imuDelayLimitMs = limitMs;
    s.producedBy = "catalog_test";
    const auto r = session::analyseAndStore(*opened, s);
    EXPECT_TRUE(r.stored) << r.notStored << r.storeStatus.message();
    return r.report ? r.report->points.at(0).imuDelayMs : NAN;
  }

  ScratchDir dir_;

 private:
  std::string freshPostgresDatabaseFor(const std::string& n) { return freshPostgresDatabase(n); }
  std::map<std::string, std::string> pgTargets_;
};

TEST_P(CatalogTest, ALotCountsInvalidAndIncompleteButNeverAveragesThem) {
  BenchConstants good;
  BenchConstants backwards = good;  // every gyro axis stated reversed: the gyro turns against the table
  backwards.gyroSign = {-1, -1, -1};

  const std::string a = session("a.fbs", "SN-A", "2026-11-01T08:00:00Z", good);
  session("b.fbs", "SN-B", "2026-11-01T09:00:00Z", backwards);
  session("c.fbs", "SN-C", "2026-11-01T10:00:00Z", good, /*complete=*/false);
  // D judged against a limit its IMU delay (about 0.5 ms) exceeds: FAIL.
  const std::string d = session("d.fbs", "SN-D", "2026-11-01T11:00:00Z", good, true, /*limitMs=*/0.4);
  // Unit A re-analysed with another read delay: result 1 is superseded.
  BenchConstants regood = good;
  regood.tableReadDelayMs = 0.06;
  const double delayA = analyse(a, regood);
  auto od = session::openSessionOrStream(d);
  ASSERT_TRUE(od.isOk());
  ASSERT_FALSE(od->results.empty());
  const double delayD = od->results.back().points.at(0).imuDelayMs;
  { std::ofstream(dir_.file("damaged.fbs")) << "not a session at all"; }
  // A real session cut short (a copy interrupted, a full disk): half its bytes.
  std::filesystem::copy_file(d, dir_.file("truncated.fbs"));
  std::filesystem::resize_file(dir_.file("truncated.fbs"), std::filesystem::file_size(d) / 2);
  // A session whose one stored result fails its checksum (changed behind
  // it): indexed, its result one row that says why and has no verdict.
  const std::string e = session("e.fbs", "SN-E", "2026-11-01T12:00:00Z", good);
  fog::test::runSql(e, "UPDATE result SET report_json = '{\"verdict\": \"pass\"}'");

  // The mean IMU temperature, from the decoded stream here.
  auto decoded = protocol::decodeRecording(fog::test::shortRun().bytes);
  ASSERT_TRUE(decoded.isOk());
  double sum = 0.0;
  std::size_t n = 0;
  for (const auto& tp : decoded->testPoints)
    for (const auto& f : tp.imu) sum += f.temperatureC, ++n;
  ASSERT_GT(n, 0u);
  const double expectedTemperature = sum / static_cast<double>(n);

  auto cat = openCatalog();
  ASSERT_TRUE(cat);
  auto report = cat->index({dir_.path().string()});
  ASSERT_TRUE(report.isOk()) << report.status().message();
  // Each damaged file is one refusal row; indexing went on past both.
  EXPECT_EQ(report->filesFound, 7);
  EXPECT_EQ(report->indexed, 5);
  EXPECT_EQ(report->refused, 2);
  ASSERT_EQ(report->refusals.size(), 2u);
  EXPECT_NE(report->refusals[0].first.find("damaged.fbs"), std::string::npos);
  EXPECT_NE(report->refusals[1].first.find("truncated.fbs"), std::string::npos);
  EXPECT_FALSE(report->refusals[1].second.empty());
  EXPECT_EQ(report->resultsStored, 6);
  auto refusedRows = cat->refusals();
  ASSERT_TRUE(refusedRows.isOk());
  ASSERT_EQ(refusedRows->size(), 2u);
  EXPECT_NE((*refusedRows)[1].first.find("truncated.fbs"), std::string::npos);
  EXPECT_EQ((*refusedRows)[1].second, report->refusals[1].second);
  auto truncatedRows = cat->db().query("SELECT count(*) FROM result WHERE path LIKE '%truncated.fbs'");
  ASSERT_TRUE(truncatedRows.isOk());
  EXPECT_EQ(integerOf((*truncatedRows)[0][0]), 0);

  auto all = cat->results("", "L7", false);
  ASSERT_TRUE(all.isOk()) << all.status().message();
  ASSERT_EQ(all->size(), 6u);
  // E's result: one row, no verdict, no point, why.
  std::vector<CatalogResult> unreadable;
  for (const auto& r : *all)
    if (r.imuSerial == "SN-E") unreadable.push_back(r);
  ASSERT_EQ(unreadable.size(), 1u);
  EXPECT_TRUE(unreadable[0].shown);
  EXPECT_EQ(unreadable[0].verdict, "");
  EXPECT_TRUE(unreadable[0].points.empty());
  EXPECT_NE(unreadable[0].verdictReason.find("fails its checksum"), std::string::npos) << unreadable[0].verdictReason;

  auto withE = lotStatistics("L7", *all, 0.8);
  ASSERT_TRUE(withE.isOk()) << withE.status().message();
  EXPECT_EQ(withE->units, 5);
  EXPECT_EQ(withE->sessions, 5);
  EXPECT_EQ(withE->noVerdict, 1);  // counted, never averaged
  ASSERT_EQ(withE->delay.size(), 1u);
  EXPECT_EQ(withE->delay[0].n, 2);

  // The rest of the test: the four sessions A to D.
  std::vector<CatalogResult> fourUnits;
  for (const auto& r : *all)
    if (r.imuSerial != "SN-E") fourUnits.push_back(r);
  const std::vector<CatalogResult>* results = &fourUnits;
  ASSERT_EQ(results->size(), 5u);
  std::map<std::string, std::string> verdictOf;
  for (const auto& r : *results)
    if (r.shown) verdictOf[r.imuSerial] = r.verdict;
  EXPECT_EQ(verdictOf["SN-A"], "pass");
  EXPECT_EQ(verdictOf["SN-B"], "invalid");
  EXPECT_EQ(verdictOf["SN-C"], "incomplete");
  EXPECT_EQ(verdictOf["SN-D"], "fail");
  for (const auto& r : *results) {
    ASSERT_EQ(r.points.size(), 1u);
    const bool vouched = r.verdict == "pass" || r.verdict == "fail";
    // A refused delay is stored without its number, with why.
    EXPECT_EQ(std::isfinite(r.points[0].imuDelayMs), vouched) << r.imuSerial << " " << r.verdict;
    EXPECT_EQ(r.points[0].refusal.empty(), vouched) << r.points[0].refusal;
    EXPECT_EQ(r.lot, "L7");
    EXPECT_EQ(r.benchId, "bench-1");
    EXPECT_EQ(r.fileSha256.size(), 64u);
    EXPECT_NEAR(r.meanTemperatureC, expectedTemperature, 1e-9);
  }

  // Judged against 0.8 and 0.4 ms: Cpk needs the limit named.
  auto unnamed = lotStatistics("L7", *results, NAN);
  ASSERT_FALSE(unnamed.isOk());
  EXPECT_NE(unnamed.status().message().find("different limits (0.4 ms, 0.8 ms)"),
            std::string::npos)
      << unnamed.status().message();
  auto stats = lotStatistics("L7", *results, 0.8);
  ASSERT_TRUE(stats.isOk()) << stats.status().message();
  EXPECT_EQ(stats->units, 4);
  EXPECT_EQ(stats->sessions, 4);
  EXPECT_EQ(stats->pass, 1);
  EXPECT_EQ(stats->fail, 1);
  EXPECT_EQ(stats->invalid, 1);
  EXPECT_EQ(stats->incomplete, 1);
  EXPECT_EQ(stats->superseded, 1);
  EXPECT_DOUBLE_EQ(stats->passRate, 0.25);
  EXPECT_DOUBLE_EQ(stats->firstPassYield, 0.25);
  EXPECT_EQ(stats->limitSource, "given");
  EXPECT_DOUBLE_EQ(stats->limitMs, 0.8);
  // The delays: A's latest (re-analysed) and D's, nothing of B or C.
  ASSERT_EQ(stats->delay.size(), 1u);  // one axis (z): no separate "all"
  const auto& z = stats->delay[0];
  EXPECT_EQ(z.axis, "z");
  EXPECT_EQ(z.n, 2);
  const double mean = (delayA + delayD) / 2.0;
  const double s = std::abs(delayA - delayD) / std::sqrt(2.0);
  EXPECT_NEAR(z.meanMs, mean, 1e-12);
  EXPECT_NEAR(z.stdMs, s, 1e-12);
  EXPECT_NEAR(z.cpk, (0.8 - mean) / (3.0 * s), 1e-9);
}

TEST_P(CatalogTest, UnchangedFilesAreNotReopenedAndAReanalysisSupersedes) {
  const std::string a = session("a.fbs", "SN-A", "2026-11-01T08:00:00Z");
  session("b.fbs", "SN-B", "2026-11-01T09:00:00Z");
  auto cat = openCatalog();
  ASSERT_TRUE(cat);
  auto first = cat->index({dir_.path().string()});
  ASSERT_TRUE(first.isOk()) << first.status().message();
  EXPECT_EQ(first->indexed, 2);
  auto again = cat->index({dir_.path().string()});
  ASSERT_TRUE(again.isOk());
  EXPECT_EQ(again->unchanged, 2);
  EXPECT_EQ(again->indexed, 0);

  BenchConstants other;
  other.boardDelayMs = 0.3;
  analyse(a, other);
  auto third = cat->index({dir_.path().string()});
  ASSERT_TRUE(third.isOk());
  EXPECT_EQ(third->unchanged, 1);
  EXPECT_EQ(third->indexed, 1);
  auto history = cat->results("SN-A", "", false);
  ASSERT_TRUE(history.isOk());
  ASSERT_EQ(history->size(), 2u);  // two results of one session, never a duplicate row
  EXPECT_FALSE((*history)[0].shown);
  EXPECT_TRUE((*history)[1].shown);
  EXPECT_EQ((*history)[0].resultNumber, 1);
  EXPECT_EQ((*history)[1].resultNumber, 2);
  EXPECT_NE((*history)[0].constantsHash, (*history)[1].constantsHash);
  EXPECT_NE((*history)[1].constantsJson.find("\"board_delay_ms\":0.3,"), std::string::npos)
      << (*history)[1].constantsJson;
  // A copy of the session elsewhere is the same session: counted once.
  std::filesystem::create_directories(dir_.file("copy"));
  std::filesystem::copy_file(a, dir_.file("copy/a.fbs"));
  ASSERT_TRUE(cat->index({dir_.path().string()}).isOk());
  auto after = cat->results("SN-A", "", false);
  ASSERT_TRUE(after.isOk());
  EXPECT_EQ(after->size(), 2u);
}

TEST_P(CatalogTest, TwoBenchesPushToOneCatalogOneOfflineFirst) {
  session("a.fbs", "SN-A", "2026-11-01T08:00:00Z");
  std::filesystem::create_directories(dir_.file("bench2"));
  {
    SessionInfo info;
    info.source = "simulator, seed 3";
    info.plan = fog::test::shortPlan();
    info.imuSerial = "SN-B";
    info.lot = "L7";
    info.benchId = "bench-2";
    info.createdUtc = "2026-11-02T08:00:00Z";
    analyse(fog::test::recordedSession(dir_, "bench2/b.fbs", info), {});
  }
  // Each bench indexes into its own SQLite catalog.
  auto bench1 = catalogFile(dir_.file("bench1.sqlite"));
  auto bench2 = catalogFile(dir_.file("bench2/bench2.sqlite"));
  ASSERT_TRUE(bench1 && bench2);
  ASSERT_TRUE(bench1->index({dir_.file("a.fbs")}).isOk());
  ASSERT_TRUE(bench2->index({dir_.file("bench2")}).isOk());

  // Bench 2 is offline: the shared catalog does not answer; it says so.
  auto offline = CatalogDb::open("postgresql://fogbench@127.0.0.1:1/none?connect_timeout=2");
  ASSERT_FALSE(offline.isOk());
  EXPECT_EQ(offline.status().code(), StatusCode::kIoError);
  EXPECT_NE(offline.status().message().find("cannot reach the PostgreSQL catalog postgresql://fogbench@127.0.0.1:1/"),
            std::string::npos)
      << offline.status().message();

  auto shared = openCatalog("shared");
  ASSERT_TRUE(shared);
  auto p1 = bench1->pushTo(*shared);
  ASSERT_TRUE(p1.isOk()) << p1.status().message();
  EXPECT_EQ(p1->pushed, 1);
  // Back online: bench 2 pushes; then both push again and nothing doubles.
  auto p2 = bench2->pushTo(*shared);
  ASSERT_TRUE(p2.isOk()) << p2.status().message();
  EXPECT_EQ(p2->pushed, 1);
  auto again1 = bench1->pushTo(*shared);
  auto again2 = bench2->pushTo(*shared);
  ASSERT_TRUE(again1.isOk() && again2.isOk());
  EXPECT_EQ(again1->pushed, 0);
  EXPECT_EQ(again1->alreadyPushed, 1);
  EXPECT_EQ(again2->pushed, 0);
  auto all = shared->results("", "L7", false);
  ASSERT_TRUE(all.isOk());
  ASSERT_EQ(all->size(), 2u);
  EXPECT_EQ((*all)[0].benchId, "bench-1");
  EXPECT_EQ((*all)[1].benchId, "bench-2");
  // A re-analysis on bench 1 is pushed as an update plus a new row.
  BenchConstants other;
  other.boardDelayMs = 0.3;
  analyse(dir_.file("a.fbs"), other);
  ASSERT_TRUE(bench1->index({dir_.file("a.fbs")}).isOk());
  auto p3 = bench1->pushTo(*shared);
  ASSERT_TRUE(p3.isOk());
  EXPECT_EQ(p3->pushed, 2);  // the superseded row changed (shown -> not), the new one
  auto unitA = shared->results("SN-A", "", false);
  ASSERT_TRUE(unitA.isOk());
  ASSERT_EQ(unitA->size(), 2u);
  EXPECT_FALSE((*unitA)[0].shown);
  EXPECT_TRUE((*unitA)[1].shown);
}

TEST_P(CatalogTest, RefusedDelaysAreStoredAsNullNotAsNumbers) {
  BenchConstants backwards;
  backwards.gyroSign = {-1, -1, -1};
  session("b.fbs", "SN-B", "2026-11-01T09:00:00Z", backwards);
  auto cat = openCatalog();
  ASSERT_TRUE(cat);
  ASSERT_TRUE(cat->index({dir_.path().string()}).isOk());
  auto rows = cat->db().query("SELECT verdict, imu_delay_ms, imu_delay_std_ms, refusal FROM result_point");
  ASSERT_TRUE(rows.isOk());
  ASSERT_EQ(rows->size(), 1u);
  EXPECT_EQ(textOf((*rows)[0][0]), "invalid");
  EXPECT_FALSE((*rows)[0][1].has_value());
  EXPECT_FALSE((*rows)[0][2].has_value());
  EXPECT_NE(textOf((*rows)[0][3]).find("INVALID"), std::string::npos) << textOf((*rows)[0][3]);
}

TEST_P(CatalogTest, ASessionWhoseResultsCannotBeReadStillCountsWithoutAVerdict) {
  const std::string a = session("a.fbs", "SN-A", "2026-11-01T08:00:00Z");
  session("b.fbs", "SN-B", "2026-11-01T09:00:00Z");
  // A's one result damaged behind its checksum: unreadable.
  fog::test::runSql(a, "UPDATE result SET report_json = '{\"verdict\": \"pass\"}'");
  auto cat = openCatalog();
  ASSERT_TRUE(cat);
  ASSERT_TRUE(cat->index({dir_.path().string()}).isOk());
  auto results = cat->results("", "L7", false);
  ASSERT_TRUE(results.isOk());
  ASSERT_EQ(results->size(), 2u);
  EXPECT_TRUE((*results)[0].shown);
  EXPECT_EQ((*results)[0].verdict, "");
  EXPECT_NE((*results)[0].verdictReason.find("cannot be read"), std::string::npos) << (*results)[0].verdictReason;
  auto stats = lotStatistics("L7", *results, NAN);
  ASSERT_TRUE(stats.isOk()) << stats.status().message();
  EXPECT_EQ(stats->units, 2);
  EXPECT_EQ(stats->sessions, 2);
  EXPECT_EQ(stats->noVerdict, 1);
  EXPECT_EQ(stats->pass, 1);
  EXPECT_EQ(stats->superseded, 0);
}

INSTANTIATE_TEST_SUITE_P(Sqlite, CatalogTest, ::testing::Values("sqlite"));
INSTANTIATE_TEST_SUITE_P(Postgres, CatalogTest, ::testing::Values("postgres"));

// A bench offline, end to end, on a server of its own (the shared fixture's
// server serves tests running side by side; this one is stopped midway):
// postgres_server.sh start, pause (the server gone, its data kept), resume.
class OfflineBenchTest : public CatalogTest {
 protected:
  int server(const std::string& what) {
    const std::string command = std::string("bash '") + FOG_POSTGRES_SERVER_SCRIPT + "' " + what + " '" + dsnFile_ + "'";
    return std::system(command.c_str());
  }
  void TearDown() override { server("stop"); }
  std::string dsnFile_ = dir_.file("offline-dsn");
};

TEST_P(OfflineBenchTest, ABenchPushesWhenTheServerIsBackExactlyOnce) {
  ASSERT_EQ(server("start"), 0) << "postgres_server.sh start failed";
  std::ifstream in(dsnFile_);
  std::string base;
  std::getline(in, base);
  ASSERT_FALSE(base.empty());
  const std::string sharedTarget = base + "&dbname=postgres&connect_timeout=5";

  const std::string a = session("a.fbs", "SN-A", "2026-11-01T08:00:00Z");
  auto bench = catalogFile(dir_.file("bench.sqlite"));
  ASSERT_TRUE(bench);
  ASSERT_TRUE(bench->index({dir_.path().string()}).isOk());
  auto first = pushPending(*bench, sharedTarget);
  ASSERT_TRUE(first.isOk()) << first.status().message();
  ASSERT_TRUE(first->reached) << first->problem;
  EXPECT_EQ(first->push.pushed, 1);
  EXPECT_EQ(first->pending, 0);

  // A connection opened while the server answered, then the server gone.
  auto opened = CatalogDb::open(sharedTarget);
  ASSERT_TRUE(opened.isOk()) << opened.status().message();
  auto openedShared = Catalog::open(std::move(*opened));
  ASSERT_TRUE(openedShared.isOk());
  ASSERT_EQ(server("pause"), 0) << "postgres_server.sh pause failed";

  // Offline, the bench goes on: a new session and a re-analysis of A (its
  // two rows change: the first is superseded) are pending.
  session("b.fbs", "SN-B", "2026-11-01T09:00:00Z");
  BenchConstants other;
  other.boardDelayMs = 0.3;
  analyse(a, other);
  ASSERT_TRUE(bench->index({dir_.path().string()}).isOk());
  ASSERT_EQ(*bench->pendingCount(), 3);
  auto midway = bench->pushTo(**openedShared);
  ASSERT_FALSE(midway.isOk());
  EXPECT_EQ(*bench->pendingCount(), 3);  // nothing marked sent
  auto down = pushPending(*bench, sharedTarget);
  ASSERT_TRUE(down.isOk()) << down.status().message();
  EXPECT_FALSE(down->reached);
  EXPECT_NE(down->problem.find("cannot reach the PostgreSQL catalog"), std::string::npos) << down->problem;
  EXPECT_EQ(down->pending, 3);
  EXPECT_EQ(down->push.pushed, 0);

  // Back: the next push sends the three once; a repeat sends nothing.
  ASSERT_EQ(server("resume"), 0) << "postgres_server.sh resume failed";
  auto back = pushPending(*bench, sharedTarget);
  ASSERT_TRUE(back.isOk()) << back.status().message();
  ASSERT_TRUE(back->reached) << back->problem;
  EXPECT_EQ(back->push.pushed, 3);
  EXPECT_EQ(back->pending, 0);
  auto again = pushPending(*bench, sharedTarget);
  ASSERT_TRUE(again.isOk() && again->reached);
  EXPECT_EQ(again->push.pushed, 0);
  EXPECT_EQ(again->push.alreadyPushed, 3);

  auto shared = CatalogDb::open(sharedTarget);
  ASSERT_TRUE(shared.isOk());
  auto sharedCatalog = Catalog::open(std::move(*shared));
  ASSERT_TRUE(sharedCatalog.isOk());
  auto rows = (*sharedCatalog)->db().query("SELECT count(*), count(DISTINCT result_key) FROM result");
  ASSERT_TRUE(rows.isOk());
  EXPECT_EQ(integerOf((*rows)[0][0]), 3);  // A's two results and B's, no duplicate
  EXPECT_EQ(integerOf((*rows)[0][1]), 3);
  auto unitA = (*sharedCatalog)->results("SN-A", "", false);
  ASSERT_TRUE(unitA.isOk());
  ASSERT_EQ(unitA->size(), 2u);
  EXPECT_FALSE((*unitA)[0].shown);  // the update of the superseded row arrived too
  EXPECT_TRUE((*unitA)[1].shown);
}

INSTANTIATE_TEST_SUITE_P(Postgres, OfflineBenchTest, ::testing::Values("postgres"));

// The results' CSV: text that looks like a formula (serial, lot, bench,
// operator) is written as text; numbers, negative ones included, as numbers.
TEST(CatalogFile, CsvWritesFormulaLikeTextAsTextAndNumbersAsNumbers) {
  CatalogResult r;
  r.imuSerial = "=1+2";
  r.imuModel = "FOG-3";
  r.lot = "+L7";
  r.benchId = "-B1";
  r.operatorName = "@ann";
  r.sessionCreatedUtc = "2026-11-01T08:00:00Z";
  r.resultNumber = 1;
  r.shown = true;
  r.meanTemperatureC = -12.5;
  r.verdict = "pass";
  r.limitMs = 0.8;
  CatalogPoint p;
  p.axis = "z";
  p.frequencyHz = 1.0;
  p.verdict = "pass";
  p.imuDelayMs = -0.25;  // not a delay a PASS would have: only the number's form matters here
  p.imuDelayStdMs = 0.001;
  r.points.push_back(p);
  const std::string csv = resultsCsv({r});
  const std::string row = csv.substr(csv.find('\n') + 1);
  EXPECT_EQ(row.rfind("'=1+2,FOG-3,'+L7,'-B1,'@ann,2026-11-01T08:00:00Z,1,,1,-12.5,pass,0.8,0,z,1,pass,-0.25,0.001,,", 0), 0u)
      << row;
}

// A password never shows in what is said about a server.
TEST(CatalogFile, APasswordIsNeverShown) {
  EXPECT_EQ(describeTarget("postgresql://fogbench:s3cret@labdb:5432/fogbench"),
            "postgresql://fogbench:***@labdb:5432/fogbench");
  EXPECT_EQ(describeTarget("postgresql://labdb/fogbench?password=s3cret&sslmode=require"),
            "postgresql://labdb/fogbench?password=***&sslmode=require");
  EXPECT_EQ(describeTarget("postgresql://fogbench@labdb:5432/fogbench"), "postgresql://fogbench@labdb:5432/fogbench");
  auto db = CatalogDb::open("postgresql://fogbench:s3cret@127.0.0.1:1/none?connect_timeout=2");
  ASSERT_FALSE(db.isOk());
  EXPECT_EQ(db.status().message().find("s3cret"), std::string::npos) << db.status().message();
}

// SQLite only: what a file named by mistake is, and catalogs of other versions.
TEST(CatalogFile, ASessionOrAForeignDatabaseNamedAsTheCatalogIsNeverWritten) {
  ScratchDir dir;
  SessionInfo info;
  info.plan = fog::test::shortPlan();
  const std::string s = fog::test::recordedSession(dir, "s.fbs", info);
  const auto before = fog::test::readFile(s);
  auto db = CatalogDb::open(s);
  ASSERT_FALSE(db.isOk());
  EXPECT_NE(db.status().message().find("a fogbench session file, not a catalog"), std::string::npos)
      << db.status().message();
  EXPECT_EQ(fog::test::readFile(s), before);

  const std::string other = dir.file("other.sqlite");
  {
    sqlite3* raw = nullptr;
    ASSERT_EQ(sqlite3_open_v2(other.c_str(), &raw, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(raw, "CREATE TABLE t (x INTEGER)", nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(raw);
  }
  const auto otherBefore = fog::test::readFile(other);
  auto db2 = CatalogDb::open(other);
  ASSERT_FALSE(db2.isOk());
  EXPECT_NE(db2.status().message().find("another SQLite database"), std::string::npos);
  EXPECT_EQ(fog::test::readFile(other), otherBefore);

  auto folder = CatalogDb::open(dir.path().string());
  ASSERT_FALSE(folder.isOk());
  EXPECT_NE(folder.status().message().find("is a folder"), std::string::npos);
}

// Numbers are bound as the shortest text that reads back exactly, whatever
// the C locale's decimal point (the GUI runs under the user's locale).
TEST(CatalogFile, NumbersRoundTripExactlyAndIgnoreTheLocale) {
  for (double v : {0.06, 0.1 + 0.2, 1e-300, -2.5e17, 0.51552, 123456789.123456789}) {
    const Value text = numberValue(v);
    ASSERT_TRUE(text.has_value());
    EXPECT_EQ(numberOf(text), v) << *text;
    EXPECT_EQ(text->find(','), std::string::npos) << *text;
  }
  EXPECT_EQ(*numberValue(0.06), "0.06");
  EXPECT_FALSE(numberValue(NAN).has_value());
  EXPECT_TRUE(std::isnan(numberOf(std::string("0,06"))));  // a decimal comma is not a number here
  EXPECT_TRUE(std::isnan(numberOf(std::string("0.06x"))));
  EXPECT_EQ(integerOf(std::string("12x"), -7), -7);
}

// Only a postgresql:// or postgres:// URI names a server: a catalog file in
// a folder whose name holds "host=" or "dbname=" is a SQLite file.
TEST(CatalogFile, OnlyAPostgresUriNamesAServer) {
  EXPECT_TRUE(isPostgresTarget("postgresql://fogbench@labdb/fogbench"));
  EXPECT_TRUE(isPostgresTarget("postgres://labdb/fogbench"));
  EXPECT_FALSE(isPostgresTarget("host=labdb dbname=fogbench"));
  EXPECT_FALSE(isPostgresTarget("/data/host=bench-2/fogbench-catalog.sqlite"));
  EXPECT_FALSE(isPostgresTarget("runs dbname=x.sqlite"));
  EXPECT_FALSE(isPostgresTarget("my-postgresql://notes.sqlite"));
  ScratchDir dir;
  std::filesystem::create_directories(dir.file("host=bench-2 dbname=lab"));
  const std::string path = dir.file("host=bench-2 dbname=lab/fogbench-catalog.sqlite");
  auto db = CatalogDb::open(path);
  ASSERT_TRUE(db.isOk()) << db.status().message();
  EXPECT_EQ((*db)->kind(), CatalogDb::Kind::kSqlite);
  ASSERT_TRUE(Catalog::open(std::move(*db)).isOk());
  EXPECT_TRUE(std::filesystem::exists(path));
}

TEST(CatalogFile, ANewerCatalogIsRefused) {
  ScratchDir dir;
  const std::string p = dir.file("c.sqlite");
  ASSERT_TRUE(catalogFile(p));
  fog::test::runSql(p, "UPDATE catalog_info SET value = '99' WHERE key = 'schema_version'");
  auto db = CatalogDb::open(p);
  ASSERT_TRUE(db.isOk());
  auto c = Catalog::open(std::move(db).value());
  ASSERT_FALSE(c.isOk());
  EXPECT_NE(c.status().message().find("update fogbench"), std::string::npos);
}

}  // namespace
}  // namespace fog::catalog
