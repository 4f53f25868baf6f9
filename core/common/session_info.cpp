#include "core/common/session_info.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace fog {

std::string importSettingsToJson(const ImportSettings& settings) {
  if (settings.empty()) return "";
  nlohmann::ordered_json doc = nlohmann::ordered_json::object();
  if (!settings.gyroRateConvention.empty()) {
    doc["gyro_rate_convention"] = settings.gyroRateConvention;
    if (settings.gyroFramePeriodMs > 0.0) doc["gyro_frame_period_ms"] = settings.gyroFramePeriodMs;
  }
  if (!settings.segmentation.empty()) doc["segmentation"] = settings.segmentation;
  return doc.dump();
}

Result<ImportSettings> importSettingsFromJson(const std::string& text) {
  ImportSettings out;
  if (text.empty()) return out;
  const auto doc = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded() || !doc.is_object()) return corruptData("the import settings are not a JSON object");
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    if (it.key() == "gyro_rate_convention" && it->is_string()) out.gyroRateConvention = it->get<std::string>();
    else if (it.key() == "segmentation" && it->is_string()) out.segmentation = it->get<std::string>();
    else if (it.key() == "gyro_frame_period_ms" && it->is_number() && std::isfinite(it->get<double>()))
      out.gyroFramePeriodMs = it->get<double>();
    else return corruptData("the import settings hold an unknown or mistyped key \"" + it.key() + "\"");
  }
  return out;
}

}  // namespace fog
