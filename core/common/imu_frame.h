#pragma once
// The IMU's axes at zero table angles in the local level frame: a lab
// convention that the Earth rate and gravity in the gyros depend on, so it is
// a bench constant, stated by the user and checked against the data by the
// diagnosis (docs/method.md, "Frames").
//
// On a three-axis table the outer axis is vertical at zero angles and each
// gyro axis is its table axis (the analysis checks every swung gyro turns
// with its axis), so a frame is two things: where z points (down or up) and
// the azimuth of x. The named conventions:
//   NED       x north, y east,  z down
//   ENU       x east,  y north, z up
//   FRD[:F]   x forward, y right, z down; forward at azimuth F
//   RFU[:F]   x right, y forward, z up;   forward at azimuth F
// Azimuths in degrees from north toward east. FRD / RFU without F state only
// the vertical (the diagnosis then finds the heading from the data, as for
// an unstated frame).

#include <optional>
#include <string>

#include "core/common/status.h"

namespace fog {

struct ImuFrame {
  enum class Convention { kUnstated, kNorthEastDown, kEastNorthUp, kForwardRightDown, kRightForwardUp };
  Convention convention = Convention::kUnstated;
  std::optional<double> forwardHeadingDeg;  // FRD / RFU only

  bool stated() const { return convention != Convention::kUnstated; }
  // Whether z points up; meaningful only when stated().
  bool zUp() const { return convention == Convention::kEastNorthUp || convention == Convention::kRightForwardUp; }
  // Azimuth of x at zero angles, when the frame states it.
  std::optional<double> xHeadingDeg() const;
  friend bool operator==(const ImuFrame&, const ImuFrame&) = default;
};

// "" (unstated), "NED", "ENU", "FRD", "FRD:30", "RFU", "RFU:-12.5": the one
// text form, in session files, import metadata, the CLI and the GUI.
std::string imuFrameToText(const ImuFrame& frame);
// Reads that form (case-insensitive, spaces ignored); anything else is
// kInvalidArgument naming the accepted forms. A heading must be a finite
// number within [-360, 360].
Result<ImuFrame> imuFrameFromText(const std::string& text);
// For people: "east-north-up (x east, y north, z up)", "not stated".
std::string describeImuFrame(const ImuFrame& frame);

}  // namespace fog
