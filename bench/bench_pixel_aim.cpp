/**
 * \file
 * \brief bench_pixel_aim: click to centre on the simulated camera, timed and measured. Run by bench/pixel_aim (which
 * starts the node drawing the frame bench_pixel_marker, broadcast here 100 m away in the direction pan 0.35, tilt 0.15
 * from the camera's axes): for each of 24 spots of the picture
 * it turns the camera so the marker shows there, finds the marker's pixel by colour in one image and sends a pixel
 * goal on that image; the time from the goal sent to its success, the marker's distance from the image centre
 * in the first image after it, in px, and the angle between the result's aim and the marker's true direction. Then the
 * same with a moving camera: each click on an image taken while a long position goal turns the camera (the pixel goal
 * preempts it). Prints p50, p95 and max; asserts nothing.
 *
 * usage: bench_pixel_aim (in the node's namespace, /ptz: ROS_NAMESPACE=/ptz)
 */
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzPixelAction.h"
#include "ptz_action_server/ros/ptz_goal.h"

namespace
{
using namespace ptz_action_server;
constexpr double MARKER_PAN = 0.35;  // rad, from the URDF's tilt axis, 0.12 m above ptz_base_link
constexpr double MARKER_TILT = 0.15;
constexpr double MARKER_DISTANCE = 100.0;  // m: the camera's offset from its axes shifts it by a tenth of a pixel
constexpr std::uint8_t MAGENTA[3] = { 255, 0, 255 };  // the first listed frame's colour
constexpr double WAIT = 20.0;                         // s

/// The latest image and its camera_info (same stamp).
class Camera
{
public:
  Camera()
  {
    ros::NodeHandle node_handle;
    images_ = node_handle.subscribe("image_raw", 2, &Camera::onImage, this);
    infos_ = node_handle.subscribe("camera_info", 10, &Camera::onInfo, this);
  }

  /// Waits for an image stamped after \p after that \p wanted accepts; false after WAIT s.
  bool next(const ros::Time& after, const std::function<bool(const sensor_msgs::Image&)>& wanted,
            sensor_msgs::Image& image, sensor_msgs::CameraInfo& info)
  {
    ros::Time looked_at;
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(WAIT);
    while (ros::WallTime::now() < deadline)
    {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (image_.header.stamp > after && image_.header.stamp != looked_at &&
            info_.header.stamp == image_.header.stamp)
        {
          looked_at = image_.header.stamp;
          if (wanted(image_))
          {
            image = image_;
            info = info_;
            return true;
          }
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
  }

private:
  void onImage(const sensor_msgs::Image::ConstPtr& image)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    image_ = *image;
  }
  void onInfo(const sensor_msgs::CameraInfo::ConstPtr& info)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    info_ = *info;
  }

  std::mutex mutex_;
  sensor_msgs::Image image_;
  sensor_msgs::CameraInfo info_;
  ros::Subscriber images_;
  ros::Subscriber infos_;
};

/// The centroid of the marker's pixels, if it is in the image clear of its edges.
bool marker(const sensor_msgs::Image& image, double& u, double& v)
{
  double sum_u = 0.0;
  double sum_v = 0.0;
  int pixels = 0;
  bool at_edge = false;
  for (std::uint32_t row = 0; row < image.height; ++row)
  {
    const std::uint8_t* pixel = &image.data[row * image.step];
    for (std::uint32_t column = 0; column < image.width; ++column, pixel += 3)
    {
      if (pixel[0] == MAGENTA[0] && pixel[1] == MAGENTA[1] && pixel[2] == MAGENTA[2])
      {
        sum_u += column;
        sum_v += row;
        ++pixels;
        at_edge = at_edge || row == 0 || column == 0 || row + 1 == image.height || column + 1 == image.width;
      }
    }
  }
  if (pixels == 0 || at_edge)
  {
    return false;
  }
  u = sum_u / pixels;
  v = sum_v / pixels;
  return true;
}

double percentile(std::vector<double> values, double fraction)
{
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<std::size_t>(fraction * values.size()))];
}

struct Click
{
  double seconds = 0.0;  ///< goal sent to success
  double error = 0.0;    ///< px from the centre after success
  double aim = 0.0;      ///< rad between the result's aim and the marker's direction
  double angle = 0.0;    ///< rad the camera turned for it (from the image's pose)
};

/// Sends a pixel goal on the marker of \p image; false if it did not succeed.
bool centre(actionlib::SimpleActionClient<PtzPixelAction>& pixel, Camera& camera, const sensor_msgs::Image& image,
            double u, double v, Click& click)
{
  PtzPixelGoal goal;
  goal.image_header = image.header;
  goal.image_width = image.width;
  goal.image_height = image.height;
  goal.u = u;
  goal.v = v;
  const ros::WallTime sent = ros::WallTime::now();
  pixel.sendGoal(goal);
  if (!pixel.waitForResult(ros::Duration(WAIT)) || pixel.getState() != actionlib::SimpleClientGoalState::SUCCEEDED)
  {
    std::fprintf(stderr, "pixel goal: %s: %s\n", pixel.getState().toString().c_str(),
                 pixel.getState().getText().c_str());
    return false;
  }
  click.seconds = (ros::WallTime::now() - sent).toSec();
  const auto result = pixel.getResult();
  click.aim = std::hypot((result->pan - MARKER_PAN) * std::cos(MARKER_TILT), result->tilt - MARKER_TILT);
  sensor_msgs::Image after;
  sensor_msgs::CameraInfo info;
  double centre_u = 0.0;
  double centre_v = 0.0;
  if (!camera.next(
          ros::Time::now(), [&](const sensor_msgs::Image& candidate) { return marker(candidate, centre_u, centre_v); },
          after, info))
  {
    std::fprintf(stderr, "no marker after the goal\n");
    return false;
  }
  click.error = std::hypot(centre_u - info.K[2], centre_v - info.K[5]);
  return true;
}

void print(const char* name, const std::vector<Click>& clicks)
{
  std::vector<double> seconds;
  std::vector<double> errors;
  std::vector<double> aims;
  double angle = 0.0;
  for (const Click& click : clicks)
  {
    seconds.push_back(click.seconds * 1000.0);
    errors.push_back(click.error);
    aims.push_back(click.aim * 1000.0);
    angle += click.angle / static_cast<double>(clicks.size());
  }
  if (clicks.empty())
  {
    std::printf("| %s | no click succeeded | | | | | | | | | |\n", name);
    return;
  }
  const std::string turn = std::isnan(angle) ? "-" : std::to_string(angle).substr(0, 4);
  std::printf("| %s | %zu | %s | %.0f | %.0f | %.0f | %.2f | %.2f | %.2f | %.3f | %.3f |\n", name, clicks.size(),
              turn.c_str(), percentile(seconds, 0.5), percentile(seconds, 0.95), percentile(seconds, 1.0),
              percentile(errors, 0.5), percentile(errors, 0.95), percentile(errors, 1.0), percentile(aims, 0.5),
              percentile(aims, 0.95));
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "bench_pixel_aim", ros::init_options::AnonymousName);
  ros::AsyncSpinner spinner(2);
  spinner.start();
  actionlib::SimpleActionClient<PtzAction> absolute("move_ptz/position_abs", true);
  actionlib::SimpleActionClient<PtzPixelAction> pixel("move_ptz/pixel", true);
  if (!absolute.waitForServer(ros::Duration(30.0)) || !pixel.waitForServer(ros::Duration(30.0)))
  {
    std::fprintf(stderr, "bench_pixel_aim: no node (move_ptz/position_abs and move_ptz/pixel)\n");
    return 1;
  }
  tf2_ros::StaticTransformBroadcaster broadcaster;
  geometry_msgs::TransformStamped frame;
  frame.header.frame_id = "ptz_base_link";
  frame.header.stamp = ros::Time::now();
  frame.child_frame_id = "bench_pixel_marker";
  frame.transform.translation.x = MARKER_DISTANCE * std::cos(MARKER_TILT) * std::cos(MARKER_PAN);
  frame.transform.translation.y = -MARKER_DISTANCE * std::cos(MARKER_TILT) * std::sin(MARKER_PAN);
  frame.transform.translation.z = 0.12 + MARKER_DISTANCE * std::sin(MARKER_TILT);
  frame.transform.rotation.w = 1.0;
  broadcaster.sendTransform(frame);
  Camera camera;
  const auto goTo = [&](double pan, double tilt) {
    absolute.sendGoal(makePtzGoal(pan, tilt, 1.0));
    return absolute.waitForResult(ros::Duration(WAIT)) &&
           absolute.getState() == actionlib::SimpleClientGoalState::SUCCEEDED;
  };
  // 24 spots: the marker 0.15, 0.25 and 0.35 rad either side of the centre, and 0.06 and 0.18 rad above and below
  // (of a view 1.05 x 0.63 rad at 1 X).
  std::vector<Click> at_rest;
  std::vector<Click> moving;
  for (const double pan_offset : { -0.35, -0.25, -0.15, 0.15, 0.25, 0.35 })
  {
    for (const double tilt_offset : { -0.18, -0.06, 0.06, 0.18 })
    {
      sensor_msgs::Image image;
      sensor_msgs::CameraInfo info;
      double u = 0.0;
      double v = 0.0;
      Click click;
      if (goTo(MARKER_PAN + pan_offset, MARKER_TILT + tilt_offset) &&
          camera.next(
              ros::Time::now(), [&](const sensor_msgs::Image& candidate) { return marker(candidate, u, v); }, image,
              info) &&
          centre(pixel, camera, image, u, v, click))
      {
        click.angle = std::hypot(pan_offset, tilt_offset);
        at_rest.push_back(click);
      }
      else if (at_rest.empty())
      {
        std::fprintf(stderr, "bench_pixel_aim: the first click failed (is the node drawing bench_pixel_marker?)\n");
        return 1;
      }

      // Moving: from the far side of the marker, a long turn past it; the click on an image mid-way.
      const double side = pan_offset < 0.0 ? -1.0 : 1.0;
      if (!goTo(MARKER_PAN + side * 0.45, MARKER_TILT + tilt_offset))
      {
        continue;
      }
      absolute.sendGoal(makePtzGoal(MARKER_PAN - side * 1.5, MARKER_TILT + tilt_offset, 1.0));
      const ros::Time sent = ros::Time::now();
      // The first image where the marker has slid 40 px from where the turn's first image showed it: mid-turn.
      double start_u = 0.0;
      bool first = true;
      if (camera.next(
              sent,
              [&](const sensor_msgs::Image& candidate) {
                if (!marker(candidate, u, v))
                {
                  return false;
                }
                if (first)
                {
                  first = false;
                  start_u = u;
                }
                return std::abs(u - start_u) > 40.0;
              },
              image, info) &&
          centre(pixel, camera, image, u, v, click))
      {
        click.angle = std::nan("");  // the turn under way is what the click interrupts
        moving.push_back(click);
      }
    }
  }
  std::printf("click to centre on the sim (640x360, 1 X, 60 degrees across): goal sent to success, and the marker's "
              "distance from the principal point after it\n");
  std::printf("| camera | clicks | mean turn rad | p50 ms | p95 ms | max ms | p50 px | p95 px | max px | aim p50 mrad "
              "| aim p95 mrad |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  print("at rest", at_rest);
  print("moving (click on an image taken mid-turn)", moving);
  return 0;
}
