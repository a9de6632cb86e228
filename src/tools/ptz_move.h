/**
 * \file
 * \brief What ptz_move's files share: its options, the Ctrl-C flag, its errors, the keyboard teleop
 * (ptz_move_teleop.cpp), the pixel command (ptz_move_pixel.cpp) and the track-detections command
 * (ptz_move_track.cpp).
 */
#pragma once

#include <csignal>
#include <string>
#include <vector>

namespace ptz_action_server::ptz_move
{
/// The command line: its options, then the command and its arguments (words).
struct Options
{
  std::string ns = "/ptz";
  bool degrees = false;
  std::string camera_info;  ///< --camera-info; "": ns + "/camera_info"
  double cancel_after = 0.0;
  double wait = 5.0;
  double speed = 0.5;
  double zoom_speed = 2.0;
  double key_timeout = 0.7;
  std::vector<std::string> words;
};

/// Set on Ctrl-C (SIGINT): a goal is cancelled, teleop stops and quits.
extern volatile std::sig_atomic_t interrupted;

/// Keyboard teleop until q, Ctrl-C or the node goes; returns the exit code.
int teleop(const Options& options);

/// `pixel U V [W H]`: centres a pixel (and zooms to a box) of the latest image of --camera-info; the exit code.
int pixel(const Options& options);

/// `track-detections TOPIC [--id ID] [--zoom-fraction F] ...`: keeps a detector's target in view; the exit code.
int trackDetections(const Options& options);

/// True if all of \p text is a number, then in \p value.
bool parseNumber(const std::string& text, double& value);

/// Prints \p message and the usage, and exits with 2.
[[noreturn]] void fail(const std::string& message);
}  // namespace ptz_action_server::ptz_move
