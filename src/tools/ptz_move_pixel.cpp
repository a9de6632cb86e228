/**
 * \file
 * \brief ptz_move pixel: centres a pixel of the camera's latest image, or zooms to a box of it (the pixel action).
 */
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>

#include "ptz_action_server/PtzPixelAction.h"
#include "ptz_move.h"
#include "ptz_move_run.h"

namespace ptz_action_server::ptz_move
{
int pixel(const Options& options)
{
  const std::size_t count = options.words.size() - 1;
  if (count != 2 && count != 4)
  {
    fail("'pixel' takes a pixel U V, and optionally a box's width and height W H (px)");
  }
  std::vector<double> values;
  for (std::size_t index = 1; index < options.words.size(); ++index)
  {
    double value = 0.0;
    if (!parseNumber(options.words[index], value))
    {
      fail("'" + options.words[index] + "' is not a number");
    }
    values.push_back(value);
  }
  // The image the pixel belongs to: the latest one, known by its camera_info (same stamp and size, and small).
  const std::string topic = options.camera_info.empty() ? options.ns + "/camera_info" : options.camera_info;
  const auto info = ros::topic::waitForMessage<sensor_msgs::CameraInfo>(topic, ros::Duration(options.wait));
  if (!info)
  {
    std::fprintf(stderr, "ptz_move: no camera_info on %s within %g s (name the image's with --camera-info)\n",
                 topic.c_str(), options.wait);
    return 1;
  }
  PtzPixelGoal goal;
  goal.image_header = info->header;
  goal.image_width = info->width;
  goal.image_height = info->height;
  goal.u = values[0];
  goal.v = values[1];
  if (values.size() == 4)
  {
    goal.box_width = values[2];
    goal.box_height = values[3];
  }
  const std::string box =
      values.size() == 4 ? " and filling the view with its " + options.words[3] + " x " + options.words[4] + " px box" :
                           "";
  std::printf("centring pixel (%g, %g)%s of the %u x %u image at %.3f s (%s)\n", goal.u, goal.v, box.c_str(),
              info->width, info->height, info->header.stamp.toSec(), topic.c_str());
  const double scale = options.degrees ? 180.0 / M_PI : 1.0;
  const char* unit = options.degrees ? "deg" : "rad";
  return run<PtzPixelAction>(options, "pixel", goal, [&](const PtzPixelResult& result) {
    if (std::isfinite(result.pan))
    {
      std::printf("  aimed at pan %.4f %s, tilt %.4f %s, zoom %.2f X%s\n", result.pan * scale, unit,
                  result.tilt * scale, unit, result.zoom, result.zoom == 0.0f ? " (left alone)" : "");
    }
  });
}

}  // namespace ptz_action_server::ptz_move
