#include "core/io/hdf5_export.h"

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <system_error>
#include <vector>

#include "core/common/sha256.h"
#include "core/common/version.h"
#include "core/io/csv_export.h"
#include "core/common/units.h"
#include "core/model/sim_config.h"
#include "core/noise/gyro_noise.h"

namespace fog::io {

namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---- HDF5: every call checked; a failure becomes a Status with HDF5's words.

// The innermost message of HDF5's error stack (its automatic printing is off).
std::string hdf5Message() {
  std::string msg;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_DOWNWARD,
      [](unsigned n, const H5E_error2_t* e, void* data) -> herr_t {
        auto* out = static_cast<std::string*>(data);
        if (n == 0 && e->desc) *out = e->desc;
        return 0;
      },
      &msg);
  return msg.empty() ? "unknown HDF5 error" : msg;
}

// An HDF5 identifier closed when it leaves scope.
class Id {
 public:
  Id(hid_t id, herr_t (*closer)(hid_t)) : id_(id), close_(closer) {}
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  ~Id() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }
  // Closes now, reporting whether the close succeeded (a file's close writes).
  bool close() {
    const herr_t r = id_ >= 0 ? close_(id_) : 0;
    id_ = -1;
    return r >= 0;
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

class Writer {
 public:
  explicit Writer(std::string file) : file_(std::move(file)) {}

  Status fail(const std::string& what) const {
    return ioError("HDF5 export: could not " + what + " for " + file_ + " (HDF5: " + hdf5Message() + ")");
  }

  Result<hid_t> group(hid_t parent, const std::string& name, std::vector<std::unique_ptr<Id>>& keep) {
    auto g = std::make_unique<Id>(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    if (!g->ok()) return fail("create group " + name);
    const hid_t id = g->get();
    keep.push_back(std::move(g));
    return id;
  }

  Status stringAttr(hid_t obj, const char* name, const std::string& value) {
    Id type(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!type.ok() || H5Tset_size(type.get(), H5T_VARIABLE) < 0 || H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
      return fail(std::string("make the string type of attribute ") + name);
    Id space(H5Screate(H5S_SCALAR), H5Sclose);
    Id attr(H5Acreate2(obj, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    const char* p = value.c_str();
    if (!attr.ok() || H5Awrite(attr.get(), type.get(), &p) < 0) return fail(std::string("write attribute ") + name);
    return Status::ok();
  }

  Status numberAttr(hid_t obj, const char* name, double value) { return scalarAttr(obj, name, H5T_NATIVE_DOUBLE, &value); }
  Status intAttr(hid_t obj, const char* name, std::int64_t value) { return scalarAttr(obj, name, H5T_NATIVE_INT64, &value); }

  // A dataset of `dims` (1 or 2 dimensions) of `memType` values, with its unit.
  Status dataset(hid_t parent, const std::string& name, hid_t fileType, hid_t memType, const void* data,
                 std::vector<hsize_t> dims, const std::string& unit) {
    Id space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
    if (!space.ok()) return fail("describe dataset " + name);
    Id set(H5Dcreate2(parent, name.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
           H5Dclose);
    if (!set.ok()) return fail("create dataset " + name);
    hsize_t count = 1;
    for (hsize_t d : dims) count *= d;
    if (count > 0 && H5Dwrite(set.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
      return fail("write dataset " + name);
    return stringAttr(set.get(), "unit", unit);
  }

  Status doubles(hid_t parent, const std::string& name, const std::vector<double>& v, const std::string& unit) {
    return dataset(parent, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, v.data(), {v.size()}, unit);
  }
  Status triples(hid_t parent, const std::string& name, const std::vector<double>& rowMajor, const std::string& unit) {
    return dataset(parent, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, rowMajor.data(), {rowMajor.size() / 3, 3}, unit);
  }
  Status integers(hid_t parent, const std::string& name, const std::vector<std::int64_t>& v, const std::string& unit) {
    return dataset(parent, name, H5T_STD_I64LE, H5T_NATIVE_INT64, v.data(), {v.size()}, unit);
  }
  Status strings(hid_t parent, const std::string& name, const std::vector<std::string>& v) {
    Id type(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!type.ok() || H5Tset_size(type.get(), H5T_VARIABLE) < 0 || H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
      return fail("make the string type of " + name);
    std::vector<const char*> p;
    for (const auto& s : v) p.push_back(s.c_str());
    return dataset(parent, name, type.get(), type.get(), p.data(), {v.size()}, "");
  }

 private:
  Status scalarAttr(hid_t obj, const char* name, hid_t memType, const void* value) {
    Id space(H5Screate(H5S_SCALAR), H5Sclose);
    const hid_t fileType = memType == H5T_NATIVE_DOUBLE ? H5T_IEEE_F64LE : H5T_STD_I64LE;
    Id attr(H5Acreate2(obj, name, fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!attr.ok() || H5Awrite(attr.get(), memType, value) < 0) return fail(std::string("write attribute ") + name);
    return Status::ok();
  }
  std::string file_;
};

std::string pointName(int index) {
  std::string n = std::to_string(index + 1);
  return n.size() < 2 ? "0" + n : n;
}

// fits.csv's rows of one test point, as columns (same doubles, NaN = empty).
Status writeFits(Writer& w, hid_t g, const analysis::TestPointResult& p) {
  struct Col {
    const char* name;
    const char* unit;
    std::vector<double> v;
  };
  std::vector<Col> cols = {{"frequency_hz", "Hz", {}},       {"frequency_std_hz", "Hz", {}},
                           {"period_ms", "ms", {}},           {"period_std_ms", "ms", {}},
                           {"phase_ms", "ms", {}},            {"phase_std_ms", "ms", {}},
                           {"amplitude_deg", "deg", {}},      {"amplitude_std_deg", "deg", {}},
                           {"offset_deg", "deg", {}},         {"trend_deg_per_s", "deg/s", {}},
                           {"trend_std_deg_per_s", "deg/s", {}}, {"residual_rms_deg", "deg", {}},
                           {"chi2_per_dof", "1", {}},         {"lag_ms", "ms", {}},
                           {"lag_std_ms", "ms", {}},          {"magnitude_ratio", "1", {}},
                           {"magnitude_ratio_std", "1", {}}};
  std::vector<std::string> channel, model;
  std::vector<std::int64_t> samples;
  auto push = [&](std::array<double, 17> row) {
    for (std::size_t i = 0; i < row.size(); ++i) cols[i].v.push_back(row[i]);
  };
  auto fit = [&](const char* ch, const char* mo, const analysis::SineFit& f, bool gyro) {
    channel.push_back(ch);
    model.push_back(mo);
    samples.push_back(static_cast<std::int64_t>(f.samples));
    push({f.frequencyHz, f.frequencyStdHz, f.periodMs, f.periodStdMs, f.phaseMs, f.phaseStdMs, f.amplitudeDeg,
          f.amplitudeStdDeg, f.offsetDeg, gyro ? f.trendDegPerS : kNaN, gyro ? f.trendStdDegPerS : kNaN,
          f.residualRmsDeg, f.chiSquarePerDof, kNaN, kNaN, kNaN, kNaN});
  };
  fit("table", "3-parameter", p.tableNominal, false);
  fit("gyro", "3-parameter", p.gyroNominal, true);
  fit("table", "4-parameter", p.tableFit, false);
  fit("gyro", "4-parameter", p.gyroFit, true);
  // The joint row exactly as fits.csv computes it (csv_export.cpp).
  const auto& j = p.joint;
  const double periodMs = j.frequencyHz > 0.0 ? 1e3 / j.frequencyHz : 0.0;
  const double periodStdMs = j.frequencyHz > 0.0 ? 1e3 * j.frequencyStdHz / (j.frequencyHz * j.frequencyHz) : 0.0;
  channel.push_back("table+gyro");
  model.push_back("joint");
  samples.push_back(static_cast<std::int64_t>(p.tableSamples + p.imuSamples));
  push({j.frequencyHz, j.frequencyStdHz, periodMs, periodStdMs, kNaN, kNaN, std::hypot(j.a, j.b), kNaN, j.offsetDeg,
        j.trendDegPerS, j.trendStdDegPerS, kNaN, j.chiSquarePerDof, j.lagS * 1e3, j.lagStdS * 1e3, j.gain,
        j.gainStd});
  FOG_RETURN_IF_ERROR(w.strings(g, "channel", channel));
  FOG_RETURN_IF_ERROR(w.strings(g, "model", model));
  FOG_RETURN_IF_ERROR(w.integers(g, "samples", samples, "1"));
  for (const auto& c : cols) FOG_RETURN_IF_ERROR(w.doubles(g, c.name, c.v, c.unit));
  return Status::ok();
}

Status writePoint(Writer& w, hid_t parent, const TestPointData& data, const analysis::TestPointResult* p) {
  std::vector<std::unique_ptr<Id>> keep;
  FOG_ASSIGN_OR_RETURN(hid_t g, w.group(parent, pointName(data.index), keep));
  FOG_RETURN_IF_ERROR(w.intAttr(g, "test_point", data.index + 1));
  FOG_RETURN_IF_ERROR(w.stringAttr(g, "axis", axisLabel(data.axis)));
  FOG_RETURN_IF_ERROR(w.numberAttr(g, "nominal_frequency_hz", data.nominalFrequencyHz));
  FOG_RETURN_IF_ERROR(w.numberAttr(g, "nominal_amplitude_deg", data.nominalAmplitudeDeg));
  FOG_RETURN_IF_ERROR(w.stringAttr(g, "kind", data.kind == TestPointKind::kStatic ? "static" : "swing"));
  {
    FOG_ASSIGN_OR_RETURN(hid_t t, w.group(g, "table", keep));
    std::vector<double> time, angle;
    time.reserve(data.table.size());
    angle.reserve(data.table.size() * 3);
    for (const auto& s : data.table) {
      time.push_back(s.timeS);
      angle.insert(angle.end(), s.angleDeg.begin(), s.angleDeg.end());
    }
    FOG_RETURN_IF_ERROR(w.doubles(t, "time_s", time, "s"));
    FOG_RETURN_IF_ERROR(w.triples(t, "angle_deg", angle, "deg"));
  }
  {
    FOG_ASSIGN_OR_RETURN(hid_t t, w.group(g, "gyro", keep));
    std::vector<double> time, inc, temp;
    std::vector<std::int64_t> lost;
    time.reserve(data.imu.size());
    inc.reserve(data.imu.size() * 3);
    for (const auto& s : data.imu) {
      time.push_back(s.timeS);
      inc.insert(inc.end(), s.incrementDeg.begin(), s.incrementDeg.end());
      temp.push_back(s.temperatureC);
      lost.push_back(s.lostBefore);
    }
    FOG_RETURN_IF_ERROR(w.doubles(t, "time_s", time, "s"));
    FOG_RETURN_IF_ERROR(w.triples(t, "increment_deg", inc, "deg"));
    FOG_RETURN_IF_ERROR(w.doubles(t, "temperature_c", temp, "degC"));
    FOG_RETURN_IF_ERROR(w.integers(t, "lost_before", lost, "frames"));
  }
  if (!p) return Status::ok();
  {
    FOG_ASSIGN_OR_RETURN(hid_t f, w.group(g, "fits", keep));
    FOG_RETURN_IF_ERROR(writeFits(w, f, *p));
  }
  {
    FOG_ASSIGN_OR_RETURN(auto r, exportResiduals(data, *p));
    FOG_ASSIGN_OR_RETURN(hid_t t, w.group(g, "residuals", keep));
    FOG_RETURN_IF_ERROR(w.doubles(t, "table_time_s", r.tableTimeS, "s"));
    FOG_RETURN_IF_ERROR(w.doubles(t, "table_residual_deg", r.tableResidualDeg, "deg"));
    FOG_RETURN_IF_ERROR(w.doubles(t, "gyro_time_s", r.gyroTimeS, "s"));
    FOG_RETURN_IF_ERROR(w.doubles(t, "gyro_residual_deg", r.gyroResidualDeg, "deg"));
  }
  {
    FOG_ASSIGN_OR_RETURN(hid_t t, w.group(g, "period_track", keep));
    std::vector<double> time, lag, amp;
    for (const auto& d : p->periodTrack) {
      time.push_back(d.timeS);
      lag.push_back(d.lagMs);
      amp.push_back(d.tableAmplitudeDeg);
    }
    FOG_RETURN_IF_ERROR(w.doubles(t, "time_s", time, "s"));
    FOG_RETURN_IF_ERROR(w.doubles(t, "lag_ms", lag, "ms"));
    FOG_RETURN_IF_ERROR(w.doubles(t, "table_amplitude_deg", amp, "deg"));
    FOG_RETURN_IF_ERROR(w.numberAttr(t, "mean_lag_ms", p->periodMeanLagMs));
    FOG_RETURN_IF_ERROR(w.numberAttr(t, "scatter_ms", p->periodScatterMs));
  }
  return Status::ok();
}

Status scalar(Writer& w, hid_t g, const std::string& name, double v, const std::string& unit) {
  return w.doubles(g, name, std::vector<double>{v}, unit);
}

// One static segment's gyro noise, under the names `noise --json` uses: the
// Allan curve and each IEEE 952 term in its customary and its SI unit.
Status writeNoise(Writer& w, hid_t parent, const noise::GyroNoiseReport& r) {
  std::vector<std::unique_ptr<Id>> keep;
  char name[32];
  std::snprintf(name, sizeof name, "segment_%02d", r.testPointIndex + 1);
  FOG_ASSIGN_OR_RETURN(hid_t g, w.group(parent, name, keep));
  FOG_RETURN_IF_ERROR(w.stringAttr(g, "axis", axisName(r.gyroAxis)));
  FOG_RETURN_IF_ERROR(w.integers(g, "test_point", {r.testPointIndex + 1}, "1"));
  FOG_RETURN_IF_ERROR(scalar(w, g, "duration_s", r.durationS, "s"));
  FOG_RETURN_IF_ERROR(scalar(w, g, "interval_s", r.intervalS, "s"));
  FOG_RETURN_IF_ERROR(scalar(w, g, "bias_deg_h", r.biasDegPerH, "deg/h"));
  FOG_RETURN_IF_ERROR(scalar(w, g, "bias_std_deg_h", r.biasStdDegPerH, "deg/h"));
  FOG_RETURN_IF_ERROR(scalar(w, g, "earth_rate_deg_h", r.earthRateDegPerH, "deg/h"));
  FOG_RETURN_IF_ERROR(scalar(w, g, "earth_corrected_bias_deg_h", r.earthCorrectedBiasDegPerH, "deg/h"));
  FOG_RETURN_IF_ERROR(scalar(w, g, "confidence", r.curve.confidence, "1"));
  {
    FOG_ASSIGN_OR_RETURN(hid_t a, w.group(g, "allan", keep));
    std::vector<double> tau, adev, low, high, edf;
    for (const auto& p : r.curve.points) {
      tau.push_back(p.tauS);
      adev.push_back(p.deviation * kSecondsPerHour);
      low.push_back(p.interval.low * kSecondsPerHour);
      high.push_back(p.interval.high * kSecondsPerHour);
      edf.push_back(p.edf);
    }
    FOG_RETURN_IF_ERROR(w.doubles(a, "tau_s", tau, "s"));
    FOG_RETURN_IF_ERROR(w.doubles(a, "adev_deg_h", adev, "deg/h"));
    FOG_RETURN_IF_ERROR(w.doubles(a, "low_deg_h", low, "deg/h"));
    FOG_RETURN_IF_ERROR(w.doubles(a, "high_deg_h", high, "deg/h"));
    FOG_RETURN_IF_ERROR(w.doubles(a, "edf", edf, "1"));
  }
  FOG_ASSIGN_OR_RETURN(hid_t terms, w.group(g, "terms", keep));
  for (const auto& t : r.model.terms) {
    FOG_ASSIGN_OR_RETURN(hid_t k, w.group(terms, noise::noiseTermKey(t.kind), keep));
    const auto u = noise::termInGyroUnits(t);
    const auto si = noise::termInSiUnits(t);
    FOG_RETURN_IF_ERROR(scalar(w, k, "value", u.value, u.unit));
    FOG_RETURN_IF_ERROR(scalar(w, k, "std", u.stdError, u.unit));
    FOG_RETURN_IF_ERROR(scalar(w, k, "value_si", si.value, si.unit));
    FOG_RETURN_IF_ERROR(scalar(w, k, "std_si", si.stdError, si.unit));
    FOG_RETURN_IF_ERROR(scalar(w, k, "tau_low_s", t.tauLowS, "s"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "tau_high_s", t.tauHighS, "s"));
  }
  return Status::ok();
}

// A response model parameter's unit, by its name (frequency_response.h).
std::string parameterUnit(const std::string& name) {
  if (name.size() > 3 && name.compare(name.size() - 3, 3, "_ms") == 0) return "ms";
  if (name.size() > 3 && name.compare(name.size() - 3, 3, "_hz") == 0) return "Hz";
  return "1";  // K, zeta
}

// One axis' frequency response, under the names `response --json` uses.
Status writeResponse(Writer& w, hid_t parent, const analysis::ResponseAnalysis& r) {
  std::vector<std::unique_ptr<Id>> keep;
  FOG_ASSIGN_OR_RETURN(hid_t g, w.group(parent, axisName(r.axis), keep));
  FOG_RETURN_IF_ERROR(w.numberAttr(g, "group_delay_at_hz", r.groupDelayAtHz));
  FOG_RETURN_IF_ERROR(w.stringAttr(g, "chosen_model", r.chosen >= 0 ? analysis::responseModelName(
                                                                          r.models[static_cast<std::size_t>(r.chosen)].kind)
                                                                    : ""));
  FOG_RETURN_IF_ERROR(w.stringAttr(g, "no_model_reason", r.chosen >= 0 ? "" : r.noModelReason));
  FOG_RETURN_IF_ERROR(w.numberAttr(g, "adequacy_p_threshold", analysis::kModelAdequacyP));
  FOG_RETURN_IF_ERROR(w.strings(g, "skipped_models", r.skipped));
  {
    FOG_ASSIGN_OR_RETURN(hid_t pg, w.group(g, "points", keep));
    std::vector<std::int64_t> index;
    std::vector<double> f, m, ms, db, dbs, ph, phs, lag, lags, cov, harm;
    // The phase against the table's motion and its budget (certifiedPhase), as `response --json`.
    std::vector<double> motion, u, ud, k, bigU, bigUms;
    for (const auto& p : r.points) {
      const analysis::CertifiedPhase c = analysis::certifiedPhase(p, r);
      motion.push_back(c.phaseDeg);
      u.push_back(c.standardDeg);
      ud.push_back(c.readDelayStdDeg);
      k.push_back(c.coverageK);
      bigU.push_back(c.expandedDeg);
      bigUms.push_back(c.expandedMs);
      index.push_back(p.index + 1);
      f.push_back(p.frequencyHz);
      m.push_back(p.magnitude);
      ms.push_back(p.magnitudeStd);
      db.push_back(p.magnitudeDb);
      dbs.push_back(p.magnitudeDbStd);
      ph.push_back(p.phaseDeg);
      phs.push_back(p.phaseStdDeg);
      lag.push_back(p.lagMs);
      lags.push_back(p.lagStdMs);
      cov.push_back(p.magnitudePhaseCovDeg);
      harm.push_back(p.harmonicFraction);
    }
    FOG_RETURN_IF_ERROR(w.integers(pg, "test_point", index, "1"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "frequency_hz", f, "Hz"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "magnitude", m, "1"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "magnitude_std", ms, "1"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "magnitude_db", db, "dB"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "magnitude_db_std", dbs, "dB"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "phase_deg", ph, "deg"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "phase_std_deg", phs, "deg"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "lag_ms", lag, "ms"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "lag_std_ms", lags, "ms"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "magnitude_phase_cov_deg", cov, "deg"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "harmonic_fraction", harm, "1"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "phase_vs_table_motion_deg", motion, "deg"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "phase_standard_uncertainty_deg", u, "deg"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "phase_read_delay_std_deg", ud, "deg"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "coverage_factor", k, "1"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "phase_expanded_uncertainty_deg", bigU, "deg"));
    FOG_RETURN_IF_ERROR(w.doubles(pg, "phase_expanded_uncertainty_ms", bigUms, "ms"));
  }
  {
    FOG_ASSIGN_OR_RETURN(hid_t lg, w.group(g, "left_out", keep));
    std::vector<std::int64_t> index;
    std::vector<double> f;
    std::vector<std::string> reason;
    for (const auto& p : r.leftOut) {
      index.push_back(p.index + 1);
      f.push_back(p.frequencyHz);
      reason.push_back(p.reason);
    }
    FOG_RETURN_IF_ERROR(w.integers(lg, "test_point", index, "1"));
    FOG_RETURN_IF_ERROR(w.doubles(lg, "frequency_hz", f, "Hz"));
    FOG_RETURN_IF_ERROR(w.strings(lg, "reason", reason));
  }
  FOG_ASSIGN_OR_RETURN(hid_t mg, w.group(g, "models", keep));
  for (const auto& m : r.models) {
    FOG_ASSIGN_OR_RETURN(hid_t k, w.group(mg, analysis::responseModelName(m.kind), keep));
    FOG_RETURN_IF_ERROR(scalar(w, k, "chi_square", m.chiSquare, "1"));
    FOG_RETURN_IF_ERROR(w.integers(k, "dof", {m.dof}, "1"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "aic", m.aic, "1"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "bic", m.bic, "1"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "p_value", m.pValue, "1"));
    FOG_RETURN_IF_ERROR(w.integers(k, "adequate", {m.adequate ? 1 : 0}, "1"));
    FOG_RETURN_IF_ERROR(w.integers(k, "admissible", {m.admissible() ? 1 : 0}, "1"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "low_frequency_delay_ms", m.lowFrequencyDelayMs.value, "ms"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "low_frequency_delay_std_ms", m.lowFrequencyDelayMs.stdDev, "ms"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "group_delay_ms", m.groupDelayMs.value, "ms"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "group_delay_std_ms", m.groupDelayMs.stdDev, "ms"));
    // NaN: the pure delay has no bandwidth (`response --json`: null).
    FOG_RETURN_IF_ERROR(scalar(w, k, "bandwidth_hz", m.bandwidthHz ? m.bandwidthHz->value : kNaN, "Hz"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "bandwidth_std_hz", m.bandwidthHz ? m.bandwidthHz->stdDev : kNaN, "Hz"));
    FOG_RETURN_IF_ERROR(w.strings(k, "notes", m.notes));
    FOG_RETURN_IF_ERROR(w.strings(k, "inadmissible", m.inadmissible));
    FOG_ASSIGN_OR_RETURN(hid_t pg, w.group(k, "parameters", keep));
    for (const auto& p : m.parameters) {
      FOG_RETURN_IF_ERROR(scalar(w, pg, p.name, p.value, parameterUnit(p.name)));
      FOG_RETURN_IF_ERROR(scalar(w, pg, p.name + "_std", p.stdDev, parameterUnit(p.name)));
    }
    // The parameters' correlation, row-major, in `parameters`' order.
    const auto n = static_cast<std::size_t>(m.correlation.rows());
    std::vector<double> corr;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < static_cast<std::size_t>(m.correlation.cols()); ++j)
        corr.push_back(m.correlation(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
    FOG_RETURN_IF_ERROR(w.dataset(k, "correlation", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, corr.data(),
                                  {n, static_cast<hsize_t>(m.correlation.cols())}, "1"));
  }
  return Status::ok();
}

// The shown result: its verdict and reasons as judgeShown gives them, and per
// point delays.csv's numbers beside the point's verdict, so a refused delay
// never appears without its mark.
Status writeResult(Writer& w, hid_t root, const Hdf5ExportInput& in) {
  std::vector<std::unique_ptr<Id>> keep;
  FOG_ASSIGN_OR_RETURN(hid_t g, w.group(root, "result", keep));
  const session::ShownVerdict none;
  const auto& v = in.shown ? *in.shown : none;
  FOG_RETURN_IF_ERROR(w.stringAttr(g, "verdict", session::shownVerdictName(v.verdict)));
  FOG_RETURN_IF_ERROR(w.stringAttr(g, "data_verdict", session::shownVerdictName(v.dataVerdict)));
  FOG_RETURN_IF_ERROR(w.intAttr(g, "stored", v.stored ? 1 : 0));
  FOG_RETURN_IF_ERROR(w.numberAttr(g, "limit_ms", v.limitMs));
  FOG_RETURN_IF_ERROR(w.stringAttr(g, "incomplete_reason", v.incompleteReason));
  FOG_RETURN_IF_ERROR(w.strings(g, "reasons", v.reasons));

  const BenchConstants* c = in.constants ? in.constants : in.report ? &in.report->constants : nullptr;
  if (c) {
    FOG_ASSIGN_OR_RETURN(hid_t k, w.group(g, "constants", keep));
    FOG_RETURN_IF_ERROR(scalar(w, k, "table_read_delay_ms", c->tableReadDelayMs, "ms"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "table_read_delay_std_ms", c->tableReadDelayStdMs, "ms"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "processing_board_delay_ms", c->boardDelayMs, "ms"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "processing_board_delay_std_ms", c->boardDelayStdMs, "ms"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "latitude_deg", c->latitudeDeg, "deg"));
    FOG_RETURN_IF_ERROR(scalar(w, k, "gain_tolerance_fraction", c->gainToleranceFraction, "1"));
    FOG_RETURN_IF_ERROR(w.integers(k, "gyro_sign", {c->gyroSign[0], c->gyroSign[1], c->gyroSign[2]}, "1"));
  }
  if (!in.report) return Status::ok();
  // delays.csv's rows (session::delayBreakdownCsv), one entry a test point.
  FOG_ASSIGN_OR_RETURN(hid_t pg, w.group(g, "points", keep));
  const auto& rc = in.report->constants;
  std::vector<std::int64_t> index;
  std::vector<std::string> axis, verdict, dataVerdict, reason;
  std::vector<std::int64_t> vouched;
  std::vector<double> freq, lag, lagStd, tr, trStd, imu, imuStd, board, boardStd, gyro, gyroStd;
  for (const auto& p : in.report->points) {
    session::ShownPoint shown;  // a point the verdict does not state: refused (as delays.csv)
    if (const auto* sp = v.point(p.index)) shown = *sp;
    index.push_back(p.index + 1);
    axis.push_back(axisLabel(p.axis));
    freq.push_back(p.nominalFrequencyHz);
    lag.push_back(p.lagMs);
    lagStd.push_back(p.lagStdMs);
    tr.push_back(rc.tableReadDelayMs);
    trStd.push_back(rc.tableReadDelayStdMs);
    imu.push_back(p.imuDelayMs);
    imuStd.push_back(p.imuDelayStdMs);
    board.push_back(rc.boardDelayMs);
    boardStd.push_back(rc.boardDelayStdMs);
    gyro.push_back(p.gyroDelayMs);
    gyroStd.push_back(p.gyroDelayStdMs);
    verdict.push_back(session::shownVerdictName(shown.verdict));
    dataVerdict.push_back(session::shownVerdictName(shown.dataVerdict));
    vouched.push_back(shown.vouched() ? 1 : 0);
    std::string r;
    for (const auto& s : shown.reasons) r += (r.empty() ? "" : "; ") + s;
    reason.push_back(r);
  }
  FOG_RETURN_IF_ERROR(w.integers(pg, "test_point", index, "1"));
  FOG_RETURN_IF_ERROR(w.strings(pg, "axis", axis));
  FOG_RETURN_IF_ERROR(w.doubles(pg, "frequency_hz", freq, "Hz"));
  FOG_RETURN_IF_ERROR(w.doubles(pg, "measured_lag_ms", lag, "ms"));
  FOG_RETURN_IF_ERROR(w.doubles(pg, "measured_lag_std_ms", lagStd, "ms"));
  FOG_RETURN_IF_ERROR(w.doubles(pg, "table_read_delay_ms", tr, "ms"));
  FOG_RETURN_IF_ERROR(w.doubles(pg, "table_read_delay_std_ms", trStd, "ms"));
  FOG_RETURN_IF_ERROR(w.doubles(pg, "imu_delay_ms", imu, "ms"));
  FOG_RETURN_IF_ERROR(w.doubles(pg, "imu_delay_std_ms", imuStd, "ms"));
  FOG_RETURN_IF_ERROR(w.doubles(pg, "processing_board_delay_ms", board, "ms"));
  FOG_RETURN_IF_ERROR(w.doubles(pg, "processing_board_delay_std_ms", boardStd, "ms"));
  FOG_RETURN_IF_ERROR(w.doubles(pg, "gyro_delay_ms", gyro, "ms"));
  FOG_RETURN_IF_ERROR(w.doubles(pg, "gyro_delay_std_ms", gyroStd, "ms"));
  FOG_RETURN_IF_ERROR(w.strings(pg, "verdict", verdict));
  FOG_RETURN_IF_ERROR(w.strings(pg, "data_verdict", dataVerdict));
  FOG_RETURN_IF_ERROR(w.integers(pg, "vouched", vouched, "1"));
  FOG_RETURN_IF_ERROR(w.strings(pg, "reason", reason));
  return Status::ok();
}

// Builds the file in memory (HDF5's core driver, no backing store) and returns
// its bytes. Why not let HDF5 write the disk file itself: when a write fails
// there (disk full), HDF5 1.10 keeps the file open with its unwritten cache,
// and its exit handler then crashes trying to flush it again. In memory, no
// HDF5 call can meet a disk error; the bytes are written with plain stdio.
Result<std::vector<unsigned char>> buildImage(const std::string& tmp, const Hdf5ExportInput& in,
                                              const std::string& metadataJson, const std::string& sha) {
  Writer w(tmp);
  Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!fapl.ok() || H5Pset_fapl_core(fapl.get(), std::size_t{4} << 20, false) < 0)
    return w.fail("set up the in-memory file");
  Id file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
  if (!file.ok()) return w.fail("create the file");
  const hid_t root = file.get();
  FOG_RETURN_IF_ERROR(w.stringAttr(root, "format", "fogbench-hdf5"));
  FOG_RETURN_IF_ERROR(w.intAttr(root, "format_version", 1));
  FOG_RETURN_IF_ERROR(w.stringAttr(root, "session_sha256", sha));
  FOG_RETURN_IF_ERROR(w.stringAttr(root, "session_file", in.sessionPath));
  FOG_RETURN_IF_ERROR(w.stringAttr(root, "fogbench_version", FOG_VERSION));
  FOG_RETURN_IF_ERROR(w.stringAttr(root, "source", in.source));
  // The unit's identity at the top, where a lab's indexer looks first (also
  // in /metadata's json); "" when the session states none.
  FOG_RETURN_IF_ERROR(w.stringAttr(root, "imu_model", in.info->imuModel));
  FOG_RETURN_IF_ERROR(w.stringAttr(root, "imu_serial", in.info->imuSerial));
  FOG_RETURN_IF_ERROR(w.stringAttr(root, "lot", in.info->lot));
  FOG_RETURN_IF_ERROR(w.stringAttr(root, "bench_id", in.info->benchId));
  {
    std::vector<std::unique_ptr<Id>> keep;
    FOG_ASSIGN_OR_RETURN(hid_t m, w.group(root, "metadata", keep));
    FOG_RETURN_IF_ERROR(w.stringAttr(m, "json", metadataJson));
    FOG_RETURN_IF_ERROR(writeResult(w, root, in));
    FOG_ASSIGN_OR_RETURN(hid_t tps, w.group(root, "test_points", keep));
    for (const auto& data : in.recording->testPoints) {
      const analysis::TestPointResult* p = nullptr;
      if (in.report)
        for (const auto& r : in.report->points)
          if (r.index == data.index) p = &r;
      FOG_RETURN_IF_ERROR(writePoint(w, tps, data, p));
    }
    if (in.responses && !in.responses->empty()) {
      FOG_ASSIGN_OR_RETURN(hid_t rg, w.group(root, "response", keep));
      for (const auto& r : *in.responses) FOG_RETURN_IF_ERROR(writeResponse(w, rg, r));
    }
    if (in.noise && !in.noise->empty()) {
      FOG_ASSIGN_OR_RETURN(hid_t ng, w.group(root, "noise", keep));
      for (const auto& r : *in.noise) FOG_RETURN_IF_ERROR(writeNoise(w, ng, r));
    }
    if (in.report)
      for (const auto& r : in.report->points) {
        bool found = false;
        for (const auto& d : in.recording->testPoints) found = found || d.index == r.index;
        if (!found)
          return invalidArgument("the report has test point " + std::to_string(r.index + 1) +
                                 ", which the recording does not; export the report with its own recording");
      }
  }
  if (H5Fflush(root, H5F_SCOPE_GLOBAL) < 0) return w.fail("finish the file");
  const ssize_t size = H5Fget_file_image(root, nullptr, 0);
  if (size < 0) return w.fail("take the file's image");
  std::vector<unsigned char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(root, image.data(), image.size()) != size) return w.fail("take the file's image");
  if (!file.close()) return w.fail("close the file");
  return image;
}

}  // namespace

Hdf5Extras hdf5Extras(const Recording& recording, const analysis::DelayReport* report, const BenchConstants& bench) {
  Hdf5Extras extras;
  if (report) extras.responses = analysis::analyzeResponses(*report, analysis::kDefaultGroupDelayAtHz);
  noise::GyroNoiseOptions options;
  options.earth.latitudeDeg = bench.latitudeDeg;
  model::applyImuFrame(bench.imuFrame, options.earth);
  if (auto reports = noise::analyzeGyroNoise(recording, options)) extras.noise = std::move(*reports);
  return extras;
}


Status exportHdf5(const std::string& path, const Hdf5ExportInput& in, bool overwrite) {
  if (!in.info || !in.recording) return invalidArgument("HDF5 export: no session to export");
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (!ec && fs::exists(st)) {
    if (fs::is_directory(st)) return invalidArgument(path + " is a folder; give the HDF5 file's name");
    if (!overwrite) return invalidArgument(path + " already exists; allow overwriting to replace it");
  }
  FOG_ASSIGN_OR_RETURN(auto metadataJson, exportMetadataJson(*in.info, *in.recording));
  std::string sha;
  if (!in.sessionPath.empty()) {
    FOG_ASSIGN_OR_RETURN(sha, sha256OfFile(in.sessionPath));
  }

  // HDF5 prints its error stack on stderr by default; the Status says it.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  // The temporary file: created exclusively (O_EXCL; mode 0666 less the
  // umask, as any new file), so that a file already named OUT.h5.partial,
  // which is not ours, is never truncated: the next free OUT.h5.N.partial.
  std::string tmp;
  int fd = -1;
  for (int i = 0; i < 100 && fd < 0; ++i) {
    tmp = path + (i == 0 ? std::string() : "." + std::to_string(i)) + ".partial";
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST)
      return ioError("cannot create " + tmp + ": " + std::strerror(errno) +
                     "; check that the folder exists and is writable");
  }
  if (fd < 0)
    return ioError("cannot create a temporary file beside " + path + ": " + tmp +
                   " and 99 others exist (left by failed exports?); remove them");
  std::FILE* f = ::fdopen(fd, "wb");
  if (!f) {
    const int err = errno;
    ::close(fd);
    std::error_code ignored;
    fs::remove(tmp, ignored);
    return ioError("cannot write " + tmp + ": " + std::strerror(err));
  }
  Status s = Status::ok();
  if (auto image = buildImage(tmp, in, metadataJson, sha); !image.isOk()) {
    s = image.status();
    std::fclose(f);
  } else {
    const bool written = std::fwrite(image.value().data(), 1, image.value().size(), f) == image.value().size();
    const int err = errno;
    const bool closed = std::fclose(f) == 0;
    if (!written || !closed)
      s = ioError("could not write all of " + tmp + " (" + std::strerror(written ? errno : err) + "; disk full?); " +
                  path + " was not written");
  }
  if (s.isOk()) {
    fs::rename(tmp, path, ec);
    if (ec) s = ioError("cannot rename " + tmp + " to " + path + ": " + ec.message());
  }
  if (!s.isOk()) fs::remove(tmp, ec);  // never leave a partial file behind
  return s;
}

}  // namespace fog::io
