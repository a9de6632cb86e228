/**
 * \file
 * \brief What the device emulator programs share: option parsing, the serial and HTTP options, and the signal loop
 * that switches faults. Each program (src/emulators/programs/<name>_main.cpp) adds its own options and device.
 *
 * src/emulators/emulator_main.cpp holds the parsing, the serial options and the loop; emulator_main_http.cpp what
 * only the IP cameras take (HttpCameraOptions and below).
 */
#pragma once

#include <csignal>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>

#include "ptz_action_server/emulators/ports/device_port.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace emulator_main
{
/// Fault switches a program offers; an empty function means "not supported".
struct Hooks
{
  std::function<void(bool)> set_silent;
  std::function<void()> unplug;
  std::function<void()> replug;
  /// A program's own fault, run once at Schedule::own_fault_after (e.g. another controller taking a gimbal).
  std::function<void()> own_fault;
};

/// Timed faults, in seconds from the start (< 0: never).
struct Schedule
{
  double silent_after = -1.0;
  double unplug_after = -1.0;
  double replug_after = -1.0;
  double own_fault_after = -1.0;
};

/// Prints \p message and \p usage to stderr and exits with 2 (a command-line error).
[[noreturn]] void fail(const char* program, const std::string& message, const char* usage);
/// A number >= 0, or fail().
double number(const char* program, const char* text, const std::string& option, const char* usage);
/// A number in [\p min, \p max], or fail() saying so.
double numberIn(const char* program, const char* text, const std::string& option, double min, double max,
                const char* usage);
/// One of \p allowed, or fail() listing them.
std::string choice(const char* program, const char* text, const std::string& option,
                   std::initializer_list<const char*> allowed, const char* usage);
/// roslaunch adds __name:= and remapping arguments; the programs ignore them.
bool isRosArgument(const std::string& argument);

/// Fetches the value of the option being parsed (fails when there is none).
using Value = std::function<const char*()>;

/**
 * \brief Walks the arguments: skips roslaunch's, answers --help with \p usage, writes --pid-file, hands every other
 * option to \p take (which returns false for an option it does not know: an error).
 */
void parseArguments(int argc, char** argv, const char* program, const std::string& usage,
                    const std::function<bool(const std::string& arg, const Value& value)>& take);
/// Takes \p arg if it says where a network emulator listens (--host HOST, --port PORT).
bool parseListenOption(const std::string& arg, const Value& value, const char* program, const char* usage,
                       std::string& host, std::uint16_t& port);
/// Takes \p arg if it is a fault option every emulator has (--silent, --silent-after S).
bool parseFaultOption(const std::string& arg, const Value& value, const char* program, const char* usage, bool& silent,
                      Schedule& schedule);

/// Options every serial emulator takes.
struct SerialOptions
{
  ptz_action_server::DevicePortConfig port;
  Schedule schedule;
  bool silent = false;
  double garble = 0.0;
};

/// The usage text of a serial emulator: its own text, then the serial options with its default link.
std::string serialUsage(const char* own, const char* default_link);
/// Takes \p arg if it is a serial option; \p value fetches its argument.
bool parseSerialOption(const std::string& arg, const Value& value, const char* program, const char* usage,
                       SerialOptions& options);

/// Blocks the signals the loop takes; call before any thread starts, so every thread inherits the mask.
sigset_t blockSignals();

/**
 * \brief Runs until SIGINT or SIGTERM. SIGUSR1 toggles silence, SIGUSR2 unplugs or replugs; the schedule's faults
 * happen on time. Messages go to stdout, flushed, so a test can follow them.
 */
void run(const char* program, const sigset_t& signals, const Hooks& hooks, Schedule schedule, bool silent);

/// A line emulator as runLine() drives it.
struct OpenedLine
{
  std::shared_ptr<void> device;  ///< keeps the emulator alive while the program runs
  ptz_action_server::DevicePort* port = nullptr;
  std::string path;
  std::function<void()> unplug;
  std::function<void()> replug;
};

/**
 * \brief Blocks the signals, opens the device (\p open), applies the options' faults, prints the start-up line (with
 * \p detail appended) and runs the signal loop until SIGINT or SIGTERM. Returns the exit code.
 */
int runLine(const char* program, const SerialOptions& options, const std::string& detail,
            const std::function<OpenedLine()>& open);

/// Runs a line emulator (FlirPtuEmulator, PelcoDEmulator, ViscaEmulator) on the options' port: see runLine().
template <class Device, class Config>
int runSerialDevice(const char* program, Config config, const SerialOptions& options, const std::string& detail)
{
  config.port = options.port;
  return runLine(program, options, detail, [&config] {
    auto device = std::make_shared<Device>(config);
    return OpenedLine{ device, &device->port(), device->path(), [device] { device->unplug(); },
                       [device] { device->replug(); } };
  });
}

/// Options every emulated IP camera takes.
struct HttpCameraOptions
{
  ptz_action_server::HttpCameraServerConfig http;
  Schedule schedule;
  bool silent = false;
  double delay = 0.0;
  unsigned error_status = 0;
  std::string certificate_file;  ///< tls: where to write the certificate ("" = nowhere)
};

/// The fault options and signals every emulated IP camera takes (the end of its usage).
extern const char* const HTTP_FAULTS_HELP;
/// The usage of an IP camera program: its own text, then the HTTP options with its default port, then the faults.
std::string httpCameraUsage(const char* own, unsigned default_port);
/// Takes \p arg if it is an HTTP or fault option.
bool parseHttpCameraOption(const std::string& arg, const Value& value, const char* program, const char* usage,
                           HttpCameraOptions& options);
/// Applies the faults, prints \p start_line, then runs the signal loop until SIGINT / SIGTERM. Returns the exit code.
int runHttpCamera(const char* program, const sigset_t& signals, ptz_action_server::HttpCameraServer& server,
                  const HttpCameraOptions& options, const std::string& start_line);

}  // namespace emulator_main
