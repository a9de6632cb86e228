#include "ptz_action_server/core/visca/visca_protocol.h"

#include <iterator>
#include <string>

#include "visca_protocol_internal.h"

namespace ptz_action_server
{
void ViscaProtocol::lens(const LensCommand& command)
{
  if (!session_.connected() || !set_up_)
  {
    session_.lens().fault("the VISCA camera is not connected: " + describe(command) + " not sent");
    return;
  }
  const std::vector<visca::Packet> packets =
      visca::lensPackets(settings_.address, settings_.lens, command, session_.lens().state());
  for (const visca::Packet& packet : packets)
  {
    // Not tagged with the current command: a refused focus command is no fault of the goal running.
    channel_.queue(TransactionChannel::Request{ bytesOf(packet), LENS, true, 0, false });
  }
  // What the camera will be in; the next lens inquiries say what it is.
  if (command.kind == LensCommand::Kind::MODE)
  {
    session_.lens().setMode(command.function, command.automatic() ? LensMode::AUTO : LensMode::MANUAL);
  }
  else
  {
    session_.lens().setMode(command.function, LensMode::MANUAL);  // lensPackets() switched it to manual first
  }
}

void ViscaProtocol::pollLens()
{
  // One lens inquiry a round at most, so that a round on a 9600 baud line grows by one exchange, never three.
  const double period = settings_.lens.poll_period;
  const TimePoint now = session_.now();
  // Only once the camera answered the pose: a camera that answers no inquiry is learnt from those alone.
  if (period <= 0.0 || inquiry_answers_ == 0 ||
      (lens_polled_at_ != TimePoint{} && secondsBetween(lens_polled_at_, now) < period))
  {
    return;
  }
  static constexpr Tag LENS_INQUIRIES[] = { FOCUS_MODE_INQUIRY, FOCUS_INQUIRY, IRIS_INQUIRY };
  for (std::size_t tried = 0; tried < std::size(LENS_INQUIRIES); ++tried)
  {
    const Tag tag = LENS_INQUIRIES[lens_turn_++ % std::size(LENS_INQUIRIES)];
    if (!(tag == IRIS_INQUIRY ? iris_polled_ : focus_polled_))
    {
      continue;
    }
    const std::uint8_t address = settings_.address;
    queuePacket(tag == FOCUS_MODE_INQUIRY ? visca::focusModeInquiry(address) :
                tag == FOCUS_INQUIRY      ? visca::focusPositionInquiry(address) :
                                            visca::irisPositionInquiry(address),
                tag, true);
    lens_polled_at_ = now;
    return;
  }
}

bool ViscaProtocol::answersLensInquiry(const visca::Reply& reply, int tag) const
{
  LensMode mode = LensMode::UNKNOWN;
  std::uint16_t focus = 0;
  std::uint8_t iris = 0;
  return tag == FOCUS_MODE_INQUIRY ? visca::decodeFocusModeAnswer(reply, mode) :
         tag == FOCUS_INQUIRY      ? visca::decodeFocusPositionAnswer(reply, focus) :
                                     visca::decodeIrisPositionAnswer(reply, iris);
}

void ViscaProtocol::handleLensAnswer(const visca::Reply& reply, Tag tag)
{
  // The answer of the lens inquiry on the wire, which can_answer decoded once already.
  lens_timeouts_ = 0;
  session_.reportAlive();
  LensMode mode = LensMode::UNKNOWN;
  std::uint16_t focus = 0;
  std::uint8_t iris = 0;
  if (tag == FOCUS_MODE_INQUIRY && visca::decodeFocusModeAnswer(reply, mode))
  {
    session_.lens().setMode(LensFunction::FOCUS, mode);
  }
  else if (tag == FOCUS_INQUIRY && visca::decodeFocusPositionAnswer(reply, focus))
  {
    session_.lens().setPosition(LensFunction::FOCUS, settings_.lens.focusShare(focus));
  }
  else if (tag == IRIS_INQUIRY && visca::decodeIrisPositionAnswer(reply, iris))
  {
    session_.lens().setPosition(LensFunction::IRIS, settings_.lens.irisShare(iris));
  }
}

void ViscaProtocol::stopLensPolling(Tag tag, std::uint8_t error)
{
  const bool silence = error == 0;
  const bool focus = silence || tag != IRIS_INQUIRY;
  const bool iris = silence || tag == IRIS_INQUIRY;
  const bool was_polled = (focus && focus_polled_.exchange(false)) | (iris && iris_polled_.exchange(false));
  lens_timeouts_ = 0;
  if (!was_polled)
  {
    return;
  }
  const std::string what = silence ? "the lens inquiries" :
                           focus   ? "the focus inquiries (CAM_FocusModeInq, CAM_FocusPosInq)" :
                                     "the iris inquiry (CAM_IrisPosInq)";
  session_.warn(deviceName() + (silence ? " answers none of " : " refuses ") + what +
                (silence ? "" : std::string(" (") + visca::errorName(error) + ")") +
                ": lens_state shows the modes the node sent and no position (set visca/lens/poll_period: 0 to skip "
                "them)");
  session_.setCapabilities(capabilities());
}

}  // namespace ptz_action_server
