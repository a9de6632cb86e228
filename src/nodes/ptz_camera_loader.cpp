/**
 * \file
 * \brief ptz_camera_loader: loads many PtzNodelet cameras into one nodelet manager, and unloads them when it stops.
 *
 * `nodelet load` is one process per nodelet; for 64 cameras those 64 idle processes cost more CPU and memory than
 * the manager that runs the cameras. This one process does the same for all of them: it asks the manager to load
 * each camera (its parameters are already on the parameter server, set by the launch file), then waits for SIGINT or
 * SIGTERM and unloads them before it exits. There is no bond: if the loader dies, the cameras keep running (as with
 * `nodelet load --no-bond`).
 *
 * Parameters (private): manager (the manager's name, /cameras), names (a list of camera nodelet names), or count and
 * name_format (printf with one int, /cam_%02d/ptz_action_server) for cameras 0 .. count-1.
 */
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

#include <nodelet/NodeletLoad.h>
#include <nodelet/NodeletUnload.h>
#include <ros/ros.h>

namespace
{
std::vector<std::string> cameraNames(const ros::NodeHandle& private_handle)
{
  std::vector<std::string> names;
  if (private_handle.getParam("names", names))
  {
    return names;
  }
  int count = 0;
  std::string format = "/cam_%02d/ptz_action_server";
  private_handle.getParam("count", count);
  private_handle.getParam("name_format", format);
  for (int index = 0; index < count; ++index)
  {
    char name[256];
    std::snprintf(name, sizeof(name), format.c_str(), index);
    names.emplace_back(name);
  }
  return names;
}

}  // namespace

int main(int argc, char** argv)
{
  // SIGINT and SIGTERM wait for sigwait() below (every thread roscpp starts inherits the mask): the cameras are
  // unloaded while roscpp can still call the manager.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  ros::init(argc, argv, "ptz_camera_loader", ros::init_options::NoSigintHandler);
  ros::NodeHandle private_handle("~");
  std::string manager = "cameras";
  private_handle.getParam("manager", manager);
  const std::vector<std::string> names = cameraNames(private_handle);
  if (names.empty())
  {
    ROS_FATAL("no cameras to load: set ~names (a list) or ~count");
    return 1;
  }
  ros::NodeHandle handle;
  const std::string load_service = ros::names::resolve(manager) + "/load_nodelet";
  const std::string unload_service = ros::names::resolve(manager) + "/unload_nodelet";
  ros::AsyncSpinner spinner(1);
  spinner.start();
  if (!ros::service::waitForService(load_service, ros::Duration(60.0)))
  {
    ROS_FATAL("the nodelet manager %s did not answer within 60 s", manager.c_str());
    return 1;
  }
  ros::ServiceClient load = handle.serviceClient<nodelet::NodeletLoad>(load_service, true);
  std::vector<std::string> loaded;
  for (const std::string& name : names)
  {
    nodelet::NodeletLoad request;
    request.request.name = name;
    request.request.type = "ptz_action_server/PtzNodelet";
    if ((load.isValid() || (load = handle.serviceClient<nodelet::NodeletLoad>(load_service, true))) &&
        load.call(request) && request.response.success)
    {
      loaded.push_back(name);
    }
    else
    {
      ROS_ERROR("%s could not load %s (see the manager's log)", manager.c_str(), name.c_str());
    }
  }
  ROS_INFO("%zu of %zu cameras loaded into %s", loaded.size(), names.size(), manager.c_str());
  spinner.stop();  // nothing to spin for until the unloads (its thread would wake ten times a second meanwhile)

  int signal = 0;
  sigwait(&stop_signals, &signal);
  ros::ServiceClient unload = handle.serviceClient<nodelet::NodeletUnload>(unload_service, true);
  for (const std::string& name : loaded)
  {
    nodelet::NodeletUnload request;
    request.request.name = name;
    if (!unload.call(request))
    {
      break;  // the manager is gone already: nothing left to unload
    }
  }
  ros::shutdown();
  return 0;
}
