/**
 * \file
 * \brief VAPIX focus and iris: `autofocus=on|off`, `focus=`, `continuousfocusmove=`, `autoiris=on|off`, `iris=`,
 * `continuousirismove=` of ptz.cgi, and the lens fields of `query=limits` and `query=position`.
 */
#pragma once

#include <optional>
#include <string>

#include "ptz_action_server/core/axis/vapix_codec.h"
#include "ptz_action_server/core/lens.h"

namespace ptz_action_server
{
namespace vapix
{
/// A lens value's range in `query=limits` (MinFocus..MaxFocus, MinIris..MaxIris); the low end is near (closed).
struct LensRange
{
  bool known = false;
  double min = 1.0;
  double max = 9999.0;

  double toValue(double share) const;
  double toShare(double value) const;
};

struct LensLimits
{
  LensRange focus;
  LensRange iris;
};
/// Reads MinFocus, MaxFocus, MinIris, MaxIris where the camera gives them (each pair optional, min < max).
LensLimits readLensLimits(const Reply& reply);

/// The lens fields of a `query=position` answer.
struct LensReading
{
  std::optional<double> focus;
  std::optional<double> iris;
  std::optional<bool> autofocus;
  std::optional<bool> autoiris;
};
LensReading readLens(const Reply& reply);

/// What the camera's lens takes: a function it reports (or switches) is present; auto/manual where it reports the
/// switch, velocity and position where info=1 offers them (or lists nothing), feedback where it reports a value in
/// known limits. VAPIX has no one-push focus.
LensCapabilities lensCapabilities(const LensLimits& limits, const LensReading& reading, const CommandList& commands);

/// The ptz.cgi arguments of \p command ("autofocus=on", "continuousfocusmove=-50", "iris=5000", ...); "" for one it
/// has no words for (one-push).
std::string lensArguments(const LensCommand& command, const LensLimits& limits);

}  // namespace vapix
}  // namespace ptz_action_server
