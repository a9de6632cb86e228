/**
 * \file
 * \brief Private to DigiViewEmulator, what its two halves share: the sessions and their subscriptions, and the
 * views' field-of-view range and count. digiview_emulator.cpp is the server (connections, sessions, subscriptions),
 * digiview_emulator_answers.cpp what the emulated DigiView answers to each message.
 */
#pragma once

#include <deque>
#include <memory>
#include <tuple>

#include <boost/asio/steady_timer.hpp>

#include "ptz_action_server/emulators/digiview_emulator.h"

namespace ptz_action_server
{
namespace digiview_views
{
inline constexpr double NARROWEST_FOV = 0.1;
inline constexpr double WIDEST_FOV = 3.14;

/// User views per layout mode (6 is the debug view: one).
inline std::uint8_t viewsOf(std::uint8_t layout_mode)
{
  static const std::uint8_t VIEWS[] = { 1, 2, 2, 3, 4, 4, 1 };
  return layout_mode < sizeof(VIEWS) ? VIEWS[layout_mode] : 1;
}
}  // namespace digiview_views

/// A GET_INTERVAL subscription: its request and its timer.
struct DigiViewEmulator::Subscription
{
  digiview::IntervalRequest request;
  std::unique_ptr<boost::asio::steady_timer> timer;
};

/// One client: a TCP connection, or a UDP peer. Lives on the I/O thread.
struct DigiViewEmulator::Session
{
  using Key = std::tuple<int, std::string, std::uint8_t>;  ///< param, stream, camera
  explicit Session(boost::asio::io_context& context) : socket(context)
  {
  }
  boost::asio::ip::tcp::socket socket;  ///< TCP only
  bool is_udp = false;
  boost::asio::ip::udp::endpoint peer;
  bool open = true;
  std::array<std::uint8_t, 2048> buffer{};
  std::size_t buffered = 0;
  std::deque<digiview::Bytes> writes;
  std::map<Key, Subscription> subscriptions;
};

}  // namespace ptz_action_server
