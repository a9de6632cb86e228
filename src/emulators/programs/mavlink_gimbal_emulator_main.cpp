/**
 * \file
 * \brief mavlink_gimbal_emulator: MAVLink gimbal managers (Gimbal Protocol v2) with their gimbals (inside the manager,
 * or MAVLink gimbal devices of their own), on the simulated motion model, over UDP or a pseudo-terminal.
 *
 * Try the mavlink_gimbal backend without a drone, or break it on purpose. SIGUSR1 toggles silence.
 */
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "ptz_action_server/emulators/emulator_main.h"
#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"

namespace
{
const char* PROGRAM = "mavlink_gimbal_emulator";
const char* USAGE = R"(usage: mavlink_gimbal_emulator [options]

The gimbal managers (Gimbal Protocol v2) of one vehicle and their two-axis gimbals: heartbeats of every component,
GIMBAL_MANAGER_INFORMATION on request and GIMBAL_MANAGER_STATUS at 5 Hz for each gimbal, GIMBAL_DEVICE_ATTITUDE_STATUS
at the interval asked for (1 Hz until then), primary control per gimbal (DO_GIMBAL_MANAGER_CONFIGURE, param7 the
gimbal's id; setpoints from anyone else are ignored), GIMBAL_MANAGER_SET_PITCHYAW, GIMBAL_MANAGER_SET_ATTITUDE
(quaternion and rates) and DO_GIMBAL_MANAGER_PITCHYAW, rate setpoints that time out.

Where the gimbals are (gimbal_device_id as the protocol defines it):
  a gimbal inside the manager's component (no MAVLink component of its own: one an autopilot drives over PWM, or a
  camera-gimbal that is its own manager) has the id 1..6; its manager sends its attitude with that id.
  A MAVLink gimbal device has its own component id (154, 171..175), which is its id in the manager's messages; it
  sends its own heartbeat and attitude, with gimbal_device_id 0.

Options:
  --host HOST              UDP address to listen on (default 127.0.0.1)
  --port PORT              UDP port (default 14550; 0 = any free port)
  --pty LINK               serve a pseudo-terminal instead, with this symlink to it (115200 baud)
  --system-id N            the vehicle's system id, shared by every component (default 1)
  --component-id N         the component hosting the gimbal manager(s) (default 1, an autopilot; e.g. 154 for a
                           camera-gimbal that is its own manager)
  --gimbals N              N gimbals inside the manager's component (0..6; default 1, or 0 with --device-component)
  --gimbal-device-id N     the id of the first gimbal inside the manager, the next ones counting up (1..6, default 1)
  --device-component C     a MAVLink gimbal device at component C (e.g. 154) managed by the manager; repeatable, for
                           several devices (an autopilot-hosted manager: --component-id 1 --device-component 154)
  --vehicle-yaw RAD        the vehicle's heading, sent as delta_yaw (default 0)
  --earth-frame            report the yaw relative to North (YAW_IN_EARTH_FRAME) instead of the vehicle
Field behaviours:
  --gimbal-v1              an autopilot that speaks only gimbal protocol v1: no gimbal manager (REQUEST_MESSAGE of
                           GIMBAL_MANAGER_INFORMATION answered UNSUPPORTED), the mount's orientation as
                           MOUNT_ORIENTATION
  --gimbal-v1-mount-status the same with ArduPilot's MOUNT_STATUS (and ArduPilot in the autopilot's HEARTBEAT)
  --px4-gimbal-output      PX4's gimbal module on AUX outputs: every attitude says YAW_LOCK (no frame flag) while its
                           yaw is the vehicle's, delta_yaw 0; the vehicle's heading goes out in ATTITUDE
  --drop-earth-frame-flag  setpoints' YAW_IN_EARTH_FRAME is lost, as in PX4 (issue 26569): only YAW_LOCK means North
  --rate-timeout S         a rate setpoint lasts this long unless repeated (default 0.5)
Faults:
  --silent                 start silent: ignore everything, send nothing
  --silent-after S         fall silent S seconds after start
  --refuse                 deny DO_GIMBAL_MANAGER_CONFIGURE (no one gets primary control)
  --held-by SYS/COMP       every gimbal starts under the primary control of SYS/COMP, which yields it to a
                           DO_GIMBAL_MANAGER_CONFIGURE (a ground station that took control earlier)
  --taken-after S          S seconds after start, controller 3/190 takes primary control of every gimbal and keeps it
Signals: SIGUSR1 toggles silence, SIGUSR2 unplugs / replugs the pseudo-terminal; SIGINT / SIGTERM end the program.
  --pid-file PATH          write the program's pid there (for whoever sends the signals)
)";

/// "3/190" as a system and a component id, or fail().
std::pair<std::uint8_t, std::uint8_t> controller(const char* text, const std::string& option)
{
  unsigned system = 0, component = 0;
  char end = 0;
  if (std::sscanf(text, "%u/%u%c", &system, &component, &end) != 2 || system < 1 || system > 255 || component < 1 ||
      component > 255)
  {
    emulator_main::fail(PROGRAM, option + " takes SYS/COMP (each 1..255), not '" + text + "'", USAGE);
  }
  return { static_cast<std::uint8_t>(system), static_cast<std::uint8_t>(component) };
}

/// "gimbals 1, 2 inside 1/1" / "gimbal device 1/154 managed by 1/1", for the start-up line.
std::string describe(const ptz_action_server::MavlinkGimbalEmulatorConfig& config)
{
  std::string text;
  for (const auto& gimbal : config.gimbals)
  {
    const std::string manager = std::to_string(config.system_id) + "/" + std::to_string(config.component_id);
    text += text.empty() ? "" : ", ";
    text += ptz_action_server::mavlink::isInternalGimbalId(gimbal.device_id) ?
                "gimbal " + std::to_string(gimbal.device_id) + " inside the manager " + manager :
                "gimbal device " + std::to_string(config.system_id) + "/" + std::to_string(gimbal.device_id) +
                    " managed by " + manager;
  }
  return text;
}
}  // namespace

int main(int argc, char** argv)
{
  using ptz_action_server::MavlinkEmulatedGimbal;
  using ptz_action_server::MavlinkGimbalEmulatorConfig;
  MavlinkGimbalEmulatorConfig config;
  config.port = 14550;
  bool silent = false;
  bool refuse = false;
  int internal_gimbals = -1;  // not given
  int first_id = 1;
  std::vector<std::uint8_t> device_components;
  std::pair<std::uint8_t, std::uint8_t> held_by{ 0, 0 };
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
        else if (arg == "--gimbals")
        {
          internal_gimbals = static_cast<int>(emulator_main::numberIn(PROGRAM, value(), arg, 0, 6, USAGE));
        }
        else if (arg == "--gimbal-device-id")
        {
          const char* text = value();
          const double number = emulator_main::number(PROGRAM, text, arg, USAGE);
          if (number < 1 || number > ptz_action_server::mavlink::MAX_INTERNAL_GIMBAL_ID)
          {
            emulator_main::fail(PROGRAM,
                                arg + " " + text +
                                    ": a gimbal inside the manager's component has the gimbal_device_id 1..6 "
                                    "(Gimbal Protocol v2); a MAVLink gimbal device of its own is --device-component " +
                                    text,
                                USAGE);
          }
          first_id = static_cast<int>(number);
        }
        else if (arg == "--device-component")
        {
          device_components.push_back(id(ptz_action_server::mavlink::MAX_INTERNAL_GIMBAL_ID + 1));
        }
        else if (arg == "--vehicle-yaw")
        {
          config.vehicle_yaw = emulator_main::numberIn(PROGRAM, value(), arg, -M_PI, M_PI, USAGE);
        }
        else if (arg == "--earth-frame")
        {
          config.report_earth_frame = true;
        }
        else if (arg == "--gimbal-v1")
        {
          config.gimbal_v1 = true;
        }
        else if (arg == "--gimbal-v1-mount-status")
        {
          config.gimbal_v1 = true;
          config.v1_mount_status = true;
        }
        else if (arg == "--px4-gimbal-output")
        {
          config.px4_gimbal_output = true;
        }
        else if (arg == "--drop-earth-frame-flag")
        {
          config.earth_frame_flag_dropped = true;
        }
        else if (arg == "--rate-timeout")
        {
          config.rate_timeout = emulator_main::numberIn(PROGRAM, value(), arg, 0.01, 60.0, USAGE);
        }
        else if (arg == "--refuse")
        {
          refuse = true;
        }
        else if (arg == "--held-by")
        {
          held_by = controller(value(), arg);
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

  if (internal_gimbals < 0)
  {
    internal_gimbals = device_components.empty() ? 1 : 0;
  }
  if (first_id + internal_gimbals - 1 > ptz_action_server::mavlink::MAX_INTERNAL_GIMBAL_ID)
  {
    emulator_main::fail(PROGRAM,
                        "gimbals inside the manager have the ids 1..6: " + std::to_string(internal_gimbals) + " from " +
                            std::to_string(first_id) + " do not fit",
                        USAGE);
  }
  if (internal_gimbals == 0 && device_components.empty())
  {
    emulator_main::fail(PROGRAM, "no gimbal: --gimbals 0 needs a --device-component", USAGE);
  }
  config.gimbals.clear();
  for (int index = 0; index < internal_gimbals; ++index)
  {
    MavlinkEmulatedGimbal gimbal;
    gimbal.device_id = static_cast<std::uint8_t>(first_id + index);
    config.gimbals.push_back(gimbal);
  }
  for (std::uint8_t component : device_components)
  {
    MavlinkEmulatedGimbal gimbal;
    gimbal.device_id = component;
    config.gimbals.push_back(gimbal);
  }

  const sigset_t signals = emulator_main::blockSignals();
  try
  {
    ptz_action_server::MavlinkGimbalEmulator device(config);
    device.setSilent(silent);
    device.setRefuse(refuse);
    if (held_by.first != 0)
    {
      for (std::size_t index = 0; index < device.gimbalCount(); ++index)
      {
        device.giveControlTo(held_by.first, held_by.second, false, index);
      }
    }
    std::printf("%s: %s, on %s %s, yaw in the %s frame%s%s\n", PROGRAM, describe(config).c_str(),
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
      for (std::size_t index = 0; index < device.gimbalCount(); ++index)
      {
        device.giveControlTo(3, 190, true, index);
      }
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
