/**
 * \file
 * \brief Command-line client: sends one goal of any PTZ action, shows progress from feedback, prints the result; or
 * drives the camera from the keyboard (teleop).
 */
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzCapabilities.h"
#include "ptz_action_server/PtzFrameAction.h"
#include "ptz_action_server/PtzRelToAction.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/ros/ptz_goal.h"
#include "ptz_move.h"
#include "ptz_move_run.h"

namespace ptz_action_server::ptz_move
{
volatile std::sig_atomic_t interrupted = 0;

namespace
{
const char* USAGE = R"(usage: ptz_move [options] COMMAND ARGS...

Commands (angles in rad, or degrees with --degrees; zoom as X-factor):
  abs    PAN TILT [ZOOM]           go to an absolute position (ZOOM defaults to the current zoom)
  rel    PAN TILT [ZOOM]           move by an offset from the current position
  vel    PAN TILT [ZOOM]           move at a velocity (per s) until Ctrl-C, --for, or a limit
  abs_tf FRAME PAN TILT [ZOOM]     go to a pan and tilt expressed in the axes of a tf frame
  frame  FRAME [ZOOM]              point the camera at the origin of a tf frame
  pixel  U V [W H]                 centre pixel (U, V) of the camera's latest image (camera_info's pixels: (0, 0)
                                   is the centre of the top-left pixel); with a W x H box around it, also zoom
                                   until the box fills the view. The image's stamp and size come from --camera-info
  track-detections TOPIC [OPTIONS] keep the target a detector finds (ptz_action_server/Detections on TOPIC; a
                                   relative name is in the node's namespace) near the image centre until Ctrl-C,
                                   --for, or it is lost; OPTIONS: --id ID (only detections of ID), --zoom-fraction F
                                   (zoom so the box spans F of the view), --dead-zone F (of the half image),
                                   --max-speed S (rad/s, deg/s with --degrees), --lost-timeout S, --lost-preset NAME
                                   (go there when lost); exits 0 when cancelled or lost
  state                            print the current PtzState once
  capabilities                     print what the device can do (the node's latched capabilities)
  teleop                           drive the camera from the keyboard: hold an arrow to pan and tilt, + or - to
                                   zoom; 1-9 go to the saved presets, h home, space stops, q (or Ctrl-C) quits

Options:
  --ns NAMESPACE   namespace of the node (default: /ptz)
  --degrees        angles (and angular speeds) in degrees
  --camera-info T  pixel: the camera_info topic of the image clicked on (default: the node's NAMESPACE/camera_info)
  --for SECONDS    cancel the goal after SECONDS (useful with vel)
  --wait SECONDS   how long to wait for the server (default 5)
  --speed SPEED    teleop: pan and tilt speed while an arrow is held (default 0.5 rad/s; deg/s with --degrees)
  --zoom-speed X   teleop: zoom speed while + or - is held (default 2 X/s)
  --key-timeout S  teleop: a key counts as held until S seconds after the terminal last repeated it (default 0.7)

Ctrl-C cancels the goal: the device decelerates to rest and the goal ends PREEMPTED.
)";

void onSigint(int)
{
  interrupted = 1;
}
}  // namespace

bool parseNumber(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0';
}

[[noreturn]] void fail(const std::string& message)
{
  std::fprintf(stderr, "ptz_move: %s\n\n%s", message.c_str(), USAGE);
  std::exit(2);
}

namespace
{
Options parseOptions(const std::vector<std::string>& args)
{
  Options options;
  for (std::size_t index = 0; index < args.size(); ++index)
  {
    const std::string& arg = args[index];
    auto value = [&]() {
      if (index + 1 >= args.size())
      {
        fail("option " + arg + " needs a value");
      }
      return args[++index];
    };
    if (arg == "--ns")
    {
      options.ns = value();
    }
    else if (arg == "--degrees")
    {
      options.degrees = true;
    }
    else if (arg == "--camera-info")
    {
      options.camera_info = value();
    }
    else if (arg == "--for" || arg == "--wait")
    {
      double seconds = 0.0;
      if (!parseNumber(value(), seconds) || seconds < 0.0)
      {
        fail(arg + " needs a number of seconds");
      }
      (arg == "--for" ? options.cancel_after : options.wait) = seconds;
    }
    else if (arg == "--key-timeout")
    {
      if (!parseNumber(value(), options.key_timeout) || !(options.key_timeout > 0.0))
      {
        fail(arg + " needs a number of seconds > 0");
      }
    }
    else if (arg == "--speed" || arg == "--zoom-speed")
    {
      double speed = 0.0;
      if (!parseNumber(value(), speed) || !(speed > 0.0))
      {
        fail(arg + " needs a speed > 0");
      }
      (arg == "--speed" ? options.speed : options.zoom_speed) = speed;
    }
    else if (arg == "-h" || arg == "--help")
    {
      std::printf("%s", USAGE);
      std::exit(0);
    }
    else
    {
      options.words.push_back(arg);
    }
  }
  return options;
}

/// Parses words[first..] as numbers; angles (the first \p angles of them) convert from degrees if asked.
std::vector<double> numbers(const Options& options, std::size_t first, std::size_t min_count, std::size_t max_count)
{
  const std::size_t count = options.words.size() - first;
  if (count < min_count || count > max_count)
  {
    fail("'" + options.words[0] + "' takes " + std::to_string(min_count) + " to " + std::to_string(max_count) +
         " numbers");
  }
  std::vector<double> values;
  for (std::size_t index = first; index < options.words.size(); ++index)
  {
    double value = 0.0;
    if (!parseNumber(options.words[index], value))
    {
      fail("'" + options.words[index] + "' is not a number");
    }
    const bool angle = values.size() < 2;
    values.push_back(options.degrees && angle ? value * M_PI / 180.0 : value);
  }
  return values;
}

/// Waits for the latest PtzState (for the default zoom and the "state" command).
bool currentState(const std::string& ns, ptz_action_server::PtzState& state, double wait)
{
  const auto message = ros::topic::waitForMessage<ptz_action_server::PtzState>(ns + "/ptz_state", ros::Duration(wait));
  if (!message)
  {
    return false;
  }
  state = *message;
  return true;
}

/// The zoom of a goal that gives none: the current zoom, or 0 ("leave it alone") when the device does not report it.
double currentZoom(const Options& options)
{
  ptz_action_server::PtzState state;
  if (!currentState(options.ns, state, options.wait))
  {
    return 1.0;
  }
  return std::isfinite(state.zoom) ? state.zoom : 0.0;
}

void printAxis(const char* name, const ptz_action_server::PtzAxisCapability& axis, const char* unit)
{
  if (!axis.present)
  {
    std::printf("  %-5s none%s%s\n", name, axis.limitation.empty() ? "" : ": ", axis.limitation.c_str());
    return;
  }
  std::printf("  %-5s position %-3s velocity %-3s feedback %-3s [%.4f, %.4f] %s, max speed %.4f %s/s%s%s\n", name,
              axis.absolute ? "yes" : "no", axis.velocity ? "yes" : "no", axis.feedback ? "yes" : "no", axis.min,
              axis.max, unit, axis.max_speed, unit, axis.limitation.empty() ? "" : "\n        ",
              axis.limitation.c_str());
}

/// Prints the node's latched capabilities; returns the exit code.
int printCapabilities(const Options& options)
{
  const auto message = ros::topic::waitForMessage<ptz_action_server::PtzCapabilities>(options.ns + "/capabilities",
                                                                                      ros::Duration(options.wait));
  if (!message)
  {
    std::fprintf(stderr, "ptz_move: no PtzCapabilities on %s/capabilities\n", options.ns.c_str());
    return 1;
  }
  std::printf("backend %s\n", message->backend.c_str());
  printAxis("pan", message->pan, "rad");
  printAxis("tilt", message->tilt, "rad");
  printAxis("zoom", message->zoom, "X");
  std::printf("  device: relative moves %s, presets %s, home %s\n", message->relative_moves ? "yes" : "no",
              message->device_presets ? "yes" : "no", message->device_home ? "yes" : "no");
  std::printf("  pixel goals: %s\n", message->pixel_aim.c_str());
  return 0;
}

}  // namespace
}  // namespace ptz_action_server::ptz_move

int main(int argc, char** argv)
{
  using namespace ptz_action_server;
  using namespace ptz_action_server::ptz_move;
  ros::init(argc, argv, "ptz_move", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  const Options options = parseOptions(std::vector<std::string>(argv + 1, argv + argc));
  if (options.words.empty())
  {
    fail("no command given");
  }
  std::signal(SIGINT, onSigint);
  ros::AsyncSpinner spinner(1);
  spinner.start();

  const std::string& command = options.words[0];
  if (command == "state")
  {
    PtzState state;
    if (!currentState(options.ns, state, options.wait))
    {
      std::fprintf(stderr, "ptz_move: no PtzState on %s/ptz_state\n", options.ns.c_str());
      return 1;
    }
    std::printf("mode %d  pan %.4f rad  tilt %.4f rad  zoom %.2f X\n", state.mode, state.pan, state.tilt, state.zoom);
    return 0;
  }
  if (command == "capabilities")
  {
    return printCapabilities(options);
  }
  if (command == "teleop")
  {
    return teleop(options);
  }
  if (command == "abs" || command == "rel" || command == "vel")
  {
    const std::vector<double> values = numbers(options, 1, 2, 3);
    PtzGoal goal = makePtzGoal(values[0], values[1], values.size() > 2 ? values[2] : 0.0);
    if (command == "abs" && values.size() == 2)
    {
      goal.zoom = currentZoom(options);
    }
    const std::string action = command == "abs" ? "position_abs" : (command == "rel" ? "position_rel" : "velocity");
    return run<PtzAction>(options, action, goal);
  }
  if (command == "abs_tf")
  {
    if (options.words.size() < 2)
    {
      fail("abs_tf needs a frame");
    }
    Options numeric = options;
    numeric.words.erase(numeric.words.begin() + 1);
    const std::vector<double> values = numbers(numeric, 1, 2, 3);
    PtzRelToGoal goal;
    goal.frame_id = options.words[1];
    goal.pan = values[0];
    goal.tilt = values[1];
    goal.zoom = values.size() > 2 ? values[2] : currentZoom(options);
    return run<PtzRelToAction>(options, "position_abs_tf", goal);
  }
  if (command == "frame")
  {
    if (options.words.size() < 2 || options.words.size() > 3)
    {
      fail("frame takes a frame and an optional zoom");
    }
    PtzFrameGoal goal;
    goal.frame_id = options.words[1];
    double zoom = 0.0;
    if (options.words.size() == 3 && !parseNumber(options.words[2], zoom))
    {
      fail("'" + options.words[2] + "' is not a number");
    }
    goal.zoom = options.words.size() == 3 ? zoom : currentZoom(options);
    return run<PtzFrameAction>(options, "frame", goal);
  }
  if (command == "pixel")
  {
    return pixel(options);
  }
  if (command == "track-detections")
  {
    return trackDetections(options);
  }
  fail("unknown command '" + command + "'");
}
