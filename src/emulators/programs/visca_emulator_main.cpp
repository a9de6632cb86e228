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
IF_Clear (broadcast, addressed, and as VISCA over IP device setting commands), two command sockets (ACK, completion
when a position is reached, buffer full, cancel), pan-tilt drive, absolute and relative positions in the model's
nibbles and speed form, home, zoom drive and direct, the position, zoom, power and version inquiries, syntax errors
for illegal parameters. Point the node at it: backend:=visca with transport: serial, port: /tmp/ptz_visca; or
backend:=visca against --udp 52381 --framing sony_ip.

Options:
  --model NAME           the units and the position layout of a camera model (default ptzoptics):
                         MODELS
  --address N            the camera's address, 1..7 (default 1)
  --udp PORT             take UDP datagrams on PORT instead (0 = any free port; answers go to the last sender)
  --framing F            raw (default) or sony_ip (VISCA over IP's 8-byte header and sequence numbers; UDP only)
  --mode NAME            a dialect of the field (may be given more than once):
                         g2-latency: answers as PTZOptics G2 cameras do (pan-tilt inquiries in 88-123 ms, zoom
                           inquiries in 26-58 ms, ACKs in 28-89 ms)
                         g3-address: replies from address A0 whatever its own (PTZOptics G3 firmware)
                         ndi-sequence: VISCA over IP sequence numbers 1..3 only, every reply numbered 1 (NewTek
                           NDI PTZ1)
                         standard-zoom: the variable zoom drive (2p, 3p) is a syntax error; 02 and 03 work
                         no-inquiries: commands answered, inquiries never
                         sony-reply-port: UDP replies go to port 52381 of the sender's host (Sony)
  --reply-port PORT      UDP replies go to PORT of the sender's host, whatever port asked (0 = to the sender)
)";
}  // namespace

int main(int argc, char** argv)
{
  emulator_main::SerialOptions options;
  options.port.link = DEFAULT_LINK;
  ptz_action_server::ViscaEmulatorConfig config;
  const std::string models = ptz_action_server::visca::ViscaModel::presetNames();
  std::string wrapped;  // the names on lines of the help's width
  for (std::size_t start = 0; start < models.size();)
  {
    std::size_t end = models.size() - start > 80 ? models.rfind(", ", start + 80) + 1 : models.size();
    wrapped += (wrapped.empty() ? "" : "\n                         ") + models.substr(start, end - start);
    start = end + (end < models.size() ? 1 : 0);
  }
  std::string own_usage = USAGE;
  own_usage.replace(own_usage.find("MODELS"), 6, wrapped);
  const std::string usage = emulator_main::serialUsage(own_usage.c_str(), DEFAULT_LINK);
  std::string modes;
  emulator_main::parseArguments(
      argc, argv, PROGRAM, usage, [&](const std::string& arg, const emulator_main::Value& value) {
        if (emulator_main::parseSerialOption(arg, value, PROGRAM, usage.c_str(), options))
        {
          return true;
        }
        if (arg == "--model")
        {
          const std::string model = value();
          if (!ptz_action_server::visca::ViscaModel::preset(model, config.model))
          {
            emulator_main::fail(PROGRAM, "--model " + model + " is none of " + models, usage.c_str());
          }
        }
        else if (arg == "--mode")
        {
          const std::string mode = value();
          if (!config.applyMode(mode))
          {
            emulator_main::fail(PROGRAM, "--mode " + mode + " is none of " + config.MODES, usage.c_str());
          }
          modes += ", " + mode;
        }
        else if (arg == "--reply-port")
        {
          config.modes.reply_port =
              static_cast<std::uint16_t>(emulator_main::numberIn(PROGRAM, value(), arg, 0, 65535, usage.c_str()));
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
          ptz_action_server::toString(config.framing) + modes);
}
