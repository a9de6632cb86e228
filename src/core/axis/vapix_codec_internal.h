/**
 * \file
 * \brief Private to the VAPIX codec, what its two halves share: vapix_codec.cpp reads the replies, the position, the
 * limits, info=1 and the product; vapix_zoom.cpp the zoom table and attributes.
 */
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>

namespace ptz_action_server
{
namespace vapix
{
/// Points of a zoom table, and entries of the lists read from a camera, at most.
constexpr std::size_t MAX_POINTS = 1000;

/// A key of a `key=value` reply or a command of info=1: letters, digits, '_' and '.'.
inline bool validKey(const std::string& key)
{
  return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
  });
}

}  // namespace vapix
}  // namespace ptz_action_server
