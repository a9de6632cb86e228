/**
 * \file
 * \brief What every device protocol over HTTP (Axis VAPIX, ONVIF) shares: its default link and session, its requests
 * and how their answers fail, the set-up failure and a command's result.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "ptz_action_server/core/device/device_protocol.h"
#include "ptz_action_server/core/device/device_session.h"
#include "ptz_action_server/core/transport/http_channel.h"

namespace ptz_action_server
{
/**
 * \brief The base of the protocols that talk to a camera by HTTP requests on a DeviceSession's HTTP link
 * (HttpLink through HttpChannel).
 *
 * Every request goes out through send(), on the I/O thread, one at a time (so this is the one place to change when
 * HTTP becomes asynchronous). A request that gets no answer is the link's loss, with its reason (the session has it);
 * an answer the protocol cannot take fails with the words statusProblem() gives it (the same for every camera: the
 * 401 names the user whose credentials were refused, never the password). A protocol keeps only what is its own:
 * which paths, which bodies, which statuses and answers it takes.
 */
class HttpDeviceProtocol : public DeviceProtocol
{
public:
  /// kind HTTP, port 80 (443 with TLS), Digest; a lost link reopens after 0.1 s at first.
  static LinkConfig defaultLink();
  /// State is polled every 100 ms; no answer for 0.5 s drops the link.
  static DeviceSessionConfig defaultSession()
  {
    return { 0.5, 0.1, 10.0, 0.15, 0.5 };
  }

  /// Nothing comes unasked over HTTP: the answers are send()'s.
  void onReceived(const std::uint8_t*, std::size_t) override
  {
  }

protected:
  /// Over \p session's HTTP link (DeviceSession::http() throws std::logic_error on another).
  explicit HttpDeviceProtocol(DeviceSession& session);

  /// Throws ConfigError unless \p link is an HTTP link: "<device> is reached over HTTP".
  static void requireHttp(const LinkConfig& link, const std::string& device);

  /// Makes \p request (I/O thread, one at a time) and returns the camera's answer, valid until the next request; or
  /// nullptr when none came: then the link is lost and the session has the reason, so the caller's problem stays ""
  /// (a transport error is the link's, not the request's).
  const HttpReply* send(const HttpRequest& request);
  /// Why the answer \p status (one the protocol does not take) fails \p what: for 401 the credentials of the link's
  /// user were refused; any other is "HTTP <status> answering <what>", then " at <where>" if given.
  std::string statusProblem(long status, const std::string& what, const std::string& where = "") const;
  /// The set-up failed with \p problem: the start fails with it; after a start the connection is dropped and set up
  /// again after the backoff. "" (the link was lost): nothing, the link reopens and the set-up runs again.
  void setupFailed(const std::string& problem);
  /// The result of command \p serial: \p problem (what the camera answered instead of taking it) is its fault; any
  /// answer, \p done or a refusal, keeps the link alive (a slow camera's command and the next poll, one request at a
  /// time, may leave more than state_timeout between two states). Neither: the link was lost.
  void commandResult(bool done, const std::string& problem, std::uint64_t serial);
  /// The link's HTTP user, for messages and diagnostics (never its password).
  const std::string& httpUser() const;

  DeviceSession& session_;

private:
  HttpChannel& http_;
};

}  // namespace ptz_action_server
