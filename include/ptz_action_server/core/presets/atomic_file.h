/**
 * \file
 * \brief A store's file (the presets, the tours): replaced whole, so that a crash or a power loss leaves the old
 * content or the new, never a mix; read whole at start.
 */
#pragma once

#include <optional>
#include <string>

namespace ptz_action_server
{
/// Writes \p text to \p path atomically: a temporary file in the same directory (created if missing), written and
/// fsynced, renamed over \p path, then the directory fsynced. Returns "" or the reason; on failure \p path is as it
/// was and no temporary file is left.
std::string writeFileAtomically(const std::string& path, const std::string& text);

/// Reads the whole of \p path into \p text, as a store reads its file at start: "" and no \p text when there is no
/// file yet; "" and \p text when it was read; else the reason (not a regular file, cannot be read).
std::string readStoredFile(const std::string& path, std::optional<std::string>& text);

}  // namespace ptz_action_server
