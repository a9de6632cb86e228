#include "ptz_action_server/ros/ptz_node.h"

#include <algorithm>
#include <chrono>
#include <string>

#include <boost/make_shared.hpp>
#include <ros/callback_queue.h>

#include "ptz_action_server/core/closed_loop_backend.h"
#include "ptz_action_server/core/speed_shaping_backend.h"
#include "ptz_action_server/ros/function_callback.h"
#include "ptz_action_server/ros/queue_timer.h"
#include "ptz_action_server/ros/sim_camera_publisher.h"

namespace ptz_action_server
{
PtzNode::PtzNode() = default;

PtzNode::~PtzNode()
{
  camera_.reset();  // each stops using the backend before it goes
  server_.reset();
  backend_.reset();
}

void PtzNode::start(const ros::NodeHandle& node_handle, const ros::NodeHandle& private_handle,
                    const BackendWrapper& wrap)
{
  const ParamReader params(private_handle);
  NodeConfig config = NodeConfig::load(params);
  std::string urdf;
  if (!node_handle.getParam("robot_description", urdf))
  {
    throw ConfigError("parameter " + node_handle.resolveName("robot_description") +
                      " is not set: load the URDF first (the launch file does)");
  }
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(urdf, config.names);
  // The picture is the simulated camera's by default; another backend (joint_topics, for a simulator without a camera
  // of its own) draws it when ~camera/enabled asks.
  const std::string backend_name = config.backend.substr(config.backend.rfind('/') + 1);
  const SimCameraSettings camera =
      SimCameraSettings::load(params.child("camera"), backend_name == "sim", kinematics, config.field_of_view.model);
  // Pixel goals on the simulated camera's picture use its lens (the field of view, or its default); clicks on it
  // centre by default.
  std::shared_ptr<LatestImage> images;
  const std::string image_topic = node_handle.resolveName("image_raw");
  if (camera.enabled)
  {
    config.pixel.lens = camera.lens;
    if (!config.pixel.image_topic_set)
    {
      config.pixel.image_topic = image_topic;
    }
    images = std::make_shared<LatestImage>();
  }
  // Position goals on a device that only moves at a speed are steered on its state, in the device's own angles; the
  // mount maps those to the contract's, under everything else (goals, limits, state, tf).
  backend_ = applyMount(
      withClosedLoop(loader_.load(config.backend, params, kinematics, config.mount), config.monitor.tolerance),
      config.mount);
  // A position goal's speed on a device that takes none with its moves: the node streams the motion.
  backend_ = withSpeedShaping(backend_);
  if (wrap)
  {
    backend_ = wrap(backend_);
  }
  server_ = std::make_unique<PtzActionServer>(node_handle, config, kinematics, backend_);
  server_->setTickCosts(tick_costs_);
  server_->setLocalImages(images, image_topic);
  server_->start();
  if (camera.enabled)
  {
    camera_ = std::make_unique<SimCameraPublisher>(node_handle, camera, kinematics, backend_, server_->poseRecorder(),
                                                   images);
  }
}

MainSpinner::MainSpinner()
  : queue_(ros::getGlobalCallbackQueue()), timers_(std::make_shared<TimerThread>([queue = queue_] {
    // Another thread armed an earlier timer: an empty call ends the wait, and the loop looks at the timers again.
    queue->addCallback(boost::make_shared<FunctionCallback>([] {}));
  }))
{
  QueueTimer::scheduleOn(queue_, timers_);
}

MainSpinner::~MainSpinner()
{
  QueueTimer::scheduleOn(queue_, nullptr);
}

void MainSpinner::spinUntilShutdown()
{
  // ros::spin() waits at most 0.1 s at a time to look at ros::ok(). The wait here lasts until the next timer, or
  // long: ros::shutdown() (from SIGINT through roscpp's poll thread, or from any thread) disables the queue, which
  // wakes it at once; the timeout is only a backstop.
  constexpr double WAIT = 5.0;              // s
  while (ros::ok() && queue_->isEnabled())  // a disabled queue returns at once: shutdown is under way
  {
    const TimerThread::Clock::time_point next = timers_->runDue();
    double wait = WAIT;
    if (next != TimerThread::Clock::time_point::max())
    {
      wait = std::clamp(std::chrono::duration<double>(next - TimerThread::Clock::now()).count(), 0.0, WAIT);
    }
    queue_->callAvailable(ros::WallDuration(wait));
  }
}

}  // namespace ptz_action_server
