/**
 * \file
 * \brief AxisCameraEmulator's `center` and `areazoom`: a point of the camera's own picture, in whole pixels of an
 * `imagewidth` x `imageheight` picture, turned into angles with the lens at the current zoom. The rest of the camera is
 * axis_camera_emulator.cpp's.
 */
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"

namespace ptz_action_server
{
namespace
{
/// \p text as \p count whole numbers separated by commas; false for anything else.
bool wholeNumbers(const std::string& text, std::size_t count, std::vector<double>& numbers)
{
  numbers.clear();
  std::size_t start = 0;
  while (numbers.size() < count)
  {
    const std::size_t comma = text.find(',', start);
    const bool last = numbers.size() + 1 == count;
    if ((comma == std::string::npos) != last)
    {
      return false;
    }
    double number = 0.0;
    if (!parseNumber(text.substr(start, last ? std::string::npos : comma - start), number) ||
        number != std::floor(number))
    {
      return false;
    }
    numbers.push_back(number);
    start = comma + 1;
  }
  return true;
}
}  // namespace

std::string AxisCameraEmulator::aimInPicture(std::map<std::string, std::string>& values, bool act, TimePoint now)
{
  const bool area = values.count("areazoom") > 0;
  if (!area && values.count("center") == 0)
  {
    return "";
  }
  if (area && zoom_table_.empty())
  {
    return "areazoom: unknown argument";  // a camera without zoom lists no area zoom
  }
  const char* name = area ? "areazoom" : "center";
  std::vector<double> point;
  if (!wholeNumbers(values[name], area ? 3 : 2, point) || (area && point[2] < 1.0))
  {
    return std::string(name) + ": bad value: " + values[name];
  }
  double size[2] = { static_cast<double>(config_.image_width), static_cast<double>(config_.image_height) };
  const char* const size_names[2] = { "imagewidth", "imageheight" };
  for (int index = 0; index < 2; ++index)
  {
    if (values.count(size_names[index]) &&
        (!parseNumber(values[size_names[index]], size[index]) || !(size[index] >= 1.0)))
    {
      return std::string(size_names[index]) + ": bad value: " + values[size_names[index]];
    }
  }
  if (!act)
  {
    return "";
  }
  const PtzSample state = model_.sample(now);
  const FieldOfViewAngles view = optics_.at(state.position[ZOOM]);
  // Pixels from the top-left corner; the picture's centre is (width / 2, height / 2).
  const double x = 2.0 * point[0] / size[0] - 1.0;
  const double y = 1.0 - 2.0 * point[1] / size[1];
  double pan = 0.0;
  double tilt = 0.0;
  centreOf(state.position[PAN], state.position[TILT], view, x, y, pan, tilt);
  model_.goToAxis(PAN, pan, now);
  model_.goToAxis(TILT, tilt, now);
  if (area)
  {
    model_.goToAxis(ZOOM, state.position[ZOOM] * point[2] / 100.0, now);  // the lens ends where it ends
  }
  return "";
}

}  // namespace ptz_action_server
