/**
 * \file
 * \brief The digiview backend's tests' devices: the backend's and the emulator's configurations for a format (the
 * format's documented angle unit on both), and a DigiView that answers with the published implementations' frames.
 */
#pragma once

#include <atomic>
#include <thread>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>

#include "digiview_golden_frames.h"
#include "ptz_action_server/core/digiview/digiview_protocol.h"
#include "ptz_action_server/emulators/digiview_emulator.h"

namespace ptz_action_server
{
namespace digiview_devices
{
using namespace digiview;

inline constexpr double WAIT = 10.0;

inline DeviceConfig<DigiViewProtocol> backendConfig(std::uint16_t port, Format format,
                                                    LinkKind transport = LinkKind::TCP)
{
  DeviceConfig<DigiViewProtocol> config;
  config.link.port = port;
  config.link.kind = transport;
  config.settings.wire = Wire(format);  // its documented angle unit, as the emulator's
  config.settings.acceleration = 4.0;   // as the emulator turns
  config.session.startup_timeout = WAIT;
  config.session.state_timeout = 1.0;  // generous: a busy test machine may starve the I/O threads
  return config;
}

inline DigiViewEmulatorConfig emulatorConfig(Format format, LinkKind transport = LinkKind::TCP)
{
  DigiViewEmulatorConfig config;
  config.wire = Wire(format);
  config.transport = transport;
  return config;
}

/**
 * A DigiView that answers GETs with the frames the published implementations print: VIDEO_OUTPUT and SYSTEM_STATUS
 * byte for byte as published-wire-facts.md sections 1.5 and 1.9.7 have them (stream "main", four views), the view's
 * state packed by this codec; each GET once (no reports). Halted (1.1 on), it answers SYSTEM_STATUS with HALT and
 * nothing about the view: a DigiView whose halted pipeline reports no view. One TCP client, on its own thread.
 */
class PublishedDigiView
{
public:
  explicit PublishedDigiView(Format format)
    : format_(format)
    , acceptor_(context_, boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0))
    , socket_(context_)
    , request_(layoutOf(format).size)
  {
    acceptor_.async_accept(socket_, [this](const boost::system::error_code& error) {
      if (!error)
      {
        read();
      }
    });
    thread_ = std::thread([this] { context_.run(); });
  }
  ~PublishedDigiView()
  {
    context_.stop();
    thread_.join();
  }
  std::uint16_t port() const
  {
    return acceptor_.local_endpoint().port();
  }
  void setHalted(bool halted)
  {
    halted_ = halted;
  }

private:
  void read()
  {
    boost::asio::async_read(socket_, boost::asio::buffer(request_),
                            [this](const boost::system::error_code& error, std::size_t) {
                              if (!error)
                              {
                                answer();
                                read();
                              }
                            });
  }
  void answer()
  {
    Message request;
    CameraId camera;
    if (Message::unpack(request_.data(), request_.size(), Wire{ format_ }, request) != UnpackError::NONE ||
        request.message_type != MessageType::GET_PARAMETERS || unpackCamera(request, camera) != UnpackError::NONE)
    {
      return;
    }
    Bytes reply;
    if (request.param_type == digiview::ParamType::VIDEO_OUTPUT)
    {
      reply = digiview_golden::fromHex(digiview_golden::CURRENT_VIDEO_OUTPUT.in(format_));
    }
    else if (request.param_type == digiview::ParamType::SYSTEM_STATUS)
    {
      reply = halted_ ?
                  packSystemStatus(format_, MessageType::CURRENT_PARAMETERS, SystemStatus{ APP_STATUS_HALT, 0, 45.5 })
                      .pack() :
                  digiview_golden::fromHex(digiview_golden::CURRENT_SYSTEM_STATUS.in(format_));
    }
    else if (halted_)
    {
      return;
    }
    else if (request.param_type == digiview::ParamType::CAM_TARGETING)
    {
      CamTargeting targeting;
      targeting.camera = camera;
      reply = packTargeting(format_, MessageType::CURRENT_PARAMETERS, targeting).pack();
    }
    else if (request.param_type == digiview::ParamType::CAM_OPTICS_AND_CONTROL)
    {
      reply = packOptics(format_, MessageType::CURRENT_PARAMETERS, CamOpticsAndControl{ camera, 0, 1.2, 1 }).pack();
    }
    boost::system::error_code ignored;
    boost::asio::write(socket_, boost::asio::buffer(reply), ignored);
  }

  const Format format_;
  std::atomic<bool> halted_{ false };
  boost::asio::io_context context_;
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::ip::tcp::socket socket_;
  Bytes request_;
  std::thread thread_;
};

}  // namespace digiview_devices
}  // namespace ptz_action_server
