/**
 * \file
 * \brief The node as main() builds it, and as the benchmark does: settings, URDF, backend plugin, action server.
 */
#pragma once

#include <functional>
#include <memory>

#include <ros/callback_queue.h>
#include <ros/node_handle.h>

#include "ptz_action_server/core/timer_thread.h"
#include "ptz_action_server/ros/backend_loader.h"
#include "ptz_action_server/ros/ptz_action_server.h"
#include "ptz_action_server/ros/tick_costs.h"

namespace ptz_action_server
{
class SimCameraPublisher;

/**
 * \brief Owns what a running ptz_action_server is made of, in the order it must go: the simulated camera's picture,
 * the server, the backend, then the plugin library the backend's code lives in.
 */
class PtzNode
{
public:
  /// Lets a caller wrap the loaded backend (the benchmark stamps every command).
  using BackendWrapper = std::function<std::shared_ptr<PtzBackend>(std::shared_ptr<PtzBackend>)>;

  PtzNode();  // defined where SimCameraPublisher is complete
  ~PtzNode();
  PtzNode(const PtzNode&) = delete;
  PtzNode& operator=(const PtzNode&) = delete;

  /// Lets the benchmark measure the state tick's parts into \p costs (see TickCosts); before start().
  void setTickCosts(TickCosts* costs)
  {
    tick_costs_ = costs;
  }

  /// Reads the node's parameters (\p private_handle) and the URDF (robot_description in \p node_handle's
  /// namespace), loads and starts the backend, then the actions. Throws ConfigError or BackendError with the reason.
  void start(const ros::NodeHandle& node_handle, const ros::NodeHandle& private_handle,
             const BackendWrapper& wrap = BackendWrapper());

private:
  BackendLoader loader_;  ///< first: destroyed last
  std::shared_ptr<PtzBackend> backend_;
  std::unique_ptr<PtzActionServer> server_;
  std::unique_ptr<SimCameraPublisher> camera_;  ///< the picture (~camera/enabled), or null
  TickCosts* tick_costs_ = nullptr;
};

/**
 * \brief ros::spin() on the global queue, for a node's main thread, without its ten wake-ups a second: waits for a
 * callback until ros::shutdown() (which disables the queue, and so wakes the wait), running each as it comes.
 *
 * Made before the node starts, it also runs the timers of that queue (QueueTimer) between callbacks, on the same
 * thread: a timer's call (the status release after every goal) then wakes the main thread only, where the process's
 * TimerThread would wake and hand it over.
 */
class MainSpinner
{
public:
  MainSpinner();
  ~MainSpinner();
  MainSpinner(const MainSpinner&) = delete;
  MainSpinner& operator=(const MainSpinner&) = delete;

  /// Runs callbacks and due timers until ros::shutdown().
  void spinUntilShutdown();

private:
  ros::CallbackQueue* const queue_;
  const std::shared_ptr<TimerThread> timers_;
};

}  // namespace ptz_action_server
