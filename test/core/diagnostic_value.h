/**
 * \file
 * \brief The tests' way to read one entry of a backend's diagnostics.
 */
#pragma once

#include <string>
#include <vector>

#include "ptz_action_server/core/backend.h"

namespace ptz_action_server
{
/// The value of \p backend's diagnostics entry \p name, or "(no <name>)" when it has none.
inline std::string diagnosticValue(const PtzBackend& backend, const std::string& name)
{
  std::vector<DiagnosticValue> values;
  backend.diagnostics(values);
  for (const DiagnosticValue& value : values)
  {
    if (value.first == name)
    {
      return value.second;
    }
  }
  return "(no " + name + ")";
}

}  // namespace ptz_action_server
