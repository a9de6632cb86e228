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

bool ViscaModel::preset(const std::string& name, ViscaModel& model)
{
  ViscaModel chosen;
  chosen.name = name;
  if (name == "evi_d70")
  {
    // EVI-D70 technical manual: pan F725h..08DBh = -170..+170 degrees, tilt FE70h..04B0h = -30..+90 (0.075 degrees a
    // step); pan speed bytes 01..18h up to 100 deg/s, tilt 01..17h up to 90 deg/s; optical zoom 0000h..4000h, 18x.
    chosen.axes = { { { 13.3333, -170.0, 170.0, 0x18, 100.0 }, { 13.3333, -30.0, 90.0, 0x17, 90.0 } } };
    chosen.zoom_table = { { 0x0000, 1.0 }, { 0x4000, 18.0 } };
  }
  else if (name == "evi_d30")
  {
    // EVI-D30/D31: pan FC90h..0370h = -100..+100 degrees, tilt FED4h..012Ch = -25..+25; pan bytes 01..18h at 3.3
    // deg/s each (80), tilt 01..14h at 2.5 each (50); zoom 0000h..03FFh, 12x.
    chosen.axes = { { { 8.8, -100.0, 100.0, 0x18, 80.0 }, { 12.0, -25.0, 25.0, 0x14, 50.0 } } };
    chosen.zoom_table = { { 0x0000, 1.0 }, { 0x03FF, 12.0 } };
  }
  else if (name != "ptzoptics")
  {
    return false;
  }
  model = chosen;
  return true;
}

const char* ViscaModel::presetNames()
{
  return "evi_d70, evi_d30, ptzoptics";
}

std::int16_t ViscaModel::toSteps(Axis axis, double radians) const
{
  const double steps = std::round(toDegrees(radians) * axes[axis].steps_per_degree);
  return static_cast<std::int16_t>(std::clamp(steps, double(std::numeric_limits<std::int16_t>::min()),
                                              double(std::numeric_limits<std::int16_t>::max())));
}

double ViscaModel::fromSteps(Axis axis, std::int16_t steps) const
{
  return toRadians(steps / axes[axis].steps_per_degree);
}

std::uint8_t ViscaModel::speedByte(Axis axis, double speed) const
{
  const ViscaAxis& visca_axis = axes[axis];
  if (speed == 0.0 || !(visca_axis.max_speed > 0.0))
  {
    return 0;
  }
  const double share = std::abs(toDegrees(speed)) / visca_axis.max_speed;
  return static_cast<std::uint8_t>(
      std::clamp(static_cast<int>(std::lround(share * visca_axis.max_speed_byte)), 1, int(visca_axis.max_speed_byte)));
}

double ViscaModel::speedOfByte(Axis axis, std::uint8_t byte) const
{
  const ViscaAxis& visca_axis = axes[axis];
  const int clamped = std::min<int>(byte, visca_axis.max_speed_byte);
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
  result[ZOOM] = has_zoom ? fullAxis({ zoom_table.front().zoom, zoom_table.back().zoom }, zoom_rate, 0.0) :
                            absentAxis("this VISCA model has no zoom");
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
