/**
 * \file
 * \brief An ONVIF client as the common libraries are, and the emulated camera on a manual clock, for the tests that
 * drive onvif_camera_emulator as other people's clients do.
 */
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <future>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <boost/asio/post.hpp>

#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/transport/http_link.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace onvif_test
{
using namespace onvif;

/// A SOAP client as the common ONVIF libraries are: one HTTP connection, a WS-Security token in every request but
/// GetSystemDateAndTime, stamped in the camera's clock.
class OnvifClient : private Link::Listener
{
public:
  /// \p stamp writes a token's Created (by default as this codec does, "...Z"); \p ask_clock false leaves the
  /// unauthenticated GetSystemDateAndTime out (a camera that refuses it).
  explicit OnvifClient(std::uint16_t port, const std::string& password = "admin",
                       std::function<std::string(double)> stamp = isoTime, bool ask_clock = true)
    : password_(password), stamp_(std::move(stamp))
  {
    LinkConfig config;
    config.kind = LinkKind::HTTP;
    config.host = "127.0.0.1";
    config.port = port;
    link_ = Link::create(context_, config, *this);
    thread_ = std::thread([this] {
      auto work = boost::asio::make_work_guard(context_);
      context_.run();
    });
    boost::asio::post(context_, [this] { link_->open(); });
    EXPECT_TRUE(waitUntil([this] { return up(); }, 10.0));
    if (!ask_clock)
    {
      return;
    }
    // As a client starts: the camera's clock first, without authentication.
    EXPECT_TRUE(call("/onvif/device_service", getSystemDateAndTime(), false));
    double camera_utc = 0.0;
    EXPECT_EQ(readSystemTime(message_.content, camera_utc), "");
    clock_offset_ = camera_utc - utcNow();
  }
  ~OnvifClient() override
  {
    boost::asio::post(context_, [this] {
      link_->close();
      context_.stop();
    });
    thread_.join();
  }

  /// POSTs \p body to \p path as it is, whatever comes back.
  HttpReply post(const std::string& path, const std::string& body, bool secure = true)
  {
    std::string xml = envelope(body);
    if (secure)
    {
      UsernameToken token;
      token.username = "admin";
      token.nonce.resize(16);
      for (char& byte : token.nonce)
      {
        byte = static_cast<char>(random_());
      }
      token.created = stamp_(utcNow() + clock_offset_);
      xml = envelope(body, &token, password_);
    }
    std::promise<HttpReply> done;
    boost::asio::post(context_, [&] {
      HttpRequest request{ path, xml, SOAP_CONTENT_TYPE };
      done.set_value(link_->http()->request(request));
    });
    return done.get_future().get();
  }
  /// POSTs \p body to \p path; true for a response (message() is it), false for a fault (message() holds it too).
  bool call(const std::string& path, const std::string& body, bool secure = true)
  {
    const HttpReply reply = post(path, body, secure);
    EXPECT_TRUE(reply.delivered);
    EXPECT_EQ(parseSoap(reply.body, message_), "") << reply.body;
    EXPECT_EQ(reply.status, message_.fault ? (message_.fault_code == "env:Sender" ? 400 : 500) : 200) << reply.body;
    return !message_.fault;
  }
  bool ptz(const std::string& body)
  {
    return call("/onvif/ptz_service", body);
  }
  const SoapMessage& message() const
  {
    return message_;
  }
  const Element* content() const
  {
    return message_.content;
  }
  Status status(const std::string& profile)
  {
    Status status;
    EXPECT_TRUE(ptz(getStatus(profile))) << message_.fault_text;
    EXPECT_EQ(readStatus(message_.content, status), "");
    return status;
  }

private:
  static double utcNow()
  {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  }
  bool up() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return up_;
  }
  void onLinkUp() override
  {
    std::lock_guard<std::mutex> lock(mutex_);
    up_ = true;
  }
  void onLinkBytes(const std::uint8_t*, std::size_t) override
  {
  }
  void onLinkDown(const std::string&) override
  {
    std::lock_guard<std::mutex> lock(mutex_);
    up_ = false;
  }

  const std::string password_;
  const std::function<std::string(double)> stamp_;
  boost::asio::io_context context_;
  std::unique_ptr<Link> link_;
  std::thread thread_;
  mutable std::mutex mutex_;
  bool up_ = false;
  double clock_offset_ = 0.0;
  std::mt19937_64 random_{ 7 };
  SoapMessage message_;
};

/// The emulator in \p mode on a manual clock.
struct Camera
{
  explicit Camera(const std::string& mode = "standard") : clock(std::make_shared<ManualClock>())
  {
    OnvifCameraEmulatorConfig config;
    EXPECT_TRUE(config.applyMode(mode)) << mode;
    emulator = std::make_unique<OnvifCameraEmulator>(config, clock);
  }
  std::shared_ptr<ManualClock> clock;
  std::unique_ptr<OnvifCameraEmulator> emulator;
};

inline std::vector<std::string> tokensOf(const Element* parent, const char* uri, const char* local)
{
  std::vector<std::string> tokens;
  for (const Element* item : children(parent, uri, local))
  {
    const char* token = attribute(item, "token");
    tokens.push_back(token == nullptr ? "" : token);
  }
  return tokens;
}

}  // namespace onvif_test
}  // namespace ptz_action_server
