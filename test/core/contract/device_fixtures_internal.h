/**
 * \file
 * \brief Private to the device fixtures: what every protocol's fixture file (<protocol>_fixtures.cpp, listed in its
 * registration in cmake/protocols.cmake) shares.
 */
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "device_fixtures.h"

namespace ptz_action_server
{
/// \p commands without the state polls.
std::vector<ClassifiedCommand> withoutQueries(const std::vector<ClassifiedCommand>& commands);
/// The texts of \p commands.
std::vector<std::string> texts(const std::vector<ClassifiedCommand>& commands);

/// What lastLinkLoss() names when \p harness's link broke: its pseudo-terminal's link, a TCP connection, or (UDP,
/// where only the silence tells) \p silence_words.
std::string transportLossWords(const DeviceHarness& harness, const std::string& silence_words = "");

/// s without a state before a link is lost: generous, a busy test machine may starve the I/O threads for a while
/// (the deadline cases read it back). 1 s was lost once in a few clean-clone runs beside two busy `yes` processes, on
/// the serial fixtures (a second recovery, a link loss in a goal).
constexpr double TEST_STATE_TIMEOUT = 1.5;
/// The IP cameras' (Axis, ONVIF): shorter than their request_timeout of 2 s, so that the slow-device case's stall past
/// the deadline is seen as silence, not as a request that timed out.
constexpr double HTTP_TEST_STATE_TIMEOUT = 1.0;

/// FLIR's and Pelco-D's reply deadline: the most it learns beyond the exchange's wire time, twice its floor of 100 ms
/// (reply_timeout 0).
constexpr double LINE_REPLY_DEADLINE = 0.2;

/// What the contract expects of every IP camera (Axis, ONVIF: an HttpCameraHarness): a backend whose silence is seen
/// as silence (its request timeout longer than the state timeout), a link loss that names the camera's URL, zoom.
template <class Harness>
class HttpCameraFixture : public HarnessFixture<Harness>
{
public:
  template <class... Arguments>
  explicit HttpCameraFixture(Arguments&&... arguments) : HarnessFixture<Harness>(std::forward<Arguments>(arguments)...)
  {
    this->harness_.config().link.http.request_timeout = 2.0;
    this->harness_.config().session.state_timeout = HTTP_TEST_STATE_TIMEOUT;
  }

  std::string linkLossWords() const override
  {
    const std::string url = this->harness_.emulator().server().url();
    return url.substr(0, url.rfind(':'));  // "http://127.0.0.1" or "https://127.0.0.1"
  }
  /// The state timeout (shorter here than request_timeout): an answer later than it leaves the link without news for
  /// longer. A goal's command and the next poll go one request at a time, so two positions may be two answers apart;
  /// the command's answer keeps the link up in between (the emulators apply SimFaults::reply_delay through
  /// HttpCameraServer::setDelay()).
  double replyDeadline() const override
  {
    return HTTP_TEST_STATE_TIMEOUT;
  }
  AxisValues goal(double pan, double tilt) const override
  {
    return AxisValues{ { pan, tilt, 2.0 } };
  }
};

}  // namespace ptz_action_server
