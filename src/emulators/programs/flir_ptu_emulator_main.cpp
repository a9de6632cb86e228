/**
 * \file
 * \brief flir_ptu_emulator: a FLIR PTU on a pseudo-terminal, over the simulated motion model.
 */
#include <cstdio>
#include <string>

#include "ptz_action_server/emulators/emulator_main.h"
#include "ptz_action_server/emulators/flir_ptu_emulator.h"

namespace
{
const char* PROGRAM = "flir_ptu_emulator";
const char* DEFAULT_LINK = "/tmp/ptz_flir";
const char* USAGE = R"(usage: flir_ptu_emulator [options]

A FLIR (Directed Perception) D46-like pan-tilt unit on a pseudo-terminal: its ASCII protocol (terse/verbose,
echo, position and velocity modes, resolution 185.1428"/position, pan +-3090 and tilt -907..604 positions,
speeds 31..1671 and 31..1114 positions/s, R / RE reset calibration answered !T!T!P!P*), paced at the baud
rate, replies ended CR LF. Like a unit at power-up it echoes and answers verbosely until FT / ED; its banner
(at power-up only) reaches only a client that has the port open then, as on a real line. On TCP it greets
every connection with the E-series banner. R keeps terse / verbose, echo and the other modes, as the
published drivers expect (they read !T!T!P!P* and go on without FT / ED). Point the node at the link:
backend:=flir port:=/tmp/ptz_flir.

Options:
  --no-banner            start terse, without echo and banner
  --reset-as-power-up    R restarts the unit as at power-up (banner on a serial line, echo and verbose
                         replies again) before it calibrates, as some units do
)";
}  // namespace

int main(int argc, char** argv)
{
  emulator_main::SerialOptions options;
  options.port.link = DEFAULT_LINK;
  ptz_action_server::FlirPtuEmulatorConfig config;
  const std::string usage = emulator_main::serialUsage(USAGE, DEFAULT_LINK);
  emulator_main::parseArguments(argc, argv, PROGRAM, usage,
                                [&](const std::string& arg, const emulator_main::Value& value) {
                                  if (emulator_main::parseSerialOption(arg, value, PROGRAM, usage.c_str(), options))
                                  {
                                    return true;
                                  }
                                  if (arg == "--no-banner")
                                  {
                                    config.banner = false;
                                    return true;
                                  }
                                  if (arg == "--reset-as-power-up")
                                  {
                                    config.reset_as_power_up = true;
                                    return true;
                                  }
                                  return false;
                                });
  return emulator_main::runSerialDevice<ptz_action_server::FlirPtuEmulator>(PROGRAM, config, options, "");
}
