/**
 * \file
 * \brief What the IP camera fixtures (Axis, ONVIF) share: an emulated camera behind its HTTP server.
 */
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "device_fixtures_internal.h"
#include "ptz_action_server/core/transport/http_link.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace ptz_action_server
{
/// What the IP camera fixtures share: an emulated camera behind its HTTP server.
class HttpCameraFixture : public DeviceFixture
{
public:
  void setSilent(bool silent) override
  {
    server().setSilent(silent);
  }
  double replyDeadline() const override
  {
    // The state timeout (shorter here than request_timeout): an answer later than it leaves the link without news
    // for longer. A goal's command and the next poll go one request at a time, so two positions may be two answers
    // apart; the command's answer keeps the link up in between (the emulators apply SimFaults::reply_delay through
    // HttpCameraServer::setDelay()).
    return HTTP_TEST_STATE_TIMEOUT;
  }
  bool setEndlessReplies(bool endless) override
  {
    server().setEndless(endless);
    return true;
  }
  /// The camera vanishes: its connections close and nothing listens (a closed keep-alive connection alone is no
  /// loss on HTTP: the next request opens another).
  void breakLink() override
  {
    server().setListening(false);
    server().dropConnections();
  }
  void restoreLink() override
  {
    server().setListening(true);
  }
  /// A connection that closes and reopens at once is ordinary HTTP: only a request that fails, or silence, is a loss.
  bool breaksAtOnce() const override
  {
    return false;
  }
  std::string linkLossWords() const override
  {
    return server().url().substr(0, server().url().rfind(':'));  // "http://127.0.0.1" or "https://127.0.0.1"
  }
  void clearCommands() override
  {
    server().received().clear();
  }
  AxisValues goal(double pan, double tilt) const override
  {
    return AxisValues{ { pan, tilt, 2.0 } };
  }

protected:
  virtual HttpCameraServer& server() const = 0;

  /// A camera serving TLS is reached over TLS, its certificate pinned (as a self-signed camera is configured).
  static void pinIfTls(const HttpCameraServer& server, LinkConfig& link)
  {
    link.http.tls = !server.fingerprint().empty();
    link.http.fingerprint = parseCertificateFingerprint(server.fingerprint());
  }
};

}  // namespace ptz_action_server
