#include "app/sim_options.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "app/cli_common.h"

namespace fog::app {

bool planGiven(const CliArguments& args) {
  for (const char* name : {"plan", "preset", "axis", "freq-hz", "amp-deg", "duration-s", "settle-s"})
    if (args.has(name)) return true;
  return false;
}

Result<TestPlan> readPlan(CliArguments& args) {
  auto file = args.text("plan");
  auto preset = args.text("preset");
  auto axis = args.text("axis");
  auto freq = args.number("freq-hz", 0.0);
  auto amp = args.number("amp-deg", 0.0);
  auto duration = args.number("duration-s", 0.0);
  auto settle = args.number("settle-s", -1.0);
  for (const auto* r : {&freq, &amp, &duration, &settle})
    if (!*r) return r->status();
  // --preset response --axis y (or response-third-octave): the response plan of that axis.
  const bool responseAxis = axis && preset && isResponsePreset(*preset);
  const bool single =
      (axis && !responseAxis) || args.text("freq-hz") || args.text("amp-deg") || args.text("duration-s");
  if ((file ? 1 : 0) + (preset ? 1 : 0) + (single ? 1 : 0) > 1)
    return invalidArgument("give one of --plan, --preset or --axis/--freq-hz/--amp-deg/--duration-s");
  if (file) {
    return loadTestPlanFile(*file);
  }
  if (single) {
    TestPoint p;
    if (axis) {
      FOG_ASSIGN_OR_RETURN(auto a, parseAxis(*axis));
      p.axis = a;
    }
    if (!args.text("freq-hz") || !args.text("amp-deg"))
      return invalidArgument("a single test point needs --freq-hz and --amp-deg");
    p.frequencyHz = *freq;
    p.amplitudeDeg = *amp;
    p.durationS = args.text("duration-s") ? *duration : 30.0 / std::max(p.frequencyHz, 1e-9);
    p.settleS = *settle >= 0.0 ? *settle : std::min(5.0, 1.0 / std::max(p.frequencyHz, 1e-9));
    TestPlan plan;
    plan.points.push_back(p);
    return plan;
  }
  if (responseAxis) {
    FOG_ASSIGN_OR_RETURN(auto a, parseAxis(*axis));
    return responsePreset(*preset, a);
  }
  return presetPlan(preset.value_or("paper"));
}

Result<std::optional<EmulatorStart>> startEmulator(int argc, char** argv, const char* help) {
  std::vector<std::string> argList(argv + 1, argv + argc);
  for (const auto& a : argList)
    if (a == "--help" || a == "-h" || a == "help") {
      std::fputs(help, stdout);
      return std::optional<EmulatorStart>();
    }
  FOG_ASSIGN_OR_RETURN(auto args, CliArguments::parse(argList, {}));
  FOG_ASSIGN_OR_RETURN(auto config, readSimConfig(args));
  return std::optional<EmulatorStart>(EmulatorStart{std::move(args), std::move(config)});
}

Result<model::SimConfig> readSimConfig(CliArguments& args) {
  model::SimConfig c;
  FOG_ASSIGN_OR_RETURN(auto seed, args.number("seed", 1.0));
  // Whole numbers up to 2^53 are exact in a double; 1e300 was cast to a
  // 64-bit integer (undefined) and ran as seed 0.
  if (!(seed >= 0 && seed <= 9007199254740992.0) || seed != std::floor(seed))
    return invalidArgument("--seed must be a whole number within 0 .. 2^53");
  c.seed = static_cast<std::uint64_t>(seed);
  struct Field {
    const char* name;
    double* target;
    double scale;
  } fields[] = {{"arw-deg-sqrt-h", &c.fog.arwDegPerSqrtH, 1.0},
                {"bias-instability-deg-h", &c.fog.biasInstabilityDegPerH, 1.0},
                {"pulse-equivalent-deg", &c.fog.pulseEquivalentDeg, 1.0},
                {"table-freq-error-ppm", &c.turntable.frequencyErrorPpm, 1.0},
                {"counter-hz", &c.samplingBoard.counterHz, 1.0},
                {"latitude-deg", &c.earth.latitudeDeg, 1.0},
                {"heading-deg", &c.earth.headingDeg, 1.0},
                {"imu-clock-ppm", &c.imuBoard.clockErrorPpm, 1.0},
                {"imu-period-ms", &c.imuBoard.framePeriodS, 1e-3},
                {"table-period-ms", &c.encoder.samplePeriodS, 1e-3},
                {"encoder-quantum-deg", &c.encoder.quantumDeg, 1.0},
                {"bias-x-deg-h", &c.fog.biasDegPerH[0], 1.0},
                {"bias-y-deg-h", &c.fog.biasDegPerH[1], 1.0},
                {"bias-z-deg-h", &c.fog.biasDegPerH[2], 1.0},
                // The nominal chain's stated constants (docs/simulator.md); 0 = off.
                {"register-period-ms", &c.fog.registerPeriodS, 1e-3},
                {"register-offset-ms", &c.fog.registerOffsetS, 1e-3},
                {"boxcar-ms", &c.fog.boxcarS, 1e-3},
                {"rate-filter-ms", &c.fog.rateFilterTimeConstantS, 1e-3},
                {"rate-filter-hz", &c.fog.rateFilterNaturalHz, 1.0},
                {"rate-filter-damping", &c.fog.rateFilterDamping, 1.0},
                {"base-tilt-deg", &c.turntable.baseTiltDeg, 1.0},
                {"base-tilt-azimuth-deg", &c.turntable.baseTiltAzimuthDeg, 1.0},
                {"eccentricity-um", &c.encoder.eccentricityUm, 1.0},
                {"eccentricity-radius-mm", &c.encoder.eccentricityRadiusMm, 1.0},
                {"eccentricity-phase-deg", &c.encoder.eccentricityPhaseDeg, 1.0},
                {"lost-table-per-mille", &c.encoder.lostPerMille, 1.0}};
  for (auto& f : fields) {
    FOG_ASSIGN_OR_RETURN(auto v, args.number(f.name, *f.target / f.scale));
    *f.target = v * f.scale;
  }
  // One value for both pairs of adjacent axes (outer-middle, middle-inner).
  FOG_ASSIGN_OR_RETURN(auto nonOrthogonality, args.number("nonorthogonality-arcsec", 0.0));
  c.turntable.nonOrthogonalityArcsec = {nonOrthogonality, nonOrthogonality};
  auto gyroDelay = args.number("gyro-delay-ms", c.fog.ownDelayS() * 1e3);
  auto bits = args.number("counter-bits", c.samplingBoard.counterBits);
  auto start = args.number("counter-start", c.samplingBoard.counterStart);
  for (const auto* r : {&gyroDelay, &bits, &start})
    if (!*r) return r->status();
  c.fog.setOwnDelayS(*gyroDelay * 1e-3);
  if (!(*bits >= 16 && *bits <= 32) || *bits != std::floor(*bits))  // checked before the cast
    return invalidArgument("--counter-bits must be a whole number within 16 .. 32");
  c.samplingBoard.counterBits = static_cast<int>(*bits);
  if (*start < 0 || *start > 4294967295.0) return invalidArgument("--counter-start must be within 0 .. 2^32-1");
  c.samplingBoard.counterStart = static_cast<std::uint32_t>(*start);
  FOG_RETURN_IF_ERROR(c.validate());
  return c;
}

}  // namespace fog::app
