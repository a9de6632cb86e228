/**
 * \file
 * \brief OnvifProtocol's focus and iris through the ONVIF Imaging service: what the bring-up asks of it, the lens
 * commands and the readings of the lens' settings and status.
 */
#include <cmath>
#include <limits>
#include <string>

#include "ptz_action_server/core/onvif/onvif_protocol.h"

namespace ptz_action_server
{
namespace
{
/// Polls between two readings of the lens (0.5 s at the default poll period): the lens is read on a poll of its own
/// requests, so less often than the pan-tilt; a command makes the next poll read it.
constexpr int LENS_POLL_EVERY = 5;

void report(LensReport& lens, const LensCapabilities& capabilities, const onvif::ImagingOptions& options,
            const onvif::ImagingReading& reading)
{
  if (capabilities.focus.present && reading.focus_mode != LensMode::UNKNOWN)
  {
    lens.setMode(LensFunction::FOCUS, reading.focus_mode);
  }
  if (capabilities.iris.present && reading.exposure_mode != LensMode::UNKNOWN)
  {
    lens.setMode(LensFunction::IRIS, reading.exposure_mode);
  }
  if (capabilities.focus.feedback && reading.has_focus)
  {
    lens.setPosition(LensFunction::FOCUS, onvif::focusShare(options.focus_position, reading.focus));
  }
  if (capabilities.iris.feedback && reading.has_iris)
  {
    lens.setPosition(LensFunction::IRIS, onvif::irisShare(options.iris, reading.iris));
  }
}
}  // namespace

bool OnvifProtocol::bringUpLens(std::string& problem)
{
  using namespace onvif;
  lens_ = LensCapabilities();
  imaging_options_ = ImagingOptions();
  std::string lacks;
  ImagingReading reading;
  if (paths_.imaging.empty())
  {
    lacks = "this ONVIF camera lists no Imaging service (GetCapabilities has no Imaging XAddr)";
  }
  else if (profile_.video_source.empty())
  {
    lacks = "profile '" + profile_.token +
            "' has no VideoSourceConfiguration (the Imaging service's requests name its "
            "video source)";
  }
  else if (!call(paths_.imaging, getImagingOptions(profile_.video_source), true, problem))
  {
    if (problem.empty())
    {
      return false;  // the link went
    }
    lacks = problem;  // "the ONVIF camera refused GetOptions: ..."
  }
  else
  {
    const std::string unread = readImagingOptions(message_.content, imaging_options_);
    lacks = unread.empty() ? "" : "the ONVIF camera's Imaging GetOptions answered " + unread;
  }
  // What the lens moves and where it is: a refusal of one of them only means that it lacks it.
  bool link = true;
  const auto ask = [&](const std::string& body) {
    link = link && (call(paths_.imaging, body, true, problem) || !problem.empty());
    return link && problem.empty();
  };
  if (lacks.empty() && ask(getMoveOptions(profile_.video_source)))
  {
    readMoveOptions(message_.content, imaging_options_);
  }
  if (lacks.empty() && ask(getImagingSettings(profile_.video_source)))
  {
    readImagingSettings(message_.content, reading);
  }
  if (lacks.empty() && ask(getImagingStatus(profile_.video_source)))
  {
    readImagingStatus(message_.content, reading);
  }
  if (!link)
  {
    return false;
  }
  problem.clear();
  if (!lacks.empty())
  {
    lens_.focus.limitation = lacks;
    lens_.iris.limitation = lacks;
    return true;
  }
  lens_ = imagingLens(imaging_options_, reading);
  report(session_.lens(), lens_, imaging_options_, reading);
  lens_polls_ = LENS_POLL_EVERY;
  lens_status_next_ = false;
  return true;
}

void OnvifProtocol::pollLens()
{
  if (!lens_.focus.present && !lens_.iris.present)
  {
    return;
  }
  // One lens request in a poll at most (a slow camera's poll round stays short): the settings, and at the next poll
  // the focus' status.
  onvif::ImagingReading reading;
  std::string problem;
  if (lens_status_next_)
  {
    lens_status_next_ = false;
    if (call(paths_.imaging, onvif::getImagingStatus(profile_.video_source), true, problem))
    {
      onvif::readImagingStatus(message_.content, reading);
    }
  }
  else if (--lens_polls_ <= 0)
  {
    lens_polls_ = LENS_POLL_EVERY;
    lens_status_next_ = lens_.focus.feedback;
    if (call(paths_.imaging, onvif::getImagingSettings(profile_.video_source), true, problem))
    {
      onvif::readImagingSettings(message_.content, reading);
    }
  }
  else
  {
    return;
  }
  if (problem.empty())
  {
    session_.reportAlive();  // an answer keeps the link alive, as the status does
  }
  report(session_.lens(), lens_, imaging_options_, reading);  // what was not answered is left as it was
}

bool OnvifProtocol::lensCall(const std::string& body)
{
  std::string problem;
  lens_polls_ = 1;  // read back at the next poll
  const bool done = call(paths_.imaging, body, true, problem);
  if (done || !problem.empty())
  {
    session_.reportAlive();  // answered: the link is alive, even if the camera refused it
  }
  if (!done)
  {
    session_.lens().fault(problem.empty() ? "not sent: the link to the ONVIF camera was lost" : problem);
  }
  return done;
}

void OnvifProtocol::lens(const LensCommand& command)
{
  using Kind = LensCommand::Kind;
  const std::string& source = profile_.video_source;
  const bool focus = command.function == LensFunction::FOCUS;
  LensReport& lens = session_.lens();
  if (command.kind == Kind::MODE)
  {
    const bool automatic = command.automatic();
    if (lensCall(focus ? onvif::setFocusMode(source, automatic) :
                         onvif::setExposure(source, automatic, std::numeric_limits<double>::quiet_NaN())))
    {
      lens.setMode(command.function, automatic ? LensMode::AUTO : LensMode::MANUAL);
    }
    return;
  }
  if (focus && (command.kind == Kind::VELOCITY || command.kind == Kind::POSITION))
  {
    // A focus Move is taken in MANUAL only by some cameras: the focus goes manual first, as the node's words promise.
    if (lens_.focus.auto_mode && lens.state().modeOf(LensFunction::FOCUS) != LensMode::MANUAL)
    {
      if (!lensCall(onvif::setFocusMode(source, false)))
      {
        return;
      }
      lens.setMode(LensFunction::FOCUS, LensMode::MANUAL);
    }
    const onvif::FloatRange& speeds = imaging_options_.focus_speed;
    const double speed = command.value * (command.value < 0.0 && speeds.min < 0.0 ? -speeds.min : speeds.max);
    lensCall(command.kind == Kind::POSITION ?
                 onvif::moveFocusAbsolute(source, onvif::focusValue(imaging_options_.focus_position, command.value)) :
             command.value == 0.0 ? onvif::stopFocus(source) :
                                    onvif::moveFocusContinuous(source, speed));
    return;
  }
  if (!focus && command.kind == Kind::POSITION)
  {
    if (lensCall(onvif::setExposure(source, false, onvif::irisValue(imaging_options_.iris, command.value))))
    {
      lens.setMode(LensFunction::IRIS, LensMode::MANUAL);
    }
    return;
  }
  lens.fault("the ONVIF Imaging service has no words for " + describe(command));  // the node checked: not reached
}

}  // namespace ptz_action_server
