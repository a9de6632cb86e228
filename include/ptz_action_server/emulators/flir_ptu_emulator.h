/**
 * \file
 * \brief A FLIR PTU emulator on a pseudo-terminal: the unit's ASCII protocol over the simulated motion model.
 */
#pragma once

#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ptz_action_server/core/sim_device_model.h"
#include "ptz_action_server/emulators/line_emulator.h"

namespace ptz_action_server
{
struct FlirPtuEmulatorConfig
{
  DevicePortConfig port;         ///< a pseudo-terminal (D46, E46 on RS-232) or a TCP server (E-series, port 4000)
  double resolution = 185.1428;  ///< arc seconds per position (a D46), both axes
  long pan_min = -3090;          ///< positions; the unit's pan is counter-clockwise positive
  long pan_max = 3090;
  long tilt_min = -907;
  long tilt_max = 604;
  double pan_max_speed = 1.5;   ///< rad/s
  double tilt_max_speed = 1.0;  ///< rad/s
  double acceleration = 3.0;    ///< rad/s^2
  /// Start verbose, with echo, and print a banner (at power-up on a serial line; on every connection over TCP, ending
  /// `Initializing...*` once the unit is ready), as a real unit does.
  bool banner = true;
};

/// A command as it reached the unit.
struct ReceivedCommand
{
  TimePoint at;      ///< when its last byte had crossed the line
  std::string text;  ///< upper case, without the delimiter
};

/**
 * \brief Speaks the FLIR PTU protocol on a pseudo-terminal.
 *
 * Starts like a unit at power-up: a banner, echo on, verbose replies, position mode. Understands FT/FV, ED/EE,
 * CI/CV, PR/TR, PN/PX/TN/TX, PU/TU, PP/TP (query, absolute), PO/TO (relative), PS/TS (speed; signed velocity in CV
 * mode), PA/TA, H/HP/HT, R, LE/LD; answers anything else with `! Illegal Command`. Reports `!P` / `!T` when a
 * velocity move reaches a limit.
 */
class FlirPtuEmulator : public LineEmulator<ReceivedCommand>
{
public:
  explicit FlirPtuEmulator(const FlirPtuEmulatorConfig& config);
  ~FlirPtuEmulator() override;

private:
  void onBytes(const std::uint8_t* data, std::size_t size, TimePoint arrived_at);
  void onTick();
  void execute(const std::string& command, TimePoint at);
  std::string reply(const std::string& letters, bool has_value, long value, TimePoint at);
  /// Position mode, the default speeds; on a serial line the banner, echo on, verbose.
  void powerUp() override;
  /// tcp: an E-series unit greets every connection (echo on, verbose, a banner).
  void greet();
  long position(Axis axis, TimePoint at);
  double toRadians(Axis axis, long position) const;

  const FlirPtuEmulatorConfig config_;
  const double resolution_rad_;

  // Guarded by mutex_.
  bool echo_ = true;
  bool terse_ = false;
  bool velocity_mode_ = false;
  std::array<long, 2> speed_{ { 0, 0 } };     ///< PS / TS setting (positions/s)
  std::array<long, 2> velocity_{ { 0, 0 } };  ///< commanded velocity in CV mode (positions/s)
  std::array<bool, 2> limit_reported_{ { false, false } };
  std::string token_;
  TimePoint banner_ready_at_{};  ///< tcp: when the banner's last line goes out (the unit needs a moment)
  bool banner_pending_ = false;
};

}  // namespace ptz_action_server
