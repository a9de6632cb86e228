/**
 * \file
 * \brief The strict number parser of the text protocols (VAPIX, ONVIF, the emulators' requests).
 */
#pragma once

#include <string>

namespace ptz_action_server
{
/// A decimal number, all of \p text, finite (no blanks around it, no hex floats, nan or inf).
bool parseNumber(const std::string& text, double& value);

}  // namespace ptz_action_server
