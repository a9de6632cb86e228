/**
 * \file
 * \brief tf for the frame goals (position_abs_tf, frame), heard only while frame goals need it.
 */
#pragma once

#include <memory>
#include <string>

#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "ptz_action_server/ros/queue_timer.h"

namespace ptz_action_server
{
/**
 * \brief A tf buffer and listener that exist from a frame goal until `listen_time` after the last one.
 *
 * A tf listener receives every transform on the robot, its cost grows with the robot whether or not anyone sends a
 * frame goal: with 8 cameras on one master, each node's listener took every camera's tf at 10 Hz. So the node
 * listens only around frame goals. A listener that has just started has not heard the frames yet (/tf_static comes
 * at once, /tf at its publishers' rates): ready() says whether a goal may look its frame up now or should wait.
 *
 * One thread: the node's main queue (the listener, the timer and the callers).
 */
class FrameListener
{
public:
  /// \p listen_time: s to keep listening after the last frame goal; \p warm_up: s a new listener may need.
  FrameListener(const ros::NodeHandle& node_handle, double listen_time, double warm_up);

  /// Listens from now on (if it did not) and for listen_time after this call.
  void listen();
  bool listening() const
  {
    return listener_ != nullptr;
  }
  /// True when \p frame_id can be looked up in \p base_frame now, or the listener has listened for warm_up already
  /// (the answer will not change by waiting: the lookup then fails with tf's reason).
  bool ready(const std::string& base_frame, const std::string& frame_id) const;
  /// The buffer the frame goals look up; only while listening().
  const tf2_ros::Buffer& buffer() const
  {
    return *buffer_;
  }

private:
  void stopListening();

  ros::NodeHandle node_handle_;
  const double listen_time_;
  const double warm_up_;
  std::unique_ptr<tf2_ros::Buffer> buffer_;
  std::unique_ptr<tf2_ros::TransformListener> listener_;
  ros::SteadyTime listening_since_;
  QueueTimer quiet_timer_;  ///< one-shot: stops listening listen_time after the last frame goal
};

}  // namespace ptz_action_server
