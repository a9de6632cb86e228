#include "ptz_action_server/ros/action_servers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace ptz_action_server
{
namespace action_servers
{
/// True if row i of NODE_ACTIONS is the action of kind i: the servers are indexed by kind.
constexpr bool rowsInKindOrder()
{
  std::size_t index = 0;
  bool in_order = true;
  std::apply([&](const auto&... row) { ((in_order = in_order && static_cast<std::size_t>(row.kind) == index++), ...); },
             NODE_ACTIONS);
  return in_order;
}
static_assert(rowsInKindOrder(), "NODE_ACTIONS lists the actions in the order of ActionKind");
// Every kind but the clicked point is an action with its row.
static_assert(static_cast<std::size_t>(ActionKind::CLICKED_POINT) == NODE_ACTION_COUNT, "a row per action");
}  // namespace action_servers

const char* actionName(ActionKind kind)
{
  static constexpr std::array<const char*, NODE_ACTION_COUNT> NAMES = std::apply(
      [](const auto&... row) { return std::array<const char*, NODE_ACTION_COUNT>{ row.name... }; }, NODE_ACTIONS);
  const auto index = static_cast<std::size_t>(kind);
  return index < NAMES.size() ? NAMES[index] : kind == ActionKind::CLICKED_POINT ? "look_at_clicked_point" : "?";
}

ActionServers::ActionServers(const ros::NodeHandle& node_handle, int queue_size, double status_list_timeout)
  : node_handle_(node_handle), queue_size_(queue_size), status_list_timeout_(status_list_timeout)
{
}

std::string ActionServers::actionNamespace(const char* name) const
{
  const std::string action_namespace = std::string("move_ptz/") + name;
  // A storm of goals from several clients must lose none: large actionlib queues, and finished goals leave the
  // status list after status_list_timeout, since actionlib republishes the whole list on every goal transition.
  // Parameters already set under the action's namespace win.
  ros::NodeHandle action_handle(node_handle_, action_namespace);
  for (const char* parameter : { "actionlib_server_sub_queue_size", "actionlib_server_pub_queue_size" })
  {
    if (!action_handle.hasParam(parameter))
    {
      action_handle.setParam(parameter, queue_size_);
    }
  }
  if (!action_handle.hasParam("status_list_timeout"))
  {
    action_handle.setParam("status_list_timeout", status_list_timeout_);
  }
  return action_namespace;
}

void ActionServers::startWithoutStatusTimers()
{
  // The rate actionlib would have used: the first action's status_frequency, else actionlib_status_frequency.
  double frequency = 5.0;
  const ros::NodeHandle first(node_handle_, std::string("move_ptz/") + std::get<0>(NODE_ACTIONS).name);
  std::string key;
  if (!first.getParam("status_frequency", frequency) && first.searchParam("actionlib_status_frequency", key))
  {
    first.getParam(key, frequency);
  }
  constexpr double STATE_TICK_RATE = 10.0;  // Hz, StatePublisher's
  status_period_ticks_ =
      frequency > 0.0 ? std::max(1, static_cast<int>(std::lround(STATE_TICK_RATE / std::min(frequency, 10.0)))) : 0;
  struct Restore
  {
    ros::NodeHandle handle;
    bool had = false;
    double value = 0.0;
  };
  std::vector<Restore> restores;
  std::apply(
      [&](const auto&... row) {
        (restores.push_back({ ros::NodeHandle(node_handle_, std::string("move_ptz/") + row.name) }), ...);
      },
      NODE_ACTIONS);
  for (Restore& restore : restores)
  {
    restore.had = restore.handle.getParam("actionlib_status_frequency", restore.value);
    restore.handle.setParam("actionlib_status_frequency", 0.0);
  }
  for (const std::unique_ptr<NodeActionServerBase>& server : servers_)
  {
    server->startServer();
  }
  for (Restore& restore : restores)
  {
    if (restore.had)
    {
      restore.handle.setParam("actionlib_status_frequency", restore.value);
    }
    else
    {
      restore.handle.deleteParam("actionlib_status_frequency");
    }
  }
  started_ = true;
}

int ActionServers::publishStatuses()
{
  if (!started_ || status_period_ticks_ == 0 || ++status_ticks_ % status_period_ticks_ != 0)
  {
    return 0;
  }
  int published = 0;
  for (const std::unique_ptr<NodeActionServerBase>& server : servers_)
  {
    published += server->publishStatusIfListened();
  }
  return published;
}

void ActionServers::batch(const std::function<void()>& changes)
{
  for (const std::unique_ptr<NodeActionServerBase>& server : servers_)
  {
    if (server)  // start() builds them one by one
    {
      server->holdStatus();
    }
  }
  struct Release
  {
    ActionServers& servers;
    ~Release()
    {
      for (const std::unique_ptr<NodeActionServerBase>& server : servers.servers_)
      {
        if (server)
        {
          server->releaseStatus();
        }
      }
    }
  } release{ *this };
  changes();
}

}  // namespace ptz_action_server
