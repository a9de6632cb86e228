/**
 * \file
 * \brief A FLIR PTU emulator on a pseudo-terminal or TCP: the unit's ASCII protocol over the simulated motion model.
 */
#pragma once

#include <array>
#include <deque>
#include <mutex>
#include <string>

#include "ptz_action_server/core/sim/sim_device_model.h"
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
  double pan_max_speed = 1.5;   ///< rad/s (PU)
  double tilt_max_speed = 1.0;  ///< rad/s (TU)
  double acceleration = 3.0;    ///< rad/s^2 (PA, TA)
  long lower_speed = 31;        ///< positions/s: PL / TL at power-up, and the least they can be set to (a D46)
  long base_speed = 1000;       ///< positions/s: PB / TB at power-up (a D46)
  /// Start verbose, with echo, and print a banner (at power-up on a serial line, to a client that has the port open;
  /// on every connection over TCP, ending `Initializing...*` once the unit is ready), as a real unit does.
  bool banner = true;
  /// `R` restarts the unit as at power-up (on a serial line its banner; echo on and verbose replies again, position
  /// mode, the power-up speeds), then calibrates: for units that do. Off (the default), `R` only calibrates and keeps
  /// every mode and setting, as the published drivers expect (they read `!T!T!P!P*` and go on terse, without echo).
  bool reset_as_power_up = false;
};

/// A command as it reached the unit.
struct ReceivedCommand
{
  TimePoint at;      ///< when its last byte had crossed the line
  std::string text;  ///< upper case, without the delimiter
};

/**
 * \brief Speaks the FLIR PTU protocol (published-wire-facts.md section 3) on a pseudo-terminal or TCP.
 *
 * Starts like a unit at power-up: echo on (each command is echoed as it arrives, a CR or LF delimiter as a line
 * break), verbose replies, position mode; on a serial line its banner is lost unless a client has the port open
 * then, as on a real line. Replies end CR LF. Understands FT/FV/F, ED/EE/E, CI/CV/C, PR/TR, PN/PX/TN/TX, PU/TU,
 * PL/TL, PB/TB, PA/TA, PP/TP (query, absolute), PO/TO (relative), PS/TS (speed; signed velocity in CV mode),
 * H/HP/HT, LE/LD, R and RE (the reset calibration): the calibration runs each axis to both its limits and home, then
 * answers `!T!T!P!P*` (CR LF); the unit reads nothing meanwhile, and keeps its modes (terse or verbose, echo, control
 * mode) and settings, so a driver that reads those 9 bytes goes on as before. With
 * FlirPtuEmulatorConfig::reset_as_power_up, `R` first restarts the unit as at power-up (banner, echo, verbose). The
 * banner comes only at power-up (reaching a client that has the serial port open then) and on a new TCP connection.
 * Anything else is answered `! Illegal Command`. Reports `!P` / `!T` when a velocity move reaches a limit.
 */
class FlirPtuEmulator : public LineEmulator<ReceivedCommand>
{
public:
  explicit FlirPtuEmulator(const FlirPtuEmulatorConfig& config);
  ~FlirPtuEmulator() override;

  /// What the unit received, classified (flir_ptu_emulator_classify.cpp): halts, questions (PP, TP, PR, ...), the
  /// mode, speed, offset and position commands that move it, set-up; each with its characters' and delimiter's wire
  /// time.
  std::vector<ClassifiedCommand> classify() const;

private:
  /// One leg of the reset calibration: \p axis runs to \p target, then the unit says \p report.
  struct CalibrationStep
  {
    Axis axis;
    long target;  ///< positions
    const char* report;
  };

  void onBytes(const std::uint8_t* data, std::size_t size, TimePoint arrived_at);
  void onTick();
  /// Echoes \p character as the unit does (a CR or LF delimiter as one line break).
  void echo(char character, std::string& out);
  /// Runs one command; returns its reply line without the line end (empty: nothing now).
  std::string execute(const std::string& command, TimePoint at);
  // flir_ptu_emulator_answers.cpp: the reply to each command.
  std::string reply(const std::string& letters, bool has_value, long value, TimePoint at);
  std::string replyToAxisSetting(const std::string& letters, bool has_value, long value, TimePoint at);
  std::string replyToMotion(const std::string& letters, bool has_value, long value, TimePoint at);
  /// Position mode, the power-up speeds, echo on and verbose (unless configured without banner); on a serial line the
  /// banner.
  void powerUp() override;
  /// tcp: an E-series unit greets every connection (echo on, verbose, a banner).
  void greet();
  /// `R` / `RE`: the axes run to their limits and home; the answer comes at the end. Modes and settings stay.
  void startCalibration(TimePoint at);
  /// The calibration's reports due at \p now, appended to \p out.
  void calibrate(TimePoint now, std::string& out);
  long position(Axis axis, TimePoint at);
  double toRadians(Axis axis, long position) const;
  std::size_t axisIndex(Axis axis) const
  {
    return axis == PAN ? 0 : 1;
  }

  const FlirPtuEmulatorConfig config_;
  const double resolution_rad_;

  // Guarded by mutex_.
  bool echo_ = true;
  bool terse_ = false;
  bool velocity_mode_ = false;
  bool limits_enforced_ = true;
  std::array<long, 2> speed_{ { 0, 0 } };         ///< PS / TS setting (positions/s)
  std::array<long, 2> velocity_{ { 0, 0 } };      ///< commanded velocity in CV mode (positions/s)
  std::array<long, 2> lower_speed_{ { 0, 0 } };   ///< PL / TL (positions/s)
  std::array<long, 2> base_speed_{ { 0, 0 } };    ///< PB / TB (positions/s)
  std::array<long, 2> acceleration_{ { 0, 0 } };  ///< PA / TA (positions/s^2), answered, not modelled
  std::array<bool, 2> limit_reported_{ { false, false } };
  std::string token_;
  bool after_cr_ = false;  ///< the last byte echoed was a CR (an LF right after it adds no line break)
  std::deque<CalibrationStep> calibration_;
  TimePoint banner_ready_at_{};  ///< tcp: when the banner's last line goes out (the unit needs a moment)
  bool banner_pending_ = false;
};

}  // namespace ptz_action_server
