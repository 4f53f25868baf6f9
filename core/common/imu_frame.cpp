#include "core/common/imu_frame.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace fog {

namespace {

struct Named {
  ImuFrame::Convention convention;
  const char* code;
  const char* words;
};
constexpr Named kNames[] = {
    {ImuFrame::Convention::kNorthEastDown, "NED", "north-east-down (x north, y east, z down)"},
    {ImuFrame::Convention::kEastNorthUp, "ENU", "east-north-up (x east, y north, z up)"},
    {ImuFrame::Convention::kForwardRightDown, "FRD", "forward-right-down (x forward, y right, z down)"},
    {ImuFrame::Convention::kRightForwardUp, "RFU", "right-forward-up (x right, y forward, z up)"},
};

const Named* named(ImuFrame::Convention c) {
  for (const auto& n : kNames)
    if (n.convention == c) return &n;
  return nullptr;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

}  // namespace

std::optional<double> ImuFrame::xHeadingDeg() const {
  switch (convention) {
    case Convention::kNorthEastDown: return 0.0;
    case Convention::kEastNorthUp: return 90.0;
    case Convention::kForwardRightDown: return forwardHeadingDeg;
    case Convention::kRightForwardUp:
      if (forwardHeadingDeg) return *forwardHeadingDeg + 90.0;
      return std::nullopt;
    case Convention::kUnstated: break;
  }
  return std::nullopt;
}

std::string imuFrameToText(const ImuFrame& frame) {
  const Named* n = named(frame.convention);
  if (!n) return {};
  std::string s = n->code;
  if (frame.forwardHeadingDeg) {
    s += ':';
    s += number(*frame.forwardHeadingDeg);
  }
  return s;
}

Result<ImuFrame> imuFrameFromText(const std::string& text) {
  std::string t;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) t += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  ImuFrame f;
  if (t.empty()) return f;
  const auto colon = t.find(':');
  const std::string code = t.substr(0, colon);
  auto refuse = [&](const std::string& why) {
    return invalidArgument("IMU frame \"" + text + "\": " + why +
                           "; write NED, ENU, FRD[:HEADING] or RFU[:HEADING] (HEADING: azimuth of the IMU's forward "
                           "axis, deg from north toward east), or nothing when it is not known");
  };
  const Named* n = nullptr;
  for (const auto& k : kNames)
    if (code == k.code) n = &k;
  if (!n) return refuse("not a frame convention");
  f.convention = n->convention;
  if (colon != std::string::npos) {
    if (f.convention == ImuFrame::Convention::kNorthEastDown || f.convention == ImuFrame::Convention::kEastNorthUp)
      return refuse(std::string(n->code) + " names its own heading");
    const std::string h = t.substr(colon + 1);
    // Decimal only: strtod would also read "0X1E" as hexadecimal.
    if (h.find_first_not_of("0123456789+-.E") != std::string::npos)
      return refuse("the heading must be a number within [-360, 360]");
    char* end = nullptr;
    const double v = std::strtod(h.c_str(), &end);
    if (h.empty() || end != h.c_str() + h.size() || !std::isfinite(v) || std::abs(v) > 360.0)
      return refuse("the heading must be a number within [-360, 360]");
    f.forwardHeadingDeg = v;
  }
  return f;
}

std::string describeImuFrame(const ImuFrame& frame) {
  const Named* n = named(frame.convention);
  if (!n) return "not stated";
  std::string s = n->words;
  if (frame.forwardHeadingDeg) {
    s += ", forward at ";
    s += number(*frame.forwardHeadingDeg);
    s += " deg from north";
  }
  return s;
}

}  // namespace fog
