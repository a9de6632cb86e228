/**
 * \file
 * \brief A Pelco-D camera emulator on a pseudo-terminal, over the simulated motion model.
 */
#pragma once

#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "ptz_action_server/core/pelco_d/pelco_d_codec.h"
#include "ptz_action_server/core/sim/sim_device_model.h"
#include "ptz_action_server/emulators/line_emulator.h"

namespace ptz_action_server
{
struct PelcoDEmulatorConfig
{
  DevicePortConfig port;  ///< a pseudo-terminal (RS-485), or a TCP server (a serial-to-Ethernet server)
  std::uint8_t address = 1;
  pelco::TiltEncoding tilt_encoding = pelco::TiltEncoding::DOWN_POSITIVE;  ///< the Pelco manual's
  bool general_reply = false;  ///< answer every non-query command with a 4-byte general reply
  /// pan +-pi, tilt +-pi/2, zoom 1..24; each axis' max speed is its speed at 0x3F.
  SimDeviceConfig device = SimDeviceConfig::defaults();
  std::uint16_t zoom_position_max = 0xFFFF;
  /// rad/s of a pan speed byte above 0x3F (a turbo byte: 0x40 or 0xFF, by device); 0: the 0x3F speed, as a FLIR
  /// D300E treats any speed above 64.
  double pan_turbo_speed = 0.0;
  /// false: a camera without set-position, as many conference cameras are (the PTZOptics ZCAM G2, ...: their
  /// command tables list the position queries and no 0x4B, 0x4D, 0x4F): it ignores them like any command it does
  /// not know (it stays where it is), and still answers the queries and moves at the speeds it is given.
  bool set_position = true;

  /// The emulator's --mode names: "standard", "no-set-position".
  static constexpr const char* MODES = "standard, no-set-position";
  /// Sets what \p mode plays; false for a name that is none of MODES.
  bool applyMode(const std::string& mode);
};

/// A frame as it reached the device.
struct ReceivedFrame
{
  TimePoint at;  ///< when its last byte had crossed the line
  pelco::Frame frame;
};

/**
 * \brief Speaks Pelco-D on a pseudo-terminal: stop, movement with speeds, the extended absolute position commands
 * (unless PelcoDEmulatorConfig::set_position is false), position queries (answered with 0x59 / 0x5B / 0x5D) and
 * presets. Frames for other addresses are ignored, frames with a bad checksum are counted and dropped.
 */
class PelcoDEmulator : public LineEmulator<ReceivedFrame>
{
public:
  explicit PelcoDEmulator(const PelcoDEmulatorConfig& config);
  ~PelcoDEmulator() override;

  pelco::ParserCounters parserCounters() const;
  /// What the device received, classified (pelco_d_emulator_classify.cpp): position queries, the stop frame, the set
  /// position frames (pan, tilt, zoom) and the rest (drives, presets); each 7 bytes on the wire.
  std::vector<ClassifiedCommand> classify() const;

private:
  /// A partial frame is lost with the power.
  void powerUp() override;
  void onBytes(const std::uint8_t* data, std::size_t size, TimePoint arrived_at);
  /// Executes a frame; returns the reply bytes (empty: none).
  std::vector<std::uint8_t> execute(const pelco::Frame& frame, TimePoint at);

  const PelcoDEmulatorConfig config_;
  // Guarded by mutex_.
  pelco::FrameParser parser_;
  std::map<int, AxisValues> presets_;
};

}  // namespace ptz_action_server
