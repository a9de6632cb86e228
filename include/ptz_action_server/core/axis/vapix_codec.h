/**
 * \file
 * \brief Axis VAPIX PTZ (protocols.md section 6): the ptz.cgi arguments the backend sends, the text/plain replies it
 * reads (`key=value` lines, or an `Error:` body), the limits, and the zoom table from VAPIX zoom values to X-factors.
 *
 * Pure functions: a table of golden replies tests them, and the fuzzer feeds them anything.
 */
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace ptz_action_server
{
namespace vapix
{
constexpr const char* PTZ_PATH = "/axis-cgi/com/ptz.cgi";
constexpr double ZOOM_VALUE_MIN = 1.0;      ///< VAPIX zoom of the widest view
constexpr double ZOOM_VALUE_MAX = 19999.0;  ///< optical (9999) plus digital zoom

/// A reply body, read.
struct Reply
{
  bool error = false;      ///< the body started with `Error:`
  std::string error_text;  ///< the camera's words after `Error:`, lines joined with "; "
  std::vector<std::pair<std::string, std::string>> values;  ///< `key=value` lines, in order

  /// The value of \p key, or nullptr.
  const std::string* find(const std::string& key) const;
};

/**
 * \brief Reads a text/plain reply: an `Error:` body, or `key=value` lines (CR LF or LF; blank lines skipped).
 * Returns "" or what is wrong ("line 2 'garbage' is not key=value"); \p reply is reset either way.
 */
std::string parseReply(const std::string& body, Reply& reply);

/// A decimal number, all of \p text, finite.
bool parseNumber(const std::string& text, double& value);

/// `query=position`: degrees and the VAPIX zoom value.
struct Position
{
  double pan = 0.0;   ///< deg, positive right (clockwise seen from above)
  double tilt = 0.0;  ///< deg, positive up
  double zoom = 1.0;  ///< VAPIX zoom value (1 = wide); 1 when the camera has no zoom
};
/// Reads pan, tilt (required) and zoom (optional) from a position reply; "" or what is missing or bad.
std::string readPosition(const Reply& reply, Position& position);

/// `query=limits`: what the camera can reach.
struct Limits
{
  double min_pan = -180.0, max_pan = 180.0;  ///< deg
  double min_tilt = -90.0, max_tilt = 90.0;  ///< deg
  double min_zoom = 1.0, max_zoom = 9999.0;  ///< VAPIX zoom values
  bool has_zoom = false;                     ///< MinZoom and MaxZoom were given
};
/// Reads MinPan, MaxPan, MinTilt, MaxTilt (required, min < max) and MinZoom, MaxZoom (optional); "" or the problem.
std::string readLimits(const Reply& reply, Limits& limits);

/**
 * \brief VAPIX zoom value <-> X-factor, through the camera's table (never linear in X).
 *
 * Text form (the `ZoomMagnification` value of `query=attributes&group=zoom`, or the `zoom_table` setting):
 * `VALUE:X,VALUE:X,...`, values and X-factors both strictly increasing, at least two points. Between points the
 * X-factor is interpolated geometrically (an optical zoom's magnification grows by a factor per motor step).
 */
class ZoomTable
{
public:
  /// Reads \p text; "" or what is wrong ("point 3 '5000:1.2': X must increase").
  static std::string parse(const std::string& text, ZoomTable& table);
  /// The text form, for diagnostics.
  std::string toText() const;

  bool empty() const
  {
    return points_.empty();
  }
  /// X of a zoom value (clamped into the table).
  double toFactor(double value) const;
  /// Zoom value of an X-factor (clamped into the table).
  double toValue(double factor) const;
  double minFactor() const
  {
    return points_.front().second;
  }
  double maxFactor() const
  {
    return points_.back().second;
  }
  double minValue() const
  {
    return points_.front().first;
  }
  double maxValue() const
  {
    return points_.back().first;
  }

private:
  std::vector<std::pair<double, double>> points_;  ///< (value, X), both increasing
};

/// `pan=P&tilt=T&zoom=Z&speed=S` for ptz.cgi: degrees with 4 decimals (fractional, never whole degrees only), the
/// zoom value rounded, speed 1..100; zoom left out when \p zoom_value < 1 (no zoom). Appended to \p out.
void appendAbsoluteMove(std::string& out, double pan_deg, double tilt_deg, double zoom_value, int speed);
/// `continuouspantiltmove=P,T&continuouszoommove=Z`, each -100..100 (positive right, up, in); zoom left out when
/// \p with_zoom is false.
void appendContinuousMove(std::string& out, int pan, int tilt, int zoom, bool with_zoom);

}  // namespace vapix
}  // namespace ptz_action_server
