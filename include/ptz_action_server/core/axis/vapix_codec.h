/**
 * \file
 * \brief Axis VAPIX PTZ (protocols.md section 6): the ptz.cgi arguments the backend sends (moves, and `center` /
 * `areazoom` on a point of the camera's picture), the text/plain replies it
 * reads (`key=value` lines, or an `Error:` body), the limits, what `info=1` offers, the zoom attributes, the product
 * number from param.cgi, and the zoom table from VAPIX zoom values to X-factors.
 *
 * Pure functions: a table of golden replies tests them, and the fuzzer feeds them anything.
 */
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace ptz_action_server
{
namespace vapix
{
constexpr const char* PTZ_PATH = "/axis-cgi/com/ptz.cgi";
constexpr const char* PARAM_PATH = "/axis-cgi/param.cgi";
/// The product's brand parameters (`root.Brand.ProdNbr`, `root.Brand.ProdFullName`, ...).
constexpr const char* BRAND_PATH = "/axis-cgi/param.cgi?action=list&group=root.Brand";
constexpr double ZOOM_VALUE_MIN = 1.0;             ///< VAPIX zoom of the widest view
constexpr double ZOOM_VALUE_OPTICAL_MAX = 9999.0;  ///< VAPIX zoom of the optical tele end
constexpr double ZOOM_VALUE_MAX = 19999.0;         ///< optical (9999) plus digital zoom

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

/// `query=position`: degrees and the VAPIX zoom value (the camera's other keys, iris, focus, brightness, autofocus,
/// autoiris, are not used).
struct Position
{
  double pan = 0.0;       ///< deg, positive right (clockwise seen from above)
  double tilt = 0.0;      ///< deg, positive up
  double zoom = 1.0;      ///< VAPIX zoom value (1 = wide); 1 when the camera gives none
  bool has_zoom = false;  ///< the reply carried `zoom=`
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
 * \brief VAPIX zoom value <-> X-factor, through a table of points.
 *
 * Text form (the `zoom_table` setting): `VALUE:X,VALUE:X,...`, values and X-factors both strictly increasing, at
 * least two points. The camera's own table is the `zoomSteps` of `query=attributes&group=zoom` (readZoomAttributes()).
 *
 * Between points the X-factor is interpolated linearly in the value. That is how Axis cameras map it: the zoomSteps
 * of the VAPIX documentation's example (1:1, 3868:2, 7736:3, 9999:3.58), a Q6075-E's (257 values per X up to 40X)
 * and a 29X camera's web interface table (357 per X to 9999, then 9999..19999 linear in the 12X digital factor)
 * all step the value evenly per X. A table with many points follows any other curve as closely as it lists it.
 */
class ZoomTable
{
public:
  /// Reads \p text; "" or what is wrong ("point 3 '5000:1.2': X must increase").
  static std::string parse(const std::string& text, ZoomTable& table);
  /// Takes (value, X) \p points, with the checks of parse(); "" or what is wrong.
  static std::string fromPoints(std::vector<std::pair<double, double>> points, ZoomTable& table);
  /**
   * \brief The table of a lens with \p max_optical X at VAPIX zoom 9999 (1X at 1), linear in between, and with
   * \p max_digital > 1 the digital range 9999..19999 up to max_optical x max_digital, linear in the digital factor.
   * Empty when \p max_optical is not above 1 (or not finite).
   */
  static ZoomTable linear(double max_optical, double max_digital = 1.0);
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
  std::size_t size() const
  {
    return points_.size();
  }
  const std::vector<std::pair<double, double>>& points() const
  {
    return points_;
  }

private:
  std::vector<std::pair<double, double>> points_;  ///< (value, X), both increasing
};

/**
 * \brief The zoom group of `query=attributes&group=zoom`, as the VAPIX PTZ API documents its plain-text answer:
 * a section per video channel, `Attributes for camera N`, then `name=value` lines; an array's entries are separated
 * by `,` and an entry's `key=value` pairs by `|`:
 *
 *     Attributes for camera 1
 *     maxOpticalZoomMag=30
 *     zoomSteps=value=1 | zoom=1,value=3868 | zoom=2,value=7736 | zoom=3,value=9999 | zoom=3.584961
 *
 * The attributes are "product/release dependent": firmware without them answers `Error:` and
 * `query: unknown value: attributes`.
 */
struct ZoomAttributes
{
  bool refused = false;  ///< the camera answered `Error:` (no such query): refusal holds its words
  std::string refusal;
  std::vector<std::pair<double, double>> steps;  ///< zoomSteps: (VAPIX value, X), as listed
  double max_optical = 0.0;                      ///< maxOpticalZoomMag; 0 when not given
  double max_digital = 0.0;                      ///< maxDigitalZoomMag; 0 when not given
};
/// Reads the answer for video channel \p camera (a body without sections counts as its own); "" or what is wrong.
std::string readZoomAttributes(const std::string& body, int camera, ZoomAttributes& attributes);
/// The table \p attributes give: the zoomSteps, else ZoomTable::linear() of maxOpticalZoomMag (and
/// maxDigitalZoomMag); "" or why they give none ("no zoomSteps and no maxOpticalZoomMag").
std::string zoomTableOf(const ZoomAttributes& attributes, ZoomTable& table);

/**
 * \brief What `ptz.cgi?info=1` says a camera offers: one command per line, `name=[argument]` or
 * `name={ a | b | c }` (`{camera=[n]}` in braces, options of the line before indented), after an
 * `Available commands:` line. A field camera without the zoom attributes lists
 * `query={ speed | position | limits | presetposcam | presetposall }`.
 */
struct CommandList
{
  std::vector<std::pair<std::string, std::vector<std::string>>> commands;  ///< name, its listed values (if any)

  bool empty() const
  {
    return commands.empty();
  }
  /// The command \p name is offered.
  bool has(const std::string& name) const;
  /// The command \p name is offered with the value \p value among its listed ones.
  bool offers(const std::string& name, const std::string& value) const;
};
/// Reads an `info=1` answer; never fails (an `Error:` body or nonsense gives an empty list).
CommandList readCommandList(const std::string& body);

/// The product, from param.cgi's `root.Brand` group (`root.Brand.ProdNbr=Q6155-E`, `...ProdFullName=...`).
struct Product
{
  std::string number;     ///< ProdNbr, e.g. "Q6155-E"
  std::string full_name;  ///< ProdFullName, e.g. "AXIS Q6155-E PTZ Dome Network Camera" ("" when not given)
};
/// Reads a `param.cgi?action=list&group=root.Brand` reply; "" or what is missing.
std::string readProduct(const Reply& reply, Product& product);

/// The optical zoom assumed for a model family when the camera gives no table (see modelFamilyZoom()).
struct FamilyZoom
{
  std::string family;        ///< "Q61": the letter and two digits of the product number
  double max_optical = 0.0;  ///< X at VAPIX zoom 9999
  const char* models = "";   ///< the family's models the figure is typical of, for messages
};
/**
 * \brief The documented default optical zoom of \p product_number's family ("Q6155-E": Q61, 30X), or false for a
 * family without one. A guess: models within a family differ, so the backend warns and names it.
 */
bool modelFamilyZoom(const std::string& product_number, FamilyZoom& zoom);
/// Every family with a default, for documentation and tests.
const std::vector<FamilyZoom>& modelFamilyZooms();

/// `pan=P&tilt=T&zoom=Z&speed=S` for ptz.cgi: degrees with 4 decimals (fractional, never whole degrees only), the
/// zoom value rounded, speed 1..100; an axis given as NaN is left out (left where it is), as is zoom when
/// \p zoom_value < 1 (no zoom). Appended to \p out.
void appendAbsoluteMove(std::string& out, double pan_deg, double tilt_deg, double zoom_value, int speed);
/// `continuouspantiltmove=P,T&continuouszoommove=Z`, each -100..100 (positive right, up, in); zoom left out when
/// \p with_zoom is false.
void appendContinuousMove(std::string& out, int pan, int tilt, int zoom, bool with_zoom);

/// A pixel of the client's picture, as `center` and `areazoom` take it: whole pixels from the picture's top-left
/// corner (its centre is (width / 2, height / 2)), in a picture of `imagewidth` x `imageheight` (without them the
/// camera takes its own default size, which is product-specific).
struct ImagePoint
{
  int x = 0;
  int y = 0;
  int image_width = 0;
  int image_height = 0;
};
/// `center=X,Y&imagewidth=W&imageheight=H`: the camera centres that point of its picture.
void appendCenter(std::string& out, const ImagePoint& point);
/// `areazoom=X,Y,Z&imagewidth=W&imageheight=H`: centres as `center` does and zooms by Z / 100 (Z at least 1): 300 to a
/// third of the current field of view, 50 out to twice it.
void appendAreaZoom(std::string& out, const ImagePoint& point, int zoom_percent);

}  // namespace vapix
}  // namespace ptz_action_server
