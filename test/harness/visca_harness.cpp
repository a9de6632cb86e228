#include "harness/visca_harness.h"

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
using PortKind = DevicePortConfig::Kind;

/// A camera (address 1, ptzoptics) on a pseudo-terminal (raw), or over UDP with Sony's VISCA over IP header.
HarnessEntry viscaEntry(PortKind kind, unsigned baud)
{
  const bool udp = kind == PortKind::UDP;
  HarnessEntry entry;
  entry.name = udp ? "visca_udp" : "visca_serial_" + std::to_string(baud);
  entry.plugin = "visca";
  entry.params =
      udp ? std::vector<HarnessParam>{ paramValue("visca/transport", "udp"), paramValue("visca/host", "127.0.0.1"),
                                       emulatorPort("visca/port"), paramValue("visca/local_host", "127.0.0.1"),
                                       paramValue("visca/framing", "sony_ip") } :
            serialParams("visca", baud);
  HarnessFigures& figures = entry.figures;
  figures.summary = "ViscaEmulator (address 1, ptzoptics), " + portSummary(kind, baud) + (udp ? ", sony_ip" : ", raw");
  figures.goal_items = "the pan-tilt and zoom commands but the pan-tilt drive stop; wire time: its bytes";
  figures.stop_items = "the pan-tilt drive stop (`81 01 06 01 VV WW 03 03 FF`)";
  // A goal is two commands, each answered by an ACK (3 bytes) before the next goes.
  figures.goal_pause = 3 * (15 + 9 + 6) * byteTime(kind, baud) + 0.005;
  // On a serial line an inquiry and its answer (16 bytes) may be on the wire first.
  figures.goal_target =
      udp ? "p99 <= 5 ms" :
            formatText("p99 <= one inquiry + 2 ms (%.1f ms)", (16 * byteTime(kind, baud) + 0.002) * 1e3);
  figures.stop_target = figures.goal_target;
  figures.goals = udp ? 1000 : 300;
  entry.start = [kind, baud, udp](const std::string& link) {
    ViscaEmulatorConfig config;
    config.port.kind = kind;
    config.port.baud = baud;
    config.port.link = udp ? "" : link;
    config.framing = udp ? ViscaFraming::SONY_IP : ViscaFraming::RAW;
    return std::make_unique<ViscaHarness>(config);
  };
  return entry;
}
}  // namespace

std::vector<HarnessEntry> viscaHarnesses()
{
  return { viscaEntry(PortKind::PTY, 9600), viscaEntry(PortKind::UDP, 0) };
}

}  // namespace ptz_action_server
