/**
 * \file
 * \brief What a backend's start() says when it fails, for the tests of start-up errors.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/backend.h"

namespace ptz_action_server
{
/// The BackendError text \p backend's start() throws; "" if it started.
inline std::string startupError(PtzBackend& backend)
{
  try
  {
    backend.start();
  }
  catch (const BackendError& error)
  {
    return error.what();
  }
  return {};
}

}  // namespace ptz_action_server
