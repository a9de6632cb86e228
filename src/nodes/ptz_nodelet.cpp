/**
 * \file
 * \brief ptz_action_server/PtzNodelet: the node as a nodelet, many cameras in one nodelet manager.
 *
 * A thin onInit() over PtzNode, the code the executable runs: the same parameters, actions, topics, services, tf and
 * diagnostics. The camera's action callbacks run on the nodelet's single-threaded queue (getNodeHandle()), which the
 * manager's worker pool serves one callback at a time, so PtzActionServer sees what the executable's ros::spin()
 * gives it: one callback at a time, never two at once. Other cameras in the manager run in parallel with it.
 */
#include <memory>

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "ptz_action_server/ros/ptz_node.h"

namespace ptz_action_server
{
class PtzNodelet : public nodelet::Nodelet
{
public:
  PtzNodelet() = default;
  /// Stops the camera (state thread, preset thread, backend threads, timers) before the nodelet's handles go.
  ~PtzNodelet() override
  {
    node_.reset();
  }

private:
  /// Starts the camera; a configuration or backend error is logged as fatal and leaves this nodelet inert (nothing
  /// advertised, no thread), the manager and its other cameras untouched.
  void onInit() override
  {
    auto node = std::make_unique<PtzNode>();
    try
    {
      node->start(getNodeHandle(), getPrivateNodeHandle());
    }
    catch (const ConfigError& error)
    {
      NODELET_FATAL("configuration error: %s (this camera stays stopped; unload it, fix it and load it again)",
                    error.what());
      return;  // node goes here: whatever it had started stops
    }
    catch (const BackendError& error)
    {
      NODELET_FATAL("backend error: %s (this camera stays stopped; unload it and load it again)", error.what());
      return;
    }
    node_ = std::move(node);
  }

  std::unique_ptr<PtzNode> node_;
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::PtzNodelet, nodelet::Nodelet)
