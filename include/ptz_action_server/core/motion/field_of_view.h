/**
 * \file
 * \brief The camera's field of view at each zoom, and the focal-length scale between two zooms.
 */
#pragma once

#include <vector>

namespace ptz_action_server
{
/// Horizontal and vertical field of view, full angles in rad.
struct FieldOfViewAngles
{
  double horizontal = 0.0;
  double vertical = 0.0;
};

/// One row of a measured field-of-view table.
struct FieldOfViewRow
{
  double zoom = 1.0;  ///< X-factor
  FieldOfViewAngles angles;
};

/// How much the focal lengths (fx, fy) grow from one zoom to another.
struct FocalScale
{
  double x = 1.0;  ///< fx(to) / fx(from)
  double y = 1.0;  ///< fy(to) / fy(from)
};

/// How the wide-end field of view narrows with zoom.
enum class ZoomLaw
{
  LENS,     ///< an ideal zoom lens: fov(X) = 2 atan(tan(fov(1) / 2) / X)
  DIVIDED,  ///< fov(X) = fov(1) / X, as a virtual camera may define it (DigiView's fov = fov_wide / zoom)
};

/// One of the two angles of a field of view.
enum class ViewDirection
{
  HORIZONTAL,
  VERTICAL,
};

/**
 * \brief Field of view as a function of zoom: a lens model or a measured table.
 *
 * A pinhole camera's focal length f relates to its field of view through tan(fov / 2) = (size / 2) / f, and an optical
 * zoom of X multiplies f by X. So:
 * - fromWideEnd(h, v): fov(X) = 2 atan(tan(fov(1) / 2) / X), exact for an ideal zoom lens (plain division fov(1) / X
 *   is only the small-angle approximation, off by 10 % at a 60 degree wide end). ZoomLaw::DIVIDED takes the plain
 *   division instead, for cameras that define their field of view that way (virtual cameras such as DigiView).
 * - fromTable(rows): between two rows, the focal length 1 / tan(fov / 2) is interpolated linearly in zoom (so a table
 *   of an ideal lens reproduces the lens model exactly between its rows); outside the table the end row holds.
 *
 * Immutable once built; safe to share between threads.
 */
class FieldOfViewModel
{
public:
  /// The model from the wide-end (zoom 1) angles. Throws ConfigError unless both are in (0, pi).
  static FieldOfViewModel fromWideEnd(const FieldOfViewAngles& wide_end, ZoomLaw law = ZoomLaw::LENS);
  /// A table: at least one row, zooms >= 1 and strictly increasing, every angle in (0, pi), and the angles not growing
  /// with zoom. Throws ConfigError naming the row.
  static FieldOfViewModel fromTable(std::vector<FieldOfViewRow> rows);

  /// The field of view at \p zoom (clamped to at least 1 for the lens model, to the table's ends for a table).
  FieldOfViewAngles at(double zoom) const;

  /// fx(\p zoom) / fx(\p calibration_zoom), and the same for fy: a camera_info calibrated at \p calibration_zoom has
  /// fx' = fx * x and fy' = fy * y at \p zoom (the principal point does not move).
  FocalScale focalScale(double calibration_zoom, double zoom) const;

  /**
   * \brief The inverse of at(): the largest zoom whose field of view in \p direction is still at least \p angle (full
   * angle, rad).
   *
   * Within the model's zooms that is the zoom whose angle is \p angle. An angle wider than the wide end gives the
   * smallest zoom (1, or a table's first row); one narrower than a table's last row that row's zoom (the table knows
   * no narrower view); the lens and divided laws narrow without end. Where a table's angle stays flat over a span of
   * zooms, the span's largest. NaN unless \p angle is in (0, pi).
   */
  double zoomFor(double angle, ViewDirection direction) const;

  /// The largest zoom whose field of view still holds \p span in both directions: the smaller of the two zoomFor().
  /// A direction whose angle is not in (0, pi) (NaN: no constraint) does not count; NaN when neither is.
  double zoomShowing(const FieldOfViewAngles& span) const;

private:
  FieldOfViewModel() = default;

  /// Focal lengths in units of half the image size: 1 / tan(fov / 2), horizontal and vertical.
  FieldOfViewAngles focalAt(double zoom) const;

  std::vector<FieldOfViewRow> focal_rows_;  ///< a table's zoom and 1 / tan(fov / 2) per row
  bool wide_end_model_ = false;             ///< true: wide_end_ and law_ instead of a table
  FieldOfViewAngles wide_end_;              ///< angles at zoom 1
  ZoomLaw law_ = ZoomLaw::LENS;
};

}  // namespace ptz_action_server
