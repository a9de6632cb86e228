/**
 * \file
 * \brief printf-style formatting into std::string, for the reasons and notes the core hands to users, and the
 * trimming of the text devices and files give.
 */
#pragma once

#include <cstddef>
#include <string>

namespace ptz_action_server
{
/// Formats like printf; the result is cut at 511 characters.
std::string formatText(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

/// \p text without the spaces, tabs and line ends (CR, LF) around it.
inline std::string trimmed(const std::string& text)
{
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos)
  {
    return {};
  }
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

}  // namespace ptz_action_server
