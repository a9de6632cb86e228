/**
 * \file
 * \brief digiview_emulator: a DigiView emulator (message format 0.5, 1.0, 1.1 or 1.2) with virtual views that slew.
 */
#include <cstdio>
#include <string>

#include "ptz_action_server/emulators/digiview_emulator.h"
#include "ptz_action_server/emulators/emulator_main.h"

namespace
{
const char* PROGRAM = "digiview_emulator";
const char* USAGE = R"(usage: digiview_emulator [options]

Answers as DigiView does (CRC-8/BLUETOOTH over the bytes before the checksum): ACKNOWLEDGEMENT for SET
CAM_TARGETING and CAM_OPTICS_AND_CONTROL (and SYSTEM_STATUS RUNNING / HALT from 1.1 on), CURRENT_PARAMETERS for GETs
and subscriptions (>= 100 ms, 1.2: >= 50 ms; 0 cancels; format 0.5: GET_INTERVAL, later a GET with interval_ms),
CHECKSUM_ERROR, DATA_ERROR, UNKNOWN, FORBIDDEN when told to refuse; QUIT closes the connection.

Options:
  --host HOST            address to listen on (default 127.0.0.1)
  --port PORT            port (default 5500; 0 = any free port)
  --transport tcp|udp    default tcp
  --format F             the message format (msg_defs.hpp revision): 0.5 (80 bytes, 72c80d2; default), 1.0 (88 bytes,
                         interval_ms in the header; 835b28e), 1.1 (1.0 with CAM_TARGETING's detection_id; 305a8ab)
                         or 1.2 (96 bytes, 16-character streams, CAM_TARGETING 13; 1cbc39f)
  --angle-unit U         radians or degrees: the unit of angles and fov on the wire (default: the format's
                         documentation's, radians for 0.5 and 1.0, degrees for 1.1 and 1.2)
  --checksum RULE        required (default) or zero_accepted: a client's checksum byte of 0 is taken unverified
  --unfilled-checksum    send a checksum byte of 0, as a DigiView built on the published helpers (they never fill it)
  --stream NAME          a stream name (default main; repeat for more streams; 1.2: up to 16 characters)
  --layout N             layout mode 0..6 (default 4: four user views)
  --rate R               rad/s a view turns at (default 1.0)
  --acceleration A       rad/s^2 (default 4.0)
  --refuse               answer every SET with FORBIDDEN
  --halted               start halted (1.1, 1.2: SYSTEM_STATUS HALT, views do not move until a client sets RUNNING)
  --silent               start silent: read and ignore everything, send nothing
  --silent-after S       fall silent S seconds after start
Signals: SIGUSR1 toggles silence, SIGUSR2 drops every connection; SIGINT / SIGTERM end the program.
  --pid-file PATH        write the program's pid there (for whoever sends the signals)
)";
}  // namespace

int main(int argc, char** argv)
{
  ptz_action_server::DigiViewEmulatorConfig config;
  config.port = 5500;
  config.streams.clear();
  bool silent = false;
  bool refuse = false;
  bool halted = false;
  std::string angle_unit;
  emulator_main::Schedule schedule;
  emulator_main::parseArguments(
      argc, argv, PROGRAM, USAGE, [&](const std::string& arg, const emulator_main::Value& value) {
        auto number = [&]() { return emulator_main::number(PROGRAM, value(), arg, USAGE); };
        if (emulator_main::parseListenOption(arg, value, PROGRAM, USAGE, config.host, config.port))
        {
          return true;
        }
        if (arg == "--transport")
        {
          config.transport = emulator_main::choice(PROGRAM, value(), arg, { "tcp", "udp" }, USAGE) == "tcp" ?
                                 ptz_action_server::LinkKind::TCP :
                                 ptz_action_server::LinkKind::UDP;
        }
        else if (arg == "--format")
        {
          ptz_action_server::digiview::parseFormat(
              emulator_main::choice(PROGRAM, value(), arg, { "0.5", "1.0", "1.1", "1.2" }, USAGE), config.wire.format);
        }
        else if (arg == "--angle-unit")
        {
          angle_unit = emulator_main::choice(PROGRAM, value(), arg, { "radians", "degrees" }, USAGE);
        }
        else if (arg == "--checksum")
        {
          ptz_action_server::digiview::parseChecksumRule(
              emulator_main::choice(PROGRAM, value(), arg, { "required", "zero_accepted" }, USAGE),
              config.wire.checksum);
        }
        else if (arg == "--unfilled-checksum")
        {
          config.fill_checksum = false;
        }
        else if (arg == "--stream")
        {
          const std::string name = value();
          if (name.empty() || name.size() > ptz_action_server::digiview::MAX_NAME_SIZE)
          {
            emulator_main::fail(PROGRAM, "--stream takes 1 to 16 characters", USAGE);
          }
          config.streams.push_back(name);
        }
        else if (arg == "--layout")
        {
          config.layout_mode = static_cast<std::uint8_t>(emulator_main::numberIn(PROGRAM, value(), arg, 0, 6, USAGE));
        }
        else if (arg == "--rate")
        {
          config.slew_rate = number();
        }
        else if (arg == "--acceleration")
        {
          config.acceleration = number();
        }
        else if (arg == "--refuse")
        {
          refuse = true;
        }
        else if (arg == "--halted")
        {
          halted = true;
        }
        else if (!emulator_main::parseFaultOption(arg, value, PROGRAM, USAGE, silent, schedule))
        {
          return false;
        }
        return true;
      });
  namespace digiview = ptz_action_server::digiview;
  if (config.streams.empty())
  {
    config.streams.push_back("main");
  }
  for (const std::string& name : config.streams)
  {
    if (name.size() > digiview::nameSizeOf(config.wire.format))
    {
      emulator_main::fail(PROGRAM, "--stream takes 1 to 8 characters before format 1.2", USAGE);
    }
  }
  config.wire.angles = digiview::documentedAngleUnit(config.wire.format);
  if (!angle_unit.empty())
  {
    digiview::parseAngleUnit(angle_unit, config.wire.angles);
  }

  const sigset_t signals = emulator_main::blockSignals();
  try
  {
    ptz_action_server::DigiViewEmulator device(config);
    device.setSilent(silent);
    device.setRefuse(refuse);
    device.setHalted(halted);
    std::printf("%s: listening on %s:%u (%s), format %s (%zu-byte messages, angles in %s, checksum %s%s), stream %s, "
                "layout %u%s%s\n",
                PROGRAM, config.host.c_str(), device.port(), ptz_action_server::toString(config.transport),
                digiview::toString(config.wire.format), digiview::layoutOf(config.wire.format).size,
                digiview::toString(config.wire.angles), digiview::toString(config.wire.checksum),
                config.fill_checksum ? "" : ", sent unfilled", config.streams.front().c_str(), config.layout_mode,
                refuse ? ", refusing SETs" : "", device.halted() ? ", halted" : "");
    std::fflush(stdout);
    emulator_main::Hooks hooks;
    hooks.set_silent = [&device](bool value) { device.setSilent(value); };
    // SIGUSR2 drops the connections; the client reconnects, so "replug" has nothing to do.
    hooks.unplug = [&device] { device.dropConnections(); };
    hooks.replug = [] {};
    emulator_main::run(PROGRAM, signals, hooks, schedule, silent);
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "%s: %s\n", PROGRAM, error.what());
    return 1;
  }
  return 0;
}
