/**
 * \file
 * \brief pantilt_emulator: a PanTilt device controller on UDP over the simulated motion model.
 *
 * Try the pantilt backend without hardware, or break the link on purpose. SIGUSR1 toggles silence.
 */
#include <cstdio>
#include <string>

#include "ptz_action_server/emulators/emulator_main.h"
#include "ptz_action_server/emulators/pantilt_emulator.h"

namespace
{
const char* PROGRAM = "pantilt_emulator";
const char* USAGE = R"(usage: pantilt_emulator [options]

A PanTilt device controller on UDP: executes SET_PARAM / COMMAND frames on a simulated pan-tilt unit and reports
its params (a full params frame in reply to every valid datagram, and every --state-period to the last client).
It speaks one wire format; frames of another PanTilt format are counted and dropped, never executed.

Options:
  --host HOST            address to listen on (default 127.0.0.1)
  --port PORT            UDP port (default 5000; 0 = any free port)
  --pty LINK             a serial line instead: SLIP frames (RFC 1055) on a pseudo-terminal, with this symlink to it
  --baud N               the pseudo-terminal's pace, 8N1 (default 115200)
  --format FORMAT        wire format (default seed):
                           seed   the seed's: version bytes 1 0, 7-byte commands, nine params fields
                           v1.0   PanTilt 1.0.x: version bytes 1 0, 15-byte commands with arguments, eleven fields
                           v1.1   PanTilt 1.1.x: as v1.0 under version bytes 1 1
  --state-period S       seconds between unsolicited params frames (default 0.1; 0 = replies only)
  --drop RATIO           drop this share of replies (0..1)
  --delay S              delay every reply by S seconds
  --flood N              send every state N times (1..1000; default 1): a device that reports N times too fast
  --silent               start silent: ignore everything, send nothing (an unplugged device)
  --silent-after S       fall silent S seconds after start
Signals: SIGUSR1 toggles silence, SIGUSR2 unplugs / replugs the pseudo-terminal; SIGINT / SIGTERM end the program.
  --pid-file PATH        write the program's pid there (for whoever sends the signals)
)";
}  // namespace

int main(int argc, char** argv)
{
  ptz_action_server::PanTiltEmulatorConfig config;
  config.port = 5000;
  bool silent = false;
  emulator_main::Schedule schedule;
  double drop = 0.0;
  double delay = 0.0;
  unsigned flood = 1;
  emulator_main::parseArguments(
      argc, argv, PROGRAM, USAGE, [&](const std::string& arg, const emulator_main::Value& value) {
        auto number = [&]() { return emulator_main::number(PROGRAM, value(), arg, USAGE); };
        if (emulator_main::parseListenOption(arg, value, PROGRAM, USAGE, config.host, config.port))
        {
          return true;
        }
        if (arg == "--pty")
        {
          config.serial = true;
          config.line.link = value();
          config.line.baud = 115200;
        }
        else if (arg == "--baud")
        {
          config.line.baud = static_cast<unsigned>(emulator_main::numberIn(PROGRAM, value(), arg, 1200, 921600, USAGE));
        }
        else if (arg == "--format")
        {
          if (!cr::pantilt::parseWireFormat(value(), config.format))
          {
            emulator_main::fail(PROGRAM, "--format must be seed, v1.0 or v1.1", USAGE);
          }
        }
        else if (arg == "--version")
        {
          // "1.0" named two formats that share their version bytes: the choice must be explicit.
          emulator_main::fail(PROGRAM,
                              "--version is replaced by --format: --format seed for what --version 1.0 meant, "
                              "--format v1.1 for --version 1.1, --format v1.0 for a PanTilt 1.0.x device",
                              USAGE);
        }
        else if (arg == "--state-period")
        {
          config.state_period = number();
        }
        else if (arg == "--drop")
        {
          drop = number();
        }
        else if (arg == "--delay")
        {
          delay = number();
        }
        else if (arg == "--flood")
        {
          flood = static_cast<unsigned>(emulator_main::numberIn(PROGRAM, value(), arg, 1, 1000, USAGE));
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
    ptz_action_server::PanTiltEmulator device(config);
    device.setSilent(silent);
    device.setDropRatio(drop);
    device.setReplyDelay(delay);
    device.setFlood(flood);
    const std::string where =
        config.serial ? device.path() + " (SLIP) at " + std::to_string(config.line.baud) + " baud" : device.address();
    std::printf("%s: listening on %s, format %s, state every %.2f s%s%s\n", PROGRAM, where.c_str(),
                cr::pantilt::toString(config.format), config.state_period,
                flood > 1 ? (", each sent " + std::to_string(flood) + " times").c_str() : "", silent ? ", silent" : "");
    std::fflush(stdout);
    emulator_main::Hooks hooks;
    hooks.set_silent = [&device](bool value) { device.setSilent(value); };
    if (config.serial)
    {
      hooks.unplug = [&device] { device.unplug(); };
      hooks.replug = [&device] { device.replug(); };
    }
    emulator_main::run(PROGRAM, signals, hooks, schedule, silent);
    // What it did, so that a client speaking another format shows up here too.
    const ptz_action_server::PanTiltEmulatorCounters counted = device.counters();
    std::uint64_t invalid = 0;
    for (std::uint64_t count : counted.invalid)
    {
      invalid += count;
    }
    const std::uint64_t foreign = counted.dropped(cr::pantilt::DecodeError::FOREIGN_FORMAT);
    std::printf("%s: %llu commands executed, %llu refused, %llu state requests; dropped %llu frames of another "
                "PanTilt format and %llu invalid datagrams\n",
                PROGRAM, static_cast<unsigned long long>(counted.commands_executed),
                static_cast<unsigned long long>(counted.commands_refused),
                static_cast<unsigned long long>(counted.state_requests), static_cast<unsigned long long>(foreign),
                static_cast<unsigned long long>(invalid - foreign));
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "%s: %s\n", PROGRAM, error.what());
    return 1;
  }
  return 0;
}
