/**
 * \file
 * \brief bench_track_detections: how closely move_ptz/track_detections keeps a moving target centred, against the
 * target's angular speed and the detection latency, beside move_ptz/track_frame on the same path. Run by
 * bench/track_detections, which starts the sim node drawing the frame bench_track_target and ptz_blob_detector
 * publishing on detections_raw, once with the node's pose history (~track/pose_history true) and once without.
 *
 * For each speed (and, for track_detections, each added latency) the target circles the camera 10 m away, 0.1 rad up,
 * from where the camera looks: the goal is sent, the target starts 1 s later, and for JUDGE s after SETTLE s every
 * joint state is judged against where the target truly was at its stamp (rad: the optical axis's angle from the
 * target's direction) and every image by where the target's disc is (px: its centroid's distance from the image
 * centre). The detections reach the node through a relay here that holds each message for the added latency (the
 * header keeps the image's stamp, as a slow detector's would). Prints one table row per case; asserts nothing.
 *
 * usage: bench_track_detections [--pose-history on|off] [--track-frame] (in the node's namespace: ROS_NAMESPACE=/ptz)
 */
#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_broadcaster.h>

#include "ptz_action_server/Detections.h"
#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzFrameAction.h"
#include "ptz_action_server/PtzTrackDetectionsAction.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/ros/ptz_goal.h"

namespace
{
using namespace ptz_action_server;
const char* const TARGET = "bench_track_target";
constexpr std::uint8_t MAGENTA[3] = { 255, 0, 255 };
constexpr double DISTANCE = 10.0;  // m
constexpr double ELEVATION = 0.1;  // rad
constexpr double LEAD = 1.0;       // s the target waits after the goal is sent
constexpr double SETTLE = 1.5;     // s of motion not judged
constexpr double JUDGE = 5.0;      // s judged
constexpr double WAIT = 20.0;      // s for a goal

/// The target's azimuth: still at start until moving_since, then at speed.
struct Path
{
  std::atomic<double> start{ 0.0 };
  std::atomic<double> speed{ 0.0 };
  std::atomic<double> moving_since{ 0.0 };  ///< ROS time s; 0: still

  double azimuthAt(double now) const
  {
    const double since = moving_since;
    return start + (since == 0.0 || now < since ? 0.0 : speed * (now - since));
  }
  static Eigen::Vector3d positionAt(double azimuth)
  {
    return { DISTANCE * std::cos(ELEVATION) * std::cos(azimuth), -DISTANCE * std::cos(ELEVATION) * std::sin(azimuth),
             DISTANCE * std::sin(ELEVATION) };
  }
};

/// Holds each Detections message for the added latency, then publishes it unchanged on detections.
class Relay
{
public:
  explicit Relay(ros::NodeHandle& node_handle)
    : publisher_(node_handle.advertise<Detections>("detections", 10))
    , subscriber_(node_handle.subscribe("detections_raw", 10, &Relay::onDetections, this))
    , thread_([this] { run(); })
  {
  }
  ~Relay()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      running_ = false;
    }
    wake_.notify_all();
    thread_.join();
  }
  void setDelay(double seconds)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    delay_ = seconds;
    latencies_.clear();
  }
  /// s from each image's stamp to its detections' publication here, since setDelay().
  std::vector<double> latencies()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return latencies_;
  }

private:
  void onDetections(const Detections::ConstPtr& message)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    held_.push_back({ ros::WallTime::now() + ros::WallDuration(delay_), message });
    wake_.notify_all();
  }
  void run()
  {
    std::unique_lock<std::mutex> lock(mutex_);
    while (running_)
    {
      if (held_.empty())
      {
        wake_.wait(lock);
        continue;
      }
      const ros::WallDuration left = held_.front().first - ros::WallTime::now();
      if (left > ros::WallDuration(0))
      {
        wake_.wait_for(lock, std::chrono::nanoseconds(left.toNSec()));
        continue;
      }
      const Detections::ConstPtr message = held_.front().second;
      held_.pop_front();
      latencies_.push_back((ros::Time::now() - message->header.stamp).toSec());
      publisher_.publish(message);
    }
  }

  ros::Publisher publisher_;
  ros::Subscriber subscriber_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool running_ = true;
  double delay_ = 0.0;
  std::deque<std::pair<ros::WallTime, Detections::ConstPtr>> held_;
  std::vector<double> latencies_;
  std::thread thread_;
};

/// The errors of the judged window: rad from the joint states, px from the images.
class Judge
{
public:
  Judge(ros::NodeHandle& node_handle, const PtzKinematics& kinematics, const Path& path)
    : kinematics_(kinematics)
    , path_(path)
    , states_(node_handle.subscribe("joint_states", 100, &Judge::onState, this))
    , images_(node_handle.subscribe("image_raw", 5, &Judge::onImage, this))
  {
  }
  void window(double from, double to)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    from_ = from;
    to_ = to;
    radians_.clear();
    pixels_.clear();
    images_without_ = 0;
  }
  void results(std::vector<double>& radians, std::vector<double>& pixels, int& images_without)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    radians = radians_;
    pixels = pixels_;
    images_without = images_without_;
  }

private:
  bool judged(double stamp) const
  {
    return stamp >= from_ && stamp <= to_;
  }
  Eigen::Vector3d axis(double pan, double tilt) const
  {
    return kinematics_.cameraInBase(pan, tilt).linear() * Eigen::Vector3d::UnitX();
  }
  void onState(const sensor_msgs::JointState::ConstPtr& state)
  {
    const double stamp = state->header.stamp.toSec();
    std::lock_guard<std::mutex> lock(mutex_);
    if (!judged(stamp) || state->position.size() < 2)
    {
      return;
    }
    double pan = 0.0;
    double tilt = 0.0;
    kinematics_.aimAt(Path::positionAt(path_.azimuthAt(stamp)), pan, tilt);
    const double cosine = axis(state->position[0], state->position[1]).dot(axis(pan, tilt));
    radians_.push_back(std::acos(std::min(1.0, cosine)));
  }
  void onImage(const sensor_msgs::Image::ConstPtr& image)
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!judged(image->header.stamp.toSec()))
      {
        return;
      }
    }
    double sum_u = 0.0;
    double sum_v = 0.0;
    int count = 0;
    for (std::uint32_t row = 0; row < image->height; ++row)
    {
      const std::uint8_t* pixel = &image->data[row * image->step];
      for (std::uint32_t column = 0; column < image->width; ++column, pixel += 3)
      {
        if (pixel[0] == MAGENTA[0] && pixel[1] == MAGENTA[1] && pixel[2] == MAGENTA[2])
        {
          sum_u += column;
          sum_v += row;
          ++count;
        }
      }
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (count == 0)
    {
      ++images_without_;
      return;
    }
    pixels_.push_back(std::hypot(sum_u / count - (image->width - 1) / 2.0, sum_v / count - (image->height - 1) / 2.0));
  }

  const PtzKinematics& kinematics_;
  const Path& path_;
  std::mutex mutex_;
  double from_ = 0.0;
  double to_ = 0.0;
  std::vector<double> radians_;
  std::vector<double> pixels_;
  int images_without_ = 0;
  ros::Subscriber states_;
  ros::Subscriber images_;
};

double percentile(std::vector<double> values, double fraction)
{
  if (values.empty())
  {
    return NAN;
  }
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<std::size_t>(fraction * values.size()))];
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "bench_track_detections", ros::init_options::AnonymousName);
  std::string pose_history = "on";
  bool track_frame = false;
  for (int index = 1; index < argc; ++index)
  {
    const std::string arg = argv[index];
    if (arg == "--pose-history" && index + 1 < argc)
    {
      pose_history = argv[++index];
    }
    else if (arg == "--track-frame")
    {
      track_frame = true;
    }
  }
  ros::AsyncSpinner spinner(2);
  spinner.start();
  ros::NodeHandle node_handle;
  actionlib::SimpleActionClient<PtzAction> absolute("move_ptz/position_abs", true);
  actionlib::SimpleActionClient<PtzTrackDetectionsAction> detections("move_ptz/track_detections", true);
  actionlib::SimpleActionClient<PtzFrameAction> frame("move_ptz/track_frame", true);
  std::string urdf;
  if (!absolute.waitForServer(ros::Duration(30.0)) || !detections.waitForServer(ros::Duration(30.0)) ||
      !frame.waitForServer(ros::Duration(30.0)) || !node_handle.getParam("robot_description", urdf))
  {
    std::fprintf(stderr, "bench_track_detections: no node (its actions and robot_description)\n");
    return 1;
  }
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(urdf);
  Path path;
  Relay relay(node_handle);
  Judge judge(node_handle, kinematics, path);
  std::atomic<bool> broadcasting{ true };
  std::thread broadcaster_thread([&] {
    tf2_ros::TransformBroadcaster broadcaster;
    geometry_msgs::TransformStamped transform;
    transform.header.frame_id = kinematics.baseFrame();
    transform.child_frame_id = TARGET;
    transform.transform.rotation.w = 1.0;
    ros::WallRate rate(50.0);
    while (broadcasting && ros::ok())
    {
      transform.header.stamp = ros::Time::now();
      const Eigen::Vector3d position = Path::positionAt(path.azimuthAt(transform.header.stamp.toSec()));
      transform.transform.translation.x = position.x();
      transform.transform.translation.y = position.y();
      transform.transform.translation.z = position.z();
      broadcaster.sendTransform(transform);
      rate.sleep();
    }
  });

  const auto run = [&](double speed, double delay, bool by_frame) {
    path.moving_since = 0.0;
    path.speed = speed;
    path.start = -speed * (LEAD + SETTLE + JUDGE) / 2.0;  // ends as far right as it starts left
    relay.setDelay(delay);
    double pan = 0.0;
    double tilt = 0.0;
    kinematics.aimAt(Path::positionAt(path.start), pan, tilt);
    absolute.sendGoal(makePtzGoal(pan, tilt, 1.0));
    absolute.waitForResult(ros::Duration(WAIT));
    if (by_frame)
    {
      PtzFrameGoal goal;
      goal.frame_id = TARGET;
      goal.zoom = 1.0;
      frame.sendGoal(goal);
    }
    else
    {
      PtzTrackDetectionsGoal goal;
      goal.detections_topic = "detections";
      goal.lost_timeout = 5.0;
      detections.sendGoal(goal);
    }
    ros::WallDuration(LEAD).sleep();
    const double since = ros::Time::now().toSec();
    path.moving_since = since;
    judge.window(since + SETTLE, since + SETTLE + JUDGE);
    ros::WallDuration(SETTLE + JUDGE + 0.3).sleep();
    const bool tracking = by_frame ? frame.getState() == actionlib::SimpleClientGoalState::ACTIVE :
                                     detections.getState() == actionlib::SimpleClientGoalState::ACTIVE;
    (by_frame ? frame.cancelGoal() : detections.cancelGoal());
    (by_frame ? frame.waitForResult(ros::Duration(WAIT)) : detections.waitForResult(ros::Duration(WAIT)));
    std::vector<double> radians;
    std::vector<double> pixels;
    int images_without = 0;
    judge.results(radians, pixels, images_without);
    const std::vector<double> latencies = relay.latencies();
    const double latency = percentile(latencies, 0.5);
    std::printf("| %s | %s | %.2f | %s | %s | %.4f | %.4f | %.1f | %.1f | %zu of %d |%s\n",
                by_frame ? "track_frame" : "track_detections", by_frame ? "(tf: the truth)" : pose_history.c_str(),
                speed, by_frame ? "-" : std::to_string(delay).substr(0, 4).c_str(),
                by_frame ? "-" : std::to_string(latency).substr(0, 5).c_str(), percentile(radians, 0.5),
                percentile(radians, 0.95), percentile(pixels, 0.5), percentile(pixels, 0.95), pixels.size(),
                static_cast<int>(pixels.size()) + images_without, tracking ? "" : " (the goal ended early)");
    std::fflush(stdout);
  };

  std::printf("| goal | pose history | target rad/s | added latency s | latency p50 s | rad p50 | rad p95 | px p50 | "
              "px p95 | images with the target |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const double speed : { 0.1, 0.3, 0.6 })
  {
    for (const double delay : { 0.0, 0.2 })
    {
      run(speed, delay, false);
    }
    if (track_frame)
    {
      run(speed, 0.0, true);
    }
  }
  broadcasting = false;
  broadcaster_thread.join();
  return 0;
}
