/**
 * \file
 * \brief What ptz_move's files share: its options, the Ctrl-C flag, and the keyboard teleop (ptz_move_teleop.cpp).
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
}  // namespace ptz_action_server::ptz_move
