#include "ptz_action_server/core/motion/field_of_view.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
namespace
{
bool validAngle(double angle)
{
  return std::isfinite(angle) && angle > 0.0 && angle < M_PI;
}

/// 1 / tan(fov / 2): the focal length in units of half the image size.
FieldOfViewAngles focalOf(const FieldOfViewAngles& angles)
{
  return { 1.0 / std::tan(angles.horizontal / 2.0), 1.0 / std::tan(angles.vertical / 2.0) };
}

FieldOfViewAngles anglesOf(const FieldOfViewAngles& focal)
{
  return { 2.0 * std::atan(1.0 / focal.horizontal), 2.0 * std::atan(1.0 / focal.vertical) };
}

double fieldOfViewSide(const FieldOfViewAngles& angles, ViewDirection direction)
{
  return direction == ViewDirection::HORIZONTAL ? angles.horizontal : angles.vertical;
}
}  // namespace

FieldOfViewModel FieldOfViewModel::fromWideEnd(const FieldOfViewAngles& wide_end, ZoomLaw law)
{
  if (!validAngle(wide_end.horizontal) || !validAngle(wide_end.vertical))
  {
    throw ConfigError(formatText("the wide-end field of view (%g, %g) rad must have both angles in (0, pi)",
                                 wide_end.horizontal, wide_end.vertical));
  }
  FieldOfViewModel field_of_view;
  field_of_view.wide_end_model_ = true;
  field_of_view.wide_end_ = wide_end;
  field_of_view.law_ = law;
  return field_of_view;
}

FieldOfViewModel FieldOfViewModel::fromTable(std::vector<FieldOfViewRow> rows)
{
  if (rows.empty())
  {
    throw ConfigError("the field-of-view table has no rows");
  }
  for (std::size_t index = 0; index < rows.size(); ++index)
  {
    const FieldOfViewRow& row = rows[index];
    if (!std::isfinite(row.zoom) || row.zoom < 1.0)
    {
      throw ConfigError(formatText("field-of-view table row %zu: zoom %g is not >= 1", index, row.zoom));
    }
    if (!validAngle(row.angles.horizontal) || !validAngle(row.angles.vertical))
    {
      throw ConfigError(formatText("field-of-view table row %zu: angles (%g, %g) rad must be in (0, pi)", index,
                                   row.angles.horizontal, row.angles.vertical));
    }
    if (index > 0)
    {
      const FieldOfViewRow& previous = rows[index - 1];
      if (row.zoom <= previous.zoom)
      {
        throw ConfigError(formatText("field-of-view table row %zu: zoom %g must be larger than the row before's %g",
                                     index, row.zoom, previous.zoom));
      }
      if (row.angles.horizontal > previous.angles.horizontal || row.angles.vertical > previous.angles.vertical)
      {
        throw ConfigError(formatText("field-of-view table row %zu: the field of view grows with zoom", index));
      }
    }
  }
  FieldOfViewModel field_of_view;
  for (FieldOfViewRow& row : rows)
  {
    row.angles = focalOf(row.angles);
  }
  field_of_view.focal_rows_ = std::move(rows);
  return field_of_view;
}

FieldOfViewAngles FieldOfViewModel::focalAt(double zoom) const
{
  if (wide_end_model_)
  {
    const double scale = zoom >= 1.0 ? zoom : 1.0;  // also NaN -> the wide end
    if (law_ == ZoomLaw::DIVIDED)
    {
      return focalOf({ wide_end_.horizontal / scale, wide_end_.vertical / scale });
    }
    const FieldOfViewAngles wide = focalOf(wide_end_);
    return { wide.horizontal * scale, wide.vertical * scale };
  }
  if (!(zoom > focal_rows_.front().zoom))  // also NaN
  {
    return focal_rows_.front().angles;
  }
  if (zoom >= focal_rows_.back().zoom)
  {
    return focal_rows_.back().angles;
  }
  const auto above = std::upper_bound(focal_rows_.begin(), focal_rows_.end(), zoom,
                                      [](double value, const FieldOfViewRow& row) { return value < row.zoom; });
  const FieldOfViewRow& high = *above;
  const FieldOfViewRow& low = *(above - 1);
  const double fraction = (zoom - low.zoom) / (high.zoom - low.zoom);
  return { low.angles.horizontal + fraction * (high.angles.horizontal - low.angles.horizontal),
           low.angles.vertical + fraction * (high.angles.vertical - low.angles.vertical) };
}

FieldOfViewAngles FieldOfViewModel::at(double zoom) const
{
  return anglesOf(focalAt(zoom));
}

FocalScale FieldOfViewModel::focalScale(double calibration_zoom, double zoom) const
{
  const FieldOfViewAngles from = focalAt(calibration_zoom);
  const FieldOfViewAngles to = focalAt(zoom);
  return { to.horizontal / from.horizontal, to.vertical / from.vertical };
}

double FieldOfViewModel::zoomFor(double angle, ViewDirection direction) const
{
  if (!validAngle(angle))
  {
    return std::nan("");
  }
  if (wide_end_model_)
  {
    const double wide = fieldOfViewSide(wide_end_, direction);
    // LENS: 1 / tan(fov / 2) = X / tan(wide / 2); DIVIDED: fov = wide / X.
    const double zoom = law_ == ZoomLaw::DIVIDED ? wide / angle : std::tan(wide / 2.0) / std::tan(angle / 2.0);
    return std::max(zoom, 1.0);
  }
  // The focal length grows (or stays) with zoom row by row: find the last row whose focal length is still at most the
  // wanted one (its view at least as wide), then go linearly in focal length towards the next row.
  const double focal = 1.0 / std::tan(angle / 2.0);
  const auto beyond = std::upper_bound(focal_rows_.begin(), focal_rows_.end(), focal,
                                       [direction](double wanted, const FieldOfViewRow& row) {
                                         return wanted < fieldOfViewSide(row.angles, direction);
                                       });
  if (beyond == focal_rows_.begin())
  {
    return focal_rows_.front().zoom;  // wider than the widest row
  }
  const FieldOfViewRow& low = *(beyond - 1);
  if (beyond == focal_rows_.end())
  {
    return low.zoom;  // as narrow as the last row or narrower
  }
  const FieldOfViewRow& high = *beyond;  // its focal length is larger than the wanted one: no division by zero
  const double low_focal = fieldOfViewSide(low.angles, direction);
  const double fraction = (focal - low_focal) / (fieldOfViewSide(high.angles, direction) - low_focal);
  return low.zoom + fraction * (high.zoom - low.zoom);
}

double FieldOfViewModel::zoomShowing(const FieldOfViewAngles& span) const
{
  // fmin takes the other when one is NaN, and NaN only when both are.
  return std::fmin(zoomFor(span.horizontal, ViewDirection::HORIZONTAL),
                   zoomFor(span.vertical, ViewDirection::VERTICAL));
}

}  // namespace ptz_action_server
