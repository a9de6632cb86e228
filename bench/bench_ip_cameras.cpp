/**
 * \file
 * \brief The emulated IP cameras ptz_bench runs: axis_camera_emulator's and onvif_camera_emulator's classes on
 * 127.0.0.1, behind their authentication (Digest; ONVIF: WS-Security).
 */
#include <string>

#include "device_table.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"

namespace ptz_bench
{
namespace
{
using namespace ptz_action_server;

/// An emulated camera whose requests are sorted by what they carry.
template <class Emulator, class Config>
class CameraDevice : public EmulatedDevice
{
public:
  CameraDevice(const Config& config, std::string goal_text, std::string stop_text)
    : emulator_(config), goal_text_(std::move(goal_text)), stop_text_(std::move(stop_text))
  {
  }
  std::uint16_t port() const override
  {
    return emulator_.port();
  }
  std::string link() const override
  {
    return "";
  }
  std::vector<Arrival> goalCommands() const override
  {
    return select(goal_text_);
  }
  std::vector<Arrival> stopCommands() const override
  {
    return select(stop_text_);
  }
  long connectionsOpened() const override
  {
    return static_cast<long>(emulator_.server().counters().connections);
  }
  ptz_action_server::EmulatorFaults* faults() override
  {
    return &emulator_;
  }

private:
  /// Requests (the target for GETs, the body for POSTs) holding \p text, answered by the camera (not a 401).
  std::vector<Arrival> select(const std::string& text) const
  {
    std::vector<Arrival> arrivals;
    for (const HttpExchange& exchange : emulator_.server().received().items())
    {
      const std::string& carried = exchange.body.empty() ? exchange.target : exchange.body;
      if (exchange.status != 401 && carried.find(text) != std::string::npos)
      {
        arrivals.push_back(Arrival{ exchange.at, 0.0 });
      }
    }
    return arrivals;
  }

  mutable Emulator emulator_;  ///< mutable: its server's log and counters are read from const accessors
  const std::string goal_text_;
  const std::string stop_text_;
};
}  // namespace

EmulatorSpec axisEmulator()
{
  EmulatorSpec spec;
  spec.summary = "AxisCameraEmulator, HTTP Digest on 127.0.0.1, ephemeral port";
  spec.goal_items = "GET ptz.cgi with pan= (a 401 challenge is not counted)";
  spec.stop_items = "GET ptz.cgi with move=stop";
  spec.goal_target = "p99 <= 5 ms with the connection warm";
  spec.stop_target = "p99 <= 5 ms";
  spec.start = [](const std::string&) -> std::unique_ptr<EmulatedDevice> {
    return std::make_unique<CameraDevice<AxisCameraEmulator, AxisCameraEmulatorConfig>>(AxisCameraEmulatorConfig(),
                                                                                        "&pan=", "move=stop");
  };
  return spec;
}

EmulatorSpec onvifEmulator()
{
  EmulatorSpec spec;
  spec.summary = "OnvifCameraEmulator, WS-Security on 127.0.0.1, ephemeral port";
  spec.goal_items = "POST AbsoluteMove";
  spec.stop_items = "POST Stop";
  spec.goal_target = "p99 <= 5 ms with the connection warm";
  spec.stop_target = "p99 <= 5 ms";
  spec.start = [](const std::string&) -> std::unique_ptr<EmulatedDevice> {
    return std::make_unique<CameraDevice<OnvifCameraEmulator, OnvifCameraEmulatorConfig>>(
        OnvifCameraEmulatorConfig(), "<tptz:AbsoluteMove>", "<tptz:Stop>");
  };
  return spec;
}

}  // namespace ptz_bench
