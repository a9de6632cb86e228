/**
 * \file
 * \brief Private to the VISCA emulator's sources: the reply kinds.
 */
#pragma once

#include <cstdint>

namespace ptz_action_server
{
namespace emulator_visca
{
constexpr std::uint8_t ACK = 0x40;
constexpr std::uint8_t COMPLETION = 0x50;
constexpr std::uint8_t ERROR = 0x60;
}  // namespace emulator_visca
}  // namespace ptz_action_server
