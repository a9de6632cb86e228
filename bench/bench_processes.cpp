#include "bench_processes.h"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <ros/ros.h>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>

#include "ptz_action_server/FieldOfView.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/core/forwarding_backend.h"
#include "ptz_action_server/ros/ptz_node.h"

namespace ptz_bench
{
namespace
{
using namespace ptz_action_server;

/// Passes everything to the loaded backend and stamps each command in shared memory.
class RecordingBackend : public ForwardingBackend
{
public:
  RecordingBackend(std::shared_ptr<PtzBackend> inner, SharedCounters* counters)
    : ForwardingBackend(std::move(inner)), counters_(counters)
  {
  }
  void goTo(const AxisValues& position) override
  {
    record();
    inner().goTo(position);
  }
  void moveAtVelocity(const AxisValues& velocity) override
  {
    record();
    inner().moveAtVelocity(velocity);
  }
  void stop() override
  {
    const std::int64_t now_ns = record();
    counters_->last_stop_ns = now_ns;
    counters_->stops++;
    inner().stop();
  }
  /// Stamps each report of the backend's, so the bench can time settled -> result.
  bool setSampleListener(SampleListener listener) override
  {
    return inner().setSampleListener([this, listener = std::move(listener)] {
      counters_->last_report_ns = monotonicNanoseconds();
      listener();
    });
  }

private:
  std::int64_t record()
  {
    const std::int64_t now_ns = monotonicNanoseconds();
    counters_->last_command_ns = now_ns;
    counters_->commands++;
    return now_ns;
  }
  SharedCounters* counters_;
};

/// The node process: what the ptz_action_server executable does, with the recorder around the backend. Runs until
/// SIGINT.
int runNode(SharedCounters* counters)
{
  ros::init(ros::M_string{ { "__ns", NODE_NAMESPACE } }, NODE_NAME);
  const ros::NodeHandle node_handle;  // held: roscpp shuts down when the last node handle goes
  const ros::NodeHandle private_handle("~");
  MainSpinner spinner;  // as the ptz_action_server executable spins
  PtzNode node;
  node.setTickCosts(&counters->tick_costs);
  try
  {
    node.start(node_handle, private_handle, [counters](std::shared_ptr<PtzBackend> backend) {
      return std::make_shared<RecordingBackend>(std::move(backend), counters);
    });
  }
  catch (const std::exception& error)
  {
    ROS_FATAL("%s", error.what());
    return 1;
  }
  spinner.spinUntilShutdown();
  return 0;
}

/// The observer process: a ptz_state subscriber of its own, so the clients' load does not skew the arrivals; while
/// listen_all is set, also a subscriber of the camera's other topics, as rviz and a robot's nodes would be.
int runObserver(SharedCounters* counters)
{
  ros::init(ros::M_string(), "ptz_bench_observer", ros::init_options::AnonymousName);
  ros::NodeHandle node_handle(NODE_NAMESPACE);
  const ros::Subscriber subscriber =
      node_handle.subscribe<PtzState>("ptz_state", 100, [counters](const PtzState::ConstPtr&) {
        if (counters->record_states)
        {
          const std::uint32_t index = counters->state_count++;
          if (index < MAX_STATE_ARRIVALS)
          {
            counters->state_arrivals_ns[index] = monotonicNanoseconds();
          }
        }
      });
  ros::AsyncSpinner spinner(1);
  spinner.start();
  std::vector<ros::Subscriber> others;
  const auto count = [counters](const auto&) { ++counters->other_messages; };
  while (ros::ok())
  {
    if (counters->listen_all && others.empty())
    {
      others.push_back(node_handle.subscribe<sensor_msgs::JointState>("joint_states", 100, count));
      others.push_back(node_handle.subscribe<tf2_msgs::TFMessage>("/tf", 100, count));
      others.push_back(node_handle.subscribe<FieldOfView>("field_of_view", 100, count));
      others.push_back(node_handle.subscribe<diagnostic_msgs::DiagnosticArray>("/diagnostics", 100, count));
    }
    else if (!counters->listen_all && !others.empty())
    {
      others.clear();
    }
    counters->listening_all =
        !others.empty() && std::all_of(others.begin(), others.end(),
                                       [](const ros::Subscriber& other) { return other.getNumPublishers() > 0; });
    ros::WallDuration(0.05).sleep();
  }
  return 0;
}

/// The children a fatal signal to the parent takes down with it. Written before the handler is installed and
/// cleared before a child is reaped, so the handler never signals a reused pid.
volatile pid_t g_children[2] = { -1, -1 };

/// A file the parent removes when a fatal signal ends it (the emulator's link), "" for none.
char g_remove_on_signal[256] = "";

void forgetChild(pid_t child)
{
  for (volatile pid_t& entry : g_children)
  {
    if (entry == child)
    {
      entry = -1;
    }
  }
}

/// SIGINT, SIGTERM, SIGHUP to the parent: interrupt the children and wait for them, then die of the signal.
/// Async-signal-safe calls only.
void onFatalSignal(int signal_number)
{
  ::alarm(10);  // a child that does not end: SIGALRM ends the parent, and PR_SET_PDEATHSIG the child
  for (const volatile pid_t& child : g_children)
  {
    if (child > 0)
    {
      ::kill(child, SIGINT);
    }
  }
  for (const volatile pid_t& child : g_children)
  {
    if (child > 0)
    {
      ::waitpid(child, nullptr, 0);
    }
  }
  if (g_remove_on_signal[0] != '\0')
  {
    ::unlink(g_remove_on_signal);
  }
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

constexpr int FATAL_SIGNALS[] = { SIGINT, SIGTERM, SIGHUP };
}  // namespace

BenchProcesses::BenchProcesses(SharedCounters* counters, bool with_observer)
{
  int gate[2];
  if (::pipe(gate) != 0)
  {
    throw std::runtime_error("pipe failed");
  }
  gate_ = gate[1];
  const int gate_read = gate[0];
  node_ = spawn([counters] { return runNode(counters); }, gate_read);
  if (with_observer)
  {
    spawn([counters] { return runObserver(counters); }, gate_read);
  }
  ::close(gate_read);
  for (std::size_t index = 0; index < children_.size(); ++index)
  {
    g_children[index] = children_[index];
  }
  for (int signal_number : FATAL_SIGNALS)
  {
    ::signal(signal_number, onFatalSignal);
  }
}

BenchProcesses::~BenchProcesses()
{
  stop();
  for (int signal_number : FATAL_SIGNALS)
  {
    ::signal(signal_number, SIG_DFL);
  }
}

pid_t BenchProcesses::spawn(const std::function<int()>& body, int gate_read)
{
  const pid_t parent = ::getpid();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0)
  {
    throw std::runtime_error("fork failed");
  }
  if (pid > 0)
  {
    children_.push_back(pid);
    return pid;
  }
  // The child: dies with the parent, leaves stdout to the parent's figures, waits at the gate (whose entry it must
  // not hold open) and runs \p body only if released.
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() != parent)
  {
    std::_Exit(1);
  }
  ::dup2(STDERR_FILENO, STDOUT_FILENO);
  ::close(gate_);
  char go = 0;
  const bool released = ::read(gate_read, &go, 1) == 1;
  ::close(gate_read);
  std::exit(released ? body() : 0);
}

void BenchProcesses::release()
{
  if (gate_ >= 0)
  {
    const std::string go(children_.size(), 'g');  // one byte each
    if (::write(gate_, go.data(), go.size()) != static_cast<ssize_t>(go.size()))
    {
      std::perror("ptz_bench: releasing the children");
    }
    ::close(gate_);
    gate_ = -1;
  }
}

bool BenchProcesses::nodeRunning()
{
  int status = 0;
  if (node_ < 0 || ::waitpid(node_, &status, WNOHANG) == 0)
  {
    return node_ >= 0;
  }
  forgetChild(node_);
  children_.erase(std::remove(children_.begin(), children_.end(), node_), children_.end());
  if (WIFEXITED(status))
  {
    std::fprintf(stderr, "ptz_bench: the node exited with status %d (its log is above)\n", WEXITSTATUS(status));
  }
  else
  {
    std::fprintf(stderr, "ptz_bench: the node died of signal %d\n", WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  }
  node_ = -1;
  return false;
}

void BenchProcesses::stop()
{
  if (gate_ >= 0)
  {
    ::close(gate_);  // unreleased children go home
    gate_ = -1;
  }
  for (pid_t child : children_)
  {
    ::kill(child, SIGINT);
  }
  for (pid_t child : children_)
  {
    forgetChild(child);
    int status = 0;
    bool ended = false;
    for (int wait = 0; wait < 1000 && !ended; ++wait)
    {
      ended = ::waitpid(child, &status, WNOHANG) == child;
      if (!ended)
      {
        ::usleep(10000);
      }
    }
    if (!ended)
    {
      std::fprintf(stderr, "ptz_bench: child %d ignored SIGINT for 10 s; killing it\n", static_cast<int>(child));
      ::kill(child, SIGKILL);
      ::waitpid(child, &status, 0);
    }
  }
  children_.clear();
  node_ = -1;
}

void setNodeParameters(const DeviceRow& row, const DeviceHarness* device, const std::string& urdf)
{
  ros::param::del(NODE_NAMESPACE);  // nothing left from the previous row
  ros::param::set(std::string(NODE_NAMESPACE) + "/robot_description", urdf);
  const std::string private_namespace = std::string(NODE_NAMESPACE) + "/" + NODE_NAME + "/";
  ros::param::set(private_namespace + "backend", row.plugin);
  for (const HarnessParam& param : row.params)
  {
    std::visit([&](const auto& value) { ros::param::set(private_namespace + param.name, value); },
               device != nullptr ? param.valueFor(*device) : param.value);
  }
}

void removeOnFatalSignal(const std::string& path)
{
  if (path.size() < sizeof(g_remove_on_signal))
  {
    std::copy(path.begin(), path.end(), g_remove_on_signal);
    g_remove_on_signal[path.size()] = '\0';
  }
}

bool waitForNode(BenchProcesses& processes, const std::function<bool()>& server_up)
{
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
  while (ros::WallTime::now() < deadline)
  {
    if (server_up())
    {
      return true;
    }
    if (!processes.nodeRunning())
    {
      return false;
    }
  }
  std::fprintf(stderr, "ptz_bench: the node's action server did not come up within 30 s\n");
  return false;
}

}  // namespace ptz_bench
