#include "ptz_action_server/core/visca/visca_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace visca
{
namespace
{
/// The fastest zoom drive speed: p = 7, speed 8 here.
constexpr int ZOOM_SPEEDS = 8;
}  // namespace

std::int32_t ViscaModel::toSteps(Axis axis, double radians) const
{
  const ViscaAxis& visca_axis = axes[axis];
  const double steps = std::round(toDegrees(radians) * visca_axis.steps_per_degree) * (visca_axis.reversed ? -1 : 1);
  const double limit = PositionLayout::limit(axis == PAN ? layout.pan_nibbles : layout.tilt_nibbles);
  return static_cast<std::int32_t>(std::clamp(steps, -limit - 1, limit));
}

double ViscaModel::fromSteps(Axis axis, std::int32_t steps) const
{
  const ViscaAxis& visca_axis = axes[axis];
  return toRadians(steps / visca_axis.steps_per_degree) * (visca_axis.reversed ? -1 : 1);
}

std::uint8_t ViscaModel::speedByte(Axis axis, double speed) const
{
  const ViscaAxis& visca_axis = axes[axis];
  if (speed == 0.0 || !(visca_axis.max_speed > 0.0))
  {
    return 0;
  }
  const double degrees = std::abs(toDegrees(speed));
  if (!visca_axis.speed_table.empty())
  {
    // The byte whose speed in the maker's table is nearest (the tables rise unevenly).
    const std::vector<double>& table = visca_axis.speed_table;
    std::size_t best = 0;
    for (std::size_t index = 1; index < table.size(); ++index)
    {
      if (std::abs(table[index] - degrees) < std::abs(table[best] - degrees))
      {
        best = index;
      }
    }
    return static_cast<std::uint8_t>(best + 1);
  }
  const double share = degrees / visca_axis.max_speed;
  return static_cast<std::uint8_t>(
      std::clamp(static_cast<int>(std::lround(share * visca_axis.max_speed_byte)), 1, int(visca_axis.max_speed_byte)));
}

double ViscaModel::speedOfByte(Axis axis, std::uint8_t byte) const
{
  const ViscaAxis& visca_axis = axes[axis];
  const int clamped = std::min<int>(byte, visca_axis.max_speed_byte);
  if (clamped <= 0)
  {
    return 0.0;
  }
  if (!visca_axis.speed_table.empty())
  {
    return toRadians(visca_axis.speed_table[std::min<std::size_t>(clamped, visca_axis.speed_table.size()) - 1]);
  }
  return toRadians(visca_axis.max_speed * clamped / visca_axis.max_speed_byte);
}

int ViscaModel::zoomSpeed(double rate) const
{
  if (rate == 0.0 || !(zoom_rate > 0.0))
  {
    return 0;
  }
  const int magnitude =
      std::clamp(static_cast<int>(std::lround(std::abs(rate) / zoom_rate * ZOOM_SPEEDS)), 1, ZOOM_SPEEDS);
  return rate > 0.0 ? magnitude : -magnitude;
}

double ViscaModel::rateOfZoomSpeed(int speed) const
{
  return zoom_rate * std::clamp(speed, -ZOOM_SPEEDS, ZOOM_SPEEDS) / ZOOM_SPEEDS;
}

std::uint16_t ViscaModel::zoomToPosition(double zoom) const
{
  if (zoom <= zoom_table.front().zoom)
  {
    return zoom_table.front().position;
  }
  for (std::size_t index = 1; index < zoom_table.size(); ++index)
  {
    const ZoomPoint& low = zoom_table[index - 1];
    const ZoomPoint& high = zoom_table[index];
    if (zoom <= high.zoom)
    {
      const double share = (zoom - low.zoom) / (high.zoom - low.zoom);
      return static_cast<std::uint16_t>(std::lround(low.position + share * (high.position - low.position)));
    }
  }
  return zoom_table.back().position;
}

double ViscaModel::positionToZoom(std::uint16_t position) const
{
  if (position <= zoom_table.front().position)
  {
    return zoom_table.front().zoom;
  }
  for (std::size_t index = 1; index < zoom_table.size(); ++index)
  {
    const ZoomPoint& low = zoom_table[index - 1];
    const ZoomPoint& high = zoom_table[index];
    if (position <= high.position)
    {
      const double share = double(position - low.position) / double(high.position - low.position);
      return low.zoom + share * (high.zoom - low.zoom);
    }
  }
  return zoom_table.back().zoom;
}

std::array<AxisCapability, AXIS_COUNT> ViscaModel::capabilities() const
{
  std::array<AxisCapability, AXIS_COUNT> result;
  for (Axis axis : { PAN, TILT })
  {
    const ViscaAxis& visca_axis = axes[axis];
    result[axis] = fullAxis({ toRadians(visca_axis.min_degrees), toRadians(visca_axis.max_degrees) },
                            toRadians(visca_axis.max_speed), acceleration);
  }
  if (!has_zoom)
  {
    result[ZOOM] = absentAxis("this VISCA model has no zoom");
    return result;
  }
  result[ZOOM] = fullAxis({ zoom_table.front().zoom, zoom_table.back().zoom }, zoom_rate, 0.0);
  if (!zoom_table_known)
  {
    // The camera reports zoom positions, but what X-factor each gives depends on its lens: never judged in X.
    AxisCapability& zoom = result[ZOOM];
    zoom.absolute = false;
    zoom.feedback = false;
    zoom.widest_view = true;  // position 0000 is the wide end whatever the lens
    zoom.limitation = "the X-factor of this VISCA camera's zoom positions depends on its lens (" + name + ")";
    zoom.remedy = "set visca/zoom/table to the lens's 'position:X' rows";
  }
  return result;
}

std::string ViscaModel::check() const
{
  for (Axis axis : { PAN, TILT })
  {
    const ViscaAxis& visca_axis = axes[axis];
    if (!(visca_axis.steps_per_degree > 0.0) || !(visca_axis.min_degrees < visca_axis.max_degrees) ||
        visca_axis.max_speed_byte == 0 || !(visca_axis.max_speed > 0.0))
    {
      return std::string("the ") + axisName(axis) +
             " axis needs steps_per_degree > 0, min < max, a speed byte >= 1 and a speed > 0";
    }
    const std::vector<double>& table = visca_axis.speed_table;
    if (!table.empty() && (table.size() != visca_axis.max_speed_byte || table.back() != visca_axis.max_speed ||
                           !std::is_sorted(table.begin(), table.end()) || !(table.front() > 0.0)))
    {
      return std::string("the ") + axisName(axis) +
             " axis' speed table needs one rising speed > 0 per byte up to max_speed_byte, the last max_speed";
    }
  }
  for (std::uint8_t nibbles : { layout.pan_nibbles, layout.tilt_nibbles })
  {
    if (nibbles != 4 && nibbles != 5)
    {
      return "positions are 4 or 5 nibbles, not " + std::to_string(nibbles);
    }
  }
  if (zoom_table.size() < 2)
  {
    return "the zoom table needs at least two rows";
  }
  for (std::size_t index = 1; index < zoom_table.size(); ++index)
  {
    if (zoom_table[index].position <= zoom_table[index - 1].position ||
        zoom_table[index].zoom <= zoom_table[index - 1].zoom)
    {
      return "the zoom table's positions and X-factors must both rise";
    }
  }
  return {};
}

}  // namespace visca
}  // namespace ptz_action_server
