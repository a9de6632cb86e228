/**
 * \file
 * \brief ptz_move teleop: drives the camera from the keyboard, the terminal in raw mode.
 */
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>

#include <sys/select.h>
#include <termios.h>
#include <unistd.h>

#include <ros/ros.h>

#include "ptz_action_server/PtzCapabilities.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/core/teleop/keyboard_teleop.h"
#include "ptz_action_server/ros/ptz_teleop.h"
#include "ptz_move.h"

namespace ptz_action_server::ptz_move
{
namespace
{
// --- teleop: the terminal in raw mode, restored whatever way the program ends.
termios saved_terminal;
volatile std::sig_atomic_t terminal_raw = 0;

void restoreTerminal()
{
  if (terminal_raw)
  {
    tcsetattr(STDIN_FILENO, TCSANOW, &saved_terminal);  // async-signal-safe
    terminal_raw = 0;
  }
}

void onFatalSignal(int signal)
{
  restoreTerminal();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

/// Keys without Enter and without echo while it lives; the terminal comes back on return, exit() and the signals that
/// end the program (SIGTERM, SIGHUP, SIGQUIT; Ctrl-C quits through the main loop).
class RawTerminal
{
public:
  RawTerminal()
  {
    if (tcgetattr(STDIN_FILENO, &saved_terminal) != 0)
    {
      return;
    }
    termios raw = saved_terminal;
    raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO);
    raw.c_cc[VMIN] = 0;
    raw.c_cc[VTIME] = 0;
    std::atexit(restoreTerminal);
    for (int signal : { SIGTERM, SIGHUP, SIGQUIT })
    {
      std::signal(signal, onFatalSignal);
    }
    terminal_raw = 1;
    tcsetattr(STDIN_FILENO, TCSANOW, &raw);
  }
  ~RawTerminal()
  {
    restoreTerminal();
  }
  RawTerminal(const RawTerminal&) = delete;
  RawTerminal& operator=(const RawTerminal&) = delete;
};

const char* modeName(int mode)
{
  switch (mode)
  {
    case ptz_action_server::PtzState::MODE_IDLE:
      return "idle";
    case ptz_action_server::PtzState::MODE_POSITION:
      return "position";
    case ptz_action_server::PtzState::MODE_VELOCITY:
      return "velocity";
  }
  return "?";
}
}  // namespace

int teleop(const Options& options)
{
  if (!isatty(STDIN_FILENO))
  {
    std::fprintf(stderr, "ptz_move: teleop reads keys from a terminal: stdin is not one\n");
    return 1;
  }
  const auto capabilities =
      ros::topic::waitForMessage<PtzCapabilities>(options.ns + "/capabilities", ros::Duration(options.wait));
  ros::NodeHandle node_handle(options.ns);
  TeleopGoals goals(node_handle);
  if (!capabilities || !goals.waitForServers(options.wait))
  {
    std::fprintf(stderr, "ptz_move: no node at %s (is it running?)\n", options.ns.c_str());
    return 1;
  }
  const double scale = options.degrees ? 180.0 / M_PI : 1.0;
  const char* unit = options.degrees ? "deg" : "rad";
  KeyboardTeleopConfig keys;
  keys.pan_speed = keys.tilt_speed = options.speed / scale;
  keys.zoom_speed = options.zoom_speed;
  keys.key_timeout = options.key_timeout;
  KeyboardTeleop keyboard(keys);
  TeleopController controller(keyboard.teleopConfig());
  controller.setSpeedLimits(teleopSpeedLimits(*capabilities));

  std::mutex state_mutex;
  PtzState state;
  bool new_state = false;
  const ros::Subscriber state_subscriber =
      node_handle.subscribe<PtzState>("ptz_state", 1, [&](const PtzState::ConstPtr& message) {
        std::lock_guard<std::mutex> lock(state_mutex);
        state = *message;
        new_state = true;
      });

  std::printf("ptz_move teleop on %s: hold an arrow to pan/tilt, + or - to zoom; 1-9 presets, h home, space stop, "
              "q quit\n",
              options.ns.c_str());
  std::fflush(stdout);
  RawTerminal raw_terminal;
  KeyDecoder decoder;
  SystemClock clock;
  std::string shown_command;
  bool quit = false;
  while (ros::ok() && !interrupted && !quit)
  {
    fd_set readable;
    FD_ZERO(&readable);
    FD_SET(STDIN_FILENO, &readable);
    timeval timeout{ 0, 50000 };  // 20 frames a second, as a joystick with autorepeat
    if (select(STDIN_FILENO + 1, &readable, nullptr, nullptr, &timeout) > 0)
    {
      char bytes[64];
      const ssize_t count = read(STDIN_FILENO, bytes, sizeof(bytes));
      if (count == 0)
      {
        quit = true;  // the terminal is gone
      }
      for (const KeyPress& press : decoder.feed(std::string(bytes, count > 0 ? count : 0)))
      {
        quit = quit || press.key == TeleopKey::QUIT;
        keyboard.press(press, clock.now());
      }
    }
    goals.execute(controller.onJoy(keyboard.input(clock.now()), clock.now()));
    std::lock_guard<std::mutex> lock(state_mutex);
    if (new_state || shown_command != goals.lastCommand())
    {
      new_state = false;
      shown_command = goals.lastCommand();
      // One line, rewritten in place.
      std::printf("\r  mode %-8s pan %+9.4f %s  tilt %+9.4f %s  zoom %6.2f X   %s\x1b[K", modeName(state.mode),
                  state.pan * scale, unit, state.tilt * scale, unit, state.zoom, shown_command.c_str());
      std::fflush(stdout);
    }
  }
  goals.execute({ TeleopCommand() });  // a stop: cancels what is moving
  const bool stopped = goals.waitUntilDone(options.wait);
  std::printf("\n%s\n", stopped ? "stopped" : "the node did not confirm the stop");
  return stopped ? 0 : 1;
}
}  // namespace ptz_action_server::ptz_move
