/**
 * \file
 * \brief The simulated camera's picture on image_raw and camera_info, rendered on a thread of its own while watched.
 */
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <image_transport/image_transport.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/motion/field_of_view.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/render/camera_renderer.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/// The simulated camera's settings (~camera/...).
struct SimCameraSettings
{
  bool enabled = false;
  int width = 640;                  ///< px
  int height = 360;                 ///< px
  double rate = 10.0;               ///< Hz, while someone watches
  std::vector<std::string> frames;  ///< tf frames drawn as markers, in the marker colours' order
  std::string frame_id;             ///< the images' and camera_info's frame: the camera's optical frame
  RenderSettings render;
  /// The lens: the node's field of view, or 60 degrees across with square pixels when it has none.
  std::optional<FieldOfViewModel> lens;

  /// Reads ~camera/enabled (default \p enabled_by_default), width, height, rate, frames, frame_id (default: the
  /// URDF's optical frame beside \p kinematics' camera link) and marker_radius from \p camera (the reader of
  /// ~camera). \p field_of_view is the node's lens, if it has one. Throws ConfigError naming the parameter.
  static SimCameraSettings load(const ParamReader& camera, bool enabled_by_default, const PtzKinematics& kinematics,
                                const std::optional<FieldOfViewModel>& field_of_view);
};

/**
 * \brief Publishes what the simulated camera sees (CameraRenderer) through image_transport: image_raw (rgb8) and
 * camera_info (the pinhole model of the field of view at the current zoom), in the node's namespace.
 *
 * One thread of its own, never the node's queues or the state tick: it sleeps while nobody subscribes (to either
 * topic), and while someone does it renders at the settings' rate, each image from the backend's state at that moment
 * (pan, tilt and zoom as the contract has them, the camera's pose from the URDF) and stamped with that state's time,
 * as joint_states is. The listed frames come from a tf listener that exists only while someone subscribes; a frame
 * tf does not know is left out (and named once in the log). The thread runs its own callback queue: the
 * subscriber-connect callbacks wake it, the tf listener's messages arrive on it between two frames. The image and
 * camera_info messages and the renderer's buffers are made with the first image and reused: a frame allocates nothing
 * of its own but what tf's lookups and roscpp's serialization do.
 */
class SimCameraPublisher
{
public:
  /// Advertises image_raw and camera_info in \p node_handle's namespace and starts the thread. \p settings must be
  /// enabled and hold a lens; \p backend must outlive the publisher's use of it (until the destructor returns).
  SimCameraPublisher(const ros::NodeHandle& node_handle, const SimCameraSettings& settings,
                     const PtzKinematics& kinematics, std::shared_ptr<PtzBackend> backend);
  /// Stops the thread, then the topics.
  ~SimCameraPublisher();

  SimCameraPublisher(const SimCameraPublisher&) = delete;
  SimCameraPublisher& operator=(const SimCameraPublisher&) = delete;

private:
  void run();
  bool watched() const;
  /// Starts the tf listener (if there are frames to draw and it is not running).
  void listen();
  void stopListening();
  /// Renders one image from the backend's state now and publishes it with its camera_info.
  void publishFrame();
  /// The listed frames' positions in the base frame, from tf.
  void updateMarkers();
  ros::Time toRosTime(TimePoint stamp) const;

  const SimCameraSettings settings_;
  const FieldOfViewModel& lens_;  ///< settings_.lens's value
  const PtzKinematics kinematics_;
  const std::shared_ptr<PtzBackend> backend_;
  SystemClock clock_;

  ros::CallbackQueue queue_;     ///< the thread's: connect callbacks and tf
  ros::NodeHandle node_handle_;  ///< on queue_
  std::unique_ptr<image_transport::ImageTransport> transport_;
  image_transport::CameraPublisher publisher_;

  // Only the thread touches these once it runs.
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  ros::WallTime listening_since_;
  std::vector<bool> reported_missing_;  ///< per frame: its absence from tf was logged while listening
  std::vector<SceneMarker> markers_;
  CameraRenderer renderer_;
  sensor_msgs::Image image_;
  sensor_msgs::CameraInfo info_;
  bool reported_unknown_pose_ = false;

  std::atomic<bool> stopping_{ false };
  std::thread thread_;  ///< last: runs on everything above
};

}  // namespace ptz_action_server
