/**
 * \file
 * \brief mavlink_gimbal_emulator: a MAVLink gimbal manager (Gimbal Protocol v2) with its gimbal, on the simulated
 * motion model, over UDP or a pseudo-terminal.
 *
 * Try the mavlink_gimbal backend without a drone, or break it on purpose. SIGUSR1 toggles silence.
 */
#include <cmath>
#include <cstdio>
#include <string>

#include "emulator_main.h"

#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"

namespace
{
const char* PROGRAM = "mavlink_gimbal_emulator";
const char* USAGE = R"(usage: mavlink_gimbal_emulator [options]

A MAVLink gimbal manager (Gimbal Protocol v2) and its two-axis gimbal: heartbeats, GIMBAL_MANAGER_INFORMATION,
GIMBAL_MANAGER_STATUS at 5 Hz, GIMBAL_DEVICE_ATTITUDE_STATUS at the interval asked for (1 Hz until then),
primary control (setpoints from anyone else are ignored), rate setpoints that time out.

Options:
  --host HOST            UDP address to listen on (default 127.0.0.1)
  --port PORT            UDP port (default 14550; 0 = any free port)
  --pty LINK             serve a pseudo-terminal instead, with this symlink to it (115200 baud)
  --system-id N          the manager's system id (default 1)
  --component-id N       the manager's component id (default 1, an autopilot; 154 = a gimbal managing itself)
  --gimbal-device-id N   the gimbal's id in the manager's messages (default 1)
  --vehicle-yaw RAD      the vehicle's heading, sent as delta_yaw (default 0)
  --earth-frame          report the yaw relative to North (YAW_IN_EARTH_FRAME) instead of the vehicle
  --rate-timeout S       a rate setpoint lasts this long unless repeated (default 0.5)
Faults:
  --silent               start silent: ignore everything, send nothing
  --silent-after S       fall silent S seconds after start
  --refuse               deny DO_GIMBAL_MANAGER_CONFIGURE (no one gets primary control)
  --taken-after S        S seconds after start, controller 3/190 takes primary control and keeps it
Signals: SIGUSR1 toggles silence, SIGUSR2 unplugs / replugs the pseudo-terminal; SIGINT / SIGTERM end the program.
  --pid-file PATH        write the program's pid there (for whoever sends the signals)
)";
}  // namespace

int main(int argc, char** argv)
{
  using ptz_action_server::MavlinkGimbalEmulatorConfig;
  MavlinkGimbalEmulatorConfig config;
  config.port = 14550;
  bool silent = false;
  bool refuse = false;
  emulator_main::Schedule schedule;
  emulator_main::parseArguments(
      argc, argv, PROGRAM, USAGE, [&](const std::string& arg, const emulator_main::Value& value) {
        auto id = [&](double min) {
          return static_cast<std::uint8_t>(emulator_main::numberIn(PROGRAM, value(), arg, min, 255, USAGE));
        };
        if (emulator_main::parseListenOption(arg, value, PROGRAM, USAGE, config.host, config.port))
        {
          return true;
        }
        if (arg == "--pty")
        {
          config.transport = ptz_action_server::LinkKind::SERIAL;
          config.line.link = value();
          config.line.baud = 115200;
        }
        else if (arg == "--system-id")
        {
          config.system_id = id(1);
        }
        else if (arg == "--component-id")
        {
          config.component_id = id(1);
        }
        else if (arg == "--gimbal-device-id")
        {
          config.gimbal_device_id = id(1);
        }
        else if (arg == "--vehicle-yaw")
        {
          config.vehicle_yaw = emulator_main::numberIn(PROGRAM, value(), arg, -M_PI, M_PI, USAGE);
        }
        else if (arg == "--earth-frame")
        {
          config.report_earth_frame = true;
        }
        else if (arg == "--rate-timeout")
        {
          config.rate_timeout = emulator_main::numberIn(PROGRAM, value(), arg, 0.01, 60.0, USAGE);
        }
        else if (arg == "--refuse")
        {
          refuse = true;
        }
        else if (arg == "--taken-after")
        {
          schedule.own_fault_after = emulator_main::number(PROGRAM, value(), arg, USAGE);
        }
        else if (!emulator_main::parseFaultOption(arg, value, PROGRAM, USAGE, silent, schedule))
        {
          return false;
        }
        return true;
      });

  const sigset_t signals = emulator_main::blockSignals();
  try
  {
    ptz_action_server::MavlinkGimbalEmulator device(config);
    device.setSilent(silent);
    device.setRefuse(refuse);
    std::printf("%s: manager %u/%u, gimbal %u, on %s %s, yaw in the %s frame%s%s\n", PROGRAM, config.system_id,
                config.component_id, config.gimbal_device_id,
                config.transport == ptz_action_server::LinkKind::UDP ? "udp" : "pty", device.address().c_str(),
                config.report_earth_frame ? "earth" : "vehicle", refuse ? ", refusing control" : "",
                silent ? ", silent" : "");
    std::fflush(stdout);
    emulator_main::Hooks hooks;
    hooks.set_silent = [&device](bool value) { device.setSilent(value); };
    if (config.transport == ptz_action_server::LinkKind::SERIAL)
    {
      hooks.unplug = [&device] { device.unplug(); };
      hooks.replug = [&device] { device.replug(); };
    }
    hooks.own_fault = [&device] {
      device.giveControlTo(3, 190);
      std::printf("%s: controller 3/190 took primary control\n", PROGRAM);
      std::fflush(stdout);
    };
    emulator_main::run(PROGRAM, signals, hooks, schedule, silent);
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "%s: %s\n", PROGRAM, error.what());
    return 1;
  }
  return 0;
}
