/**
 * \file
 * \brief Replacing a file whole, so that a crash or a power loss leaves the old content or the new, never a mix.
 */
#pragma once

#include <string>

namespace ptz_action_server
{
/// Writes \p text to \p path atomically: a temporary file in the same directory (created if missing), written and
/// fsynced, renamed over \p path, then the directory fsynced. Returns "" or the reason; on failure \p path is as it
/// was and no temporary file is left.
std::string writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace ptz_action_server
