/**
 * \file
 * \brief pelco_d_emulator: a Pelco-D PTZ camera on a pseudo-terminal, over the simulated motion model.
 */
#include <cstdio>
#include <string>

#include "ptz_action_server/emulators/emulator_main.h"
#include "ptz_action_server/emulators/pelco_d_emulator.h"

namespace
{
const char* PROGRAM = "pelco_d_emulator";
const char* DEFAULT_LINK = "/tmp/ptz_pelco_d";
const char* USAGE = R"(usage: pelco_d_emulator [options]

A Pelco-D PTZ camera (pan +-180, tilt +-90 degrees, zoom 1..24x) on a pseudo-terminal: stop, movement with speeds,
absolute positions (0x4B, 0x4D, 0x4F), position queries (0x51/0x53/0x55 answered with 0x59/0x5B/0x5D) and presets,
paced at the baud rate. Point the node at the link: backend:=pelco_d port:=/tmp/ptz_pelco_d.

Options:
  --address N            the camera's address, 1..255 (default 1)
  --tilt-encoding E      down_positive (the Pelco manual's: 45 below the horizon is 4500, 30 above is 33000;
                         default) or up_positive (30 above is 3000, 45 below is 31500)
  --general-reply        answer every command with a 4-byte general reply
  --turbo-speed R        rad/s of a pan speed byte above 0x3F (turbo); default: the 0x3F speed
  --mode MODE            a camera as found in the field (default standard):
                           standard         takes the set-position commands 0x4B, 0x4D, 0x4F
                           no-set-position  a conference camera without them (the PTZOptics ZCAM G2's command table
                                            lists only the queries): it answers the position queries and moves at a
                                            speed, and ignores a set-position like any command it does not know (it
                                            stays where it is; a general reply only with --general-reply); the node
                                            steers it with pelco_d/set_position: false, or finds it out on the first
                                            goal (auto)
)";
}  // namespace

int main(int argc, char** argv)
{
  emulator_main::SerialOptions options;
  options.port.link = DEFAULT_LINK;
  ptz_action_server::PelcoDEmulatorConfig config;
  const std::string usage = emulator_main::serialUsage(USAGE, DEFAULT_LINK);
  emulator_main::parseArguments(
      argc, argv, PROGRAM, usage, [&](const std::string& arg, const emulator_main::Value& value) {
        if (emulator_main::parseSerialOption(arg, value, PROGRAM, usage.c_str(), options))
        {
          return true;
        }
        if (arg == "--address")
        {
          config.address =
              static_cast<std::uint8_t>(emulator_main::numberIn(PROGRAM, value(), arg, 1, 255, usage.c_str()));
        }
        else if (arg == "--tilt-encoding")
        {
          ptz_action_server::pelco::parseTiltEncoding(
              emulator_main::choice(PROGRAM, value(), arg, { "down_positive", "up_positive" }, usage.c_str()),
              config.tilt_encoding);
        }
        else if (arg == "--turbo-speed")
        {
          config.pan_turbo_speed = emulator_main::number(PROGRAM, value(), arg, usage.c_str());
        }
        else if (arg == "--general-reply")
        {
          config.general_reply = true;
        }
        else if (arg == "--mode")
        {
          const std::string mode = value();
          if (!config.applyMode(mode))
          {
            emulator_main::fail(PROGRAM, "--mode " + mode + " is none of " + config.MODES, usage.c_str());
          }
        }
        else
        {
          return false;
        }
        return true;
      });
  return emulator_main::runSerialDevice<ptz_action_server::PelcoDEmulator>(
      PROGRAM, config, options,
      ", address " + std::to_string(config.address) + ", tilt " +
          ptz_action_server::pelco::toString(config.tilt_encoding) +
          (config.set_position ? "" : ", no set-position (ignores 0x4B, 0x4D, 0x4F)"));
}
