/**
 * \file
 * \brief What the tests and the benchmarks ask of a running ROS node from outside: its process id, and waiting on a
 * condition in wall time.
 */
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include <ros/master.h>
#include <ros/network.h>
#include <ros/this_node.h>
#include <ros/wall_timer.h>
#include <xmlrpcpp/XmlRpcClient.h>

namespace ptz_action_server
{
/// The pid of the node \p name (a nodelet manager, a node), asked of the node itself through its XML-RPC API
/// (getPid); 0 if the master does not know it or it does not answer.
inline int pidOfNode(const std::string& name)
{
  XmlRpc::XmlRpcValue request;
  request[0] = ros::this_node::getName();
  request[1] = name;
  XmlRpc::XmlRpcValue response;
  XmlRpc::XmlRpcValue payload;
  if (!ros::master::execute("lookupNode", request, response, payload, false))
  {
    return 0;
  }
  std::string host;
  std::uint32_t port = 0;
  if (!ros::network::splitURI(static_cast<std::string>(payload), host, port))
  {
    return 0;
  }
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue pid_request(ros::this_node::getName());
  XmlRpc::XmlRpcValue pid_response;
  if (!client.execute("getPid", pid_request, pid_response) || pid_response.size() < 3)
  {
    return 0;
  }
  return static_cast<int>(pid_response[2]);
}

/// Waits until \p condition holds or \p timeout s of wall time pass, checking every 20 ms; its last value.
inline bool waitUntilWall(const std::function<bool()>& condition, double timeout)
{
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  while (!condition())
  {
    if (ros::WallTime::now() > deadline)
    {
      return false;
    }
    ros::WallDuration(0.02).sleep();
  }
  return true;
}

}  // namespace ptz_action_server
