/**
 * \file
 * \brief Private to DigiViewEmulator, what its two halves share: the sessions and their subscriptions, and the
 * views' field-of-view range and their boxes in each layout. digiview_emulator.cpp is the server (connections,
 * sessions, subscriptions), digiview_emulator_answers.cpp what the emulated DigiView answers to each message.
 */
#pragma once

#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "ptz_action_server/emulators/digiview_emulator.h"

namespace ptz_action_server
{
namespace digiview_views
{
inline constexpr double NARROWEST_FOV = 0.1;
inline constexpr double WIDEST_FOV = 3.14;

/// The user views of a layout mode on the 1920 x 1080 output, as the seed describes the layouts (6, the debug view,
/// shows the sensor's frame: one view).
inline std::vector<digiview::BoundingBox> viewsOf(std::uint8_t layout_mode)
{
  using Box = digiview::BoundingBox;
  switch (layout_mode)
  {
    case 1:  // two stacked
      return { Box{ 0, 0, 1920, 540 }, Box{ 0, 540, 1920, 540 } };
    case 2:  // two side by side
      return { Box{ 0, 0, 960, 1080 }, Box{ 960, 0, 960, 1080 } };
    case 3:  // two on top, one below
      return { Box{ 0, 0, 960, 540 }, Box{ 960, 0, 960, 540 }, Box{ 0, 540, 1920, 540 } };
    case 4:  // 2 x 2
      return { Box{ 0, 0, 960, 540 }, Box{ 960, 0, 960, 540 }, Box{ 0, 540, 960, 540 }, Box{ 960, 540, 960, 540 } };
    case 5:  // three on top, one below
      return { Box{ 0, 0, 640, 540 }, Box{ 640, 0, 640, 540 }, Box{ 1280, 0, 640, 540 }, Box{ 0, 540, 1920, 540 } };
    default:  // 0: one camera; 6: the debug view
      return { Box{ 0, 0, 1920, 1080 } };
  }
}
}  // namespace digiview_views

/// A subscription (0.5: GET_INTERVAL, later a GET with interval_ms): its request and when it reports next.
struct DigiViewEmulator::Subscription
{
  digiview::IntervalRequest request;
  TimePoint due;
};

/// One client: a TCP connection, or a UDP peer. Lives on the I/O thread.
struct DigiViewEmulator::Session
{
  using Key = std::tuple<int, std::string, std::uint8_t>;  ///< param, stream, camera
  std::string peer;                                        ///< "host:port"
  bool is_udp = false;
  bool open = true;
  std::vector<std::uint8_t> buffered;  ///< tcp: the start of a message not yet whole
  std::map<Key, Subscription> subscriptions;
};

}  // namespace ptz_action_server
