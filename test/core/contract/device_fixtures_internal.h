/**
 * \file
 * \brief Private to the device fixtures: what every protocol's fixture file (<protocol>_fixtures.cpp, listed in its
 * registration in cmake/protocols.cmake) shares.
 */
#pragma once

#include <cstdint>
#include <vector>

#include "device_fixtures.h"
#include "ptz_action_server/core/sim/sim_device_model.h"

namespace ptz_action_server
{
/// \p bytes as upper-case hex pairs, each followed by a space.
std::string hex(const std::vector<std::uint8_t>& bytes);

/// A path for an emulator's pseudo-terminal link, unique in this process.
std::string uniqueLink(const char* name);

/// \p commands without the state polls.
std::vector<DeviceCommand> withoutQueries(const std::vector<DeviceCommand>& commands);

/// s without a state before a link is lost: generous, a busy test machine may starve the I/O threads for a while
/// (the deadline cases read it back). 1 s was lost once in a few clean-clone runs beside two busy `yes` processes, on
/// the serial fixtures (a second recovery, a link loss in a goal).
constexpr double TEST_STATE_TIMEOUT = 1.5;
/// The IP cameras' (Axis, ONVIF): shorter than their request_timeout of 2 s, so that the slow-device case's stall past
/// the deadline is seen as silence, not as a request that timed out.
constexpr double HTTP_TEST_STATE_TIMEOUT = 1.0;

}  // namespace ptz_action_server
