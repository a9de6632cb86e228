/**
 * \file
 * \brief Text the core writes and reads: printf-style formatting into std::string (the reasons and notes the core
 * hands to users), and the strict number parser of the text protocols (VAPIX, ONVIF).
 */
#pragma once

#include <string>

namespace ptz_action_server
{
/// Formats like printf; the result is cut at 511 characters.
std::string formatText(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

/// A decimal number, all of \p text, finite (no blanks around it, no hex floats, nan or inf).
bool parseNumber(const std::string& text, double& value);

}  // namespace ptz_action_server
