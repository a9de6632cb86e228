/**
 * \file
 * \brief ptz_move track-detections: keeps a detector's target near the image centre (the track_detections action)
 * until Ctrl-C, --for, or the target is lost.
 */
#include <cmath>
#include <cstdio>
#include <string>

#include <ros/ros.h>

#include "ptz_action_server/PtzTrackDetectionsAction.h"
#include "ptz_move.h"
#include "ptz_move_run.h"

namespace ptz_action_server::ptz_move
{
namespace
{
/// \p text as a number of \p option; the node checks its range (and says why it refuses one).
float numberOf(const std::string& option, const std::string& text)
{
  double value = 0.0;
  if (!parseNumber(text, value) || !std::isfinite(value) || value < 0.0)
  {
    fail(option + " takes a number >= 0, not '" + text + "'");
  }
  return static_cast<float>(value);
}
}  // namespace

int trackDetections(const Options& options)
{
  if (options.words.size() < 2 || options.words[1].rfind("--", 0) == 0)
  {
    fail("'track-detections' needs the topic of the detections (ptz_action_server/Detections)");
  }
  PtzTrackDetectionsGoal goal;
  goal.detections_topic = options.words[1];
  for (std::size_t index = 2; index < options.words.size(); index += 2)
  {
    const std::string& option = options.words[index];
    if (index + 1 >= options.words.size())
    {
      fail("'track-detections' option " + option + " needs a value");
    }
    const std::string& value = options.words[index + 1];
    if (option == "--id")
    {
      goal.target_id = value;
    }
    else if (option == "--zoom-fraction")
    {
      goal.zoom_fraction = numberOf(option, value);
    }
    else if (option == "--dead-zone")
    {
      goal.dead_zone = numberOf(option, value);
    }
    else if (option == "--max-speed")
    {
      goal.max_speed = numberOf(option, value) * (options.degrees ? M_PI / 180.0 : 1.0);
    }
    else if (option == "--lost-timeout")
    {
      goal.lost_timeout = numberOf(option, value);
    }
    else if (option == "--lost-preset")
    {
      goal.lost_preset = value;
    }
    else
    {
      fail("'track-detections' has no option " + option);
    }
  }
  std::printf("tracking the %s on %s%s%s (Ctrl-C stops)\n",
              goal.target_id.empty() ? "best detection" : ("detections of '" + goal.target_id + "'").c_str(),
              goal.detections_topic.c_str(), goal.lost_preset.empty() ? "" : "; when lost, to preset ",
              goal.lost_preset.c_str());
  bool lost = false;
  const int code =
      run<PtzTrackDetectionsAction>(options, "track_detections", goal, [&](const PtzTrackDetectionsResult& result) {
        lost = result.outcome.rfind("lost", 0) == 0;
      });
  // A lost target is how tracking ends on its own: not a failure.
  return lost ? 0 : code;
}

}  // namespace ptz_action_server::ptz_move
