#include "app/noise_command.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>

#include "app/cli_common.h"
#include "core/noise/gyro_noise.h"
#include "app/session_input.h"

namespace fog::app {

int noiseCommand(CliArguments& args) {
  const bool json = args.flag("json");
  noise::GyroNoiseOptions options;
  if (auto axis = args.text("axis")) {
    auto parsed = parseAxis(*axis);
    if (!parsed) return fail(parsed.status(), 2);
    options.gyroAxis = *parsed;
  }
  auto perOctave = args.number("taus-per-octave", 2.0);
  if (!perOctave) return fail(perOctave.status(), 2);
  if (*perOctave < 1.0 || *perOctave > 16.0 || *perOctave != static_cast<int>(*perOctave))
    return fail(invalidArgument("--taus-per-octave must be a whole number 1 .. 16"), 2);
  options.allan.tausPerOctave = static_cast<int>(*perOctave);
  // The swing test to predict: given, or the paper's two conditions.
  std::vector<analysis::PlannedTest> planned;
  if (args.has("freq-hz") || args.has("amp-deg") || args.has("duration-s")) {
    analysis::PlannedTest t;
    auto f = args.number("freq-hz", 0.1), a = args.number("amp-deg", 10.0), d = args.number("duration-s", 294.0);
    for (const auto* r : {&f, &a, &d})
      if (!*r) return fail(r->status(), 2);
    if (!(*f > 0.0) || !(*a > 0.0) || !(*d > 0.0))
      return fail(invalidArgument("--freq-hz, --amp-deg and --duration-s must be > 0"), 2);
    t.frequencyHz = *f;
    t.amplitudeDeg = *a;
    t.durationS = *d;
    planned.push_back(t);
  } else {
    for (const TestPlan& plan : {TestPlan::paperSlow(), TestPlan::paperFast()}) {
      analysis::PlannedTest t;
      t.frequencyHz = plan.points.front().frequencyHz;
      t.amplitudeDeg = plan.points.front().amplitudeDeg;
      t.durationS = plan.points.front().durationS;
      planned.push_back(t);
    }
  }
  int failed = 0;
  auto opened = openFileArgument(args, "noise needs exactly one SESSION.fbs or raw stream FILE", failed);
  if (!opened) return failed;
  // A raw stream states no latitude or pulse equivalent (0: the stream's
  // STATUS frames or the command line must).
  const BenchConstants& bench = opened->info.bench;
  const Recording& recording = opened->recording;
  auto latitude = args.number("latitude-deg", bench.latitudeDeg);
  if (!latitude) return fail(latitude.status(), 2);
  if (!(std::abs(*latitude) <= 90.0)) return fail(invalidArgument("--latitude-deg must be within [-90, 90]"), 2);
  options.earth.latitudeDeg = *latitude;
  // The Earth rate a static gyro sees depends on where its axes point.
  auto frame = readImuFrame(args, bench.imuFrame);
  if (!frame) return fail(frame.status(), 2);
  model::applyImuFrame(*frame, options.earth);
  const auto yamlPath = args.text("kalibr-yaml");
  const bool overwrite = args.flag("overwrite");
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (yamlPath)
    if (auto s = checkOutputFile(*yamlPath, overwrite, "--kalibr-yaml"); !s.isOk()) return fail(s, 2);

  auto reports = noise::analyzeGyroNoise(recording, options);
  if (!reports) return fail(reports.status(), exitCodeFor(reports.status()));
  // The prediction uses the first segment (the one a plan normally has).
  std::vector<noise::SwingPrediction> predictions;
  for (const auto& t : planned) predictions.push_back(noise::predictSwing(reports->front(), t));
  std::cout << (json ? noise::formatNoiseJson(*reports, predictions) + "\n"
                     : noise::formatNoiseText(*reports, predictions));
  if (yamlPath) {
    // The first static segment (the one a plan normally has), as for the
    // prediction; serialised before the file is opened.
    const std::string text = noise::formatKalibrYaml(reports->front(), opened->sourceLine());
    std::ofstream file(*yamlPath, std::ios::binary | std::ios::trunc);
    file << text;
    file.close();
    if (!file) return fail(ioError("cannot write '" + *yamlPath + "'; check the folder and the free space"), 2);
    std::cerr << "fogbench-cli: kalibr / OpenVINS IMU noise of static segment " << reports->front().testPointIndex + 1
              << " written to " << *yamlPath << "\n";
  }
  return 0;
}

}  // namespace fog::app
