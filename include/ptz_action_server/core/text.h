/**
 * \file
 * \brief printf-style formatting into std::string, for the reasons and notes the core hands to users.
 */
#pragma once

#include <string>

namespace ptz_action_server
{
/// Formats like printf; the result is cut at 511 characters.
std::string formatText(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

}  // namespace ptz_action_server
