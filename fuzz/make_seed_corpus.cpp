// Writes a few small, valid sampling-board streams as libFuzzer seeds, and,
// given a second folder, small session files made from them:
//   fog_fuzz_seed_corpus fuzz/corpus/decoder [SESSION_SEED_DIR]

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "core/protocol/frame.h"
#include "core/protocol/recording_builder.h"
#include "core/session/session_file.h"

namespace {

using namespace fog::protocol;

bool writeFile(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream f(path, std::ios::binary);
  f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(f);
}

StatusPayload recordingStatus(int bits) {
  StatusPayload s;
  s.counterBits = static_cast<std::uint8_t>(bits);
  s.pulseEquivalentDeg = 5e-5;
  s.testPoint = 0;
  s.axis = 0;
  s.phase = TestPhase::kRecording;
  s.nominalFrequencyMicroHz = 1000000;
  s.nominalAmplitudeMicroDeg = 3000000;
  return s;
}

// ms milliseconds of table (1 ms) and IMU (2 ms) frames, counter at 10 MHz
// starting at `start`, truncated to `bits`.
std::vector<std::uint8_t> recording(int ms, std::uint32_t start, int bits) {
  FrameWriter w;
  std::vector<std::uint8_t> out;
  const std::uint32_t mask = bits >= 32 ? 0xFFFFFFFFu : (1u << bits) - 1u;
  w.status(start & mask, recordingStatus(bits), out);
  for (int i = 0; i < ms; ++i) {
    const std::uint32_t c = start + static_cast<std::uint32_t>(i) * 10000u;
    TablePayload t;
    t.angleMicroDeg = {i * 1000, -i, 7};
    w.table(c & mask, t, out);
    if (i % 2 == 0) {
      ImuPayload m;
      m.pulses = {20, -1, 0};
      m.temperatureCentiC = 2500;
      w.imu((c + 2800) & mask, m, out);
    }
  }
  return out;
}

// A session holding `stream`: finished (complete or not) with its decoded
// samples and a result, or left as a crashed recorder leaves it.
bool writeSession(const std::string& path, const std::vector<std::uint8_t>& stream, int kind) {
  std::remove(path.c_str());
  fog::SessionInfo info;
  info.operatorName = "fuzz";
  info.source = "fog_fuzz_seed_corpus";
  info.plan.points.push_back(fog::TestPlan::paperFast().points.front());
  auto writer = fog::session::SessionWriter::create(path, info);
  if (!writer) return false;
  if (!(*writer)->appendRaw(stream.data(), stream.size()).isOk()) return false;
  if (kind == 2) return (*writer)->flush().isOk();  // interrupted: no finish()
  auto rec = decodeRecording(stream);
  if (rec && !(*writer)->storeRecording(*rec).isOk()) return false;
  if (!(*writer)->finish(kind == 0, kind == 0 ? "" : "serial port vanished (after 0.1 s)").isOk()) return false;
  writer->reset();
  return fog::session::addResult(path, R"({"analysed_by":"seed"})", R"({"report_format":1,"test_points":[]})").isOk();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: %s <decoder corpus directory> [<session corpus directory>]\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  bool ok = true;

  ok &= writeFile(dir + "/recording_32bit.bin", recording(40, 1000, 32));
  ok &= writeFile(dir + "/recording_wrap_16bit.bin", recording(20, 0xFF00u, 16));
  ok &= writeFile(dir + "/recording_wrap_32bit.bin", recording(20, 0xFFFF0000u, 32));

  std::vector<std::uint8_t> one;
  FrameWriter w;
  w.imu(1, {}, one);
  w.table(2, {}, one);
  w.status(3, {}, one);
  ok &= writeFile(dir + "/one_of_each.bin", one);

  // Garbage, a damaged frame, a duplicate and a stale frame around good ones.
  std::vector<std::uint8_t> messy = {0x00, 0xA5, 0x5A, 0x09, 0xA5};
  const auto good = recording(6, 5000, 32);
  messy.insert(messy.end(), good.begin(), good.end());
  messy[5 + 40] ^= 0x04;
  appendFrame(Frame{FrameType::kTable, 3, 40000, TablePayload{}}, messy);
  appendFrame(Frame{FrameType::kTable, 1, 60000, TablePayload{}}, messy);
  messy.insert(messy.end(), {0xA5, 0x5A, 0x02});  // truncated tail
  ok &= writeFile(dir + "/messy.bin", messy);

  if (!ok) {
    std::fprintf(stderr, "could not write the seeds to %s\n", dir.c_str());
    return 1;
  }
  if (argc == 3) {
    const std::string sessions = argv[2];
    ok &= writeSession(sessions + "/complete.fbs", recording(40, 1000, 32), 0);
    ok &= writeSession(sessions + "/incomplete.fbs", recording(20, 0xFFFF0000u, 32), 1);
    ok &= writeSession(sessions + "/interrupted.fbs", recording(20, 5000, 16), 2);
    ok &= writeSession(sessions + "/garbage_stream.fbs", messy, 0);
    if (!ok) {
      std::fprintf(stderr, "could not write the session seeds to %s\n", sessions.c_str());
      return 1;
    }
  }
  return 0;
}
