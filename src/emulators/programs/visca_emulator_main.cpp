/**
 * \file
 * \brief visca_emulator: a VISCA camera on a pseudo-terminal, TCP or UDP, over the simulated motion model.
 */
#include <cstdio>
#include <string>

#include "ptz_action_server/emulators/emulator_main.h"
#include "ptz_action_server/emulators/visca_emulator.h"

namespace
{
const char* PROGRAM = "visca_emulator";
const char* DEFAULT_LINK = "/tmp/ptz_visca";
const char* USAGE = R"(usage: visca_emulator [options]

A Sony VISCA camera on a pseudo-terminal (paced at the baud rate), a TCP server or a UDP socket: address set and
IF_Clear, two command sockets (ACK, completion when a position is reached, buffer full, cancel), pan-tilt drive,
absolute and relative positions, home, zoom drive and direct, the position and zoom inquiries, syntax errors for
illegal parameters. Point the node at it: backend:=serial with protocol: visca, port: /tmp/ptz_visca; or
backend:=visca_ip against --udp 52381 --framing sony_ip.

Options:
  --model NAME           evi_d70, evi_d30 or ptzoptics (default ptzoptics: 14.4 steps a degree)
  --address N            the camera's address, 1..7 (default 1)
  --udp PORT             take UDP datagrams on PORT instead (0 = any free port; answers go to the last sender)
  --framing F            raw (default) or sony_ip (VISCA over IP's 8-byte header and sequence numbers; UDP only)
)";
}  // namespace

int main(int argc, char** argv)
{
  emulator_main::SerialOptions options;
  options.port.link = DEFAULT_LINK;
  ptz_action_server::ViscaEmulatorConfig config;
  const std::string usage = emulator_main::serialUsage(USAGE, DEFAULT_LINK);
  emulator_main::parseArguments(
      argc, argv, PROGRAM, usage, [&](const std::string& arg, const emulator_main::Value& value) {
        if (emulator_main::parseSerialOption(arg, value, PROGRAM, usage.c_str(), options))
        {
          return true;
        }
        if (arg == "--model")
        {
          ptz_action_server::visca::ViscaModel::preset(
              emulator_main::choice(PROGRAM, value(), arg, { "evi_d70", "evi_d30", "ptzoptics" }, usage.c_str()),
              config.model);
        }
        else if (arg == "--address")
        {
          config.address =
              static_cast<std::uint8_t>(emulator_main::numberIn(PROGRAM, value(), arg, 1, 7, usage.c_str()));
        }
        else if (arg == "--udp")
        {
          options.port.kind = ptz_action_server::DevicePortConfig::Kind::UDP;
          options.port.port =
              static_cast<std::uint16_t>(emulator_main::numberIn(PROGRAM, value(), arg, 0, 65535, usage.c_str()));
        }
        else if (arg == "--framing")
        {
          ptz_action_server::parseViscaFraming(
              emulator_main::choice(PROGRAM, value(), arg, { "raw", "sony_ip" }, usage.c_str()), config.framing);
        }
        else
        {
          return false;
        }
        return true;
      });
  if (config.framing == ptz_action_server::ViscaFraming::SONY_IP &&
      options.port.kind != ptz_action_server::DevicePortConfig::Kind::UDP)
  {
    emulator_main::fail(PROGRAM, "--framing sony_ip needs --udp PORT", usage.c_str());
  }
  return emulator_main::runSerialDevice<ptz_action_server::ViscaEmulator>(
      PROGRAM, config, options,
      ", address " + std::to_string(config.address) + ", model " + config.model.name + ", framing " +
          ptz_action_server::toString(config.framing));
}
