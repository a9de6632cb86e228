#include <algorithm>
#include <mutex>

#include "ptz_action_server/emulators/visca_emulator.h"

namespace ptz_action_server
{
SimLensConfig ViscaEmulator::lensModelConfig(const ViscaEmulatorConfig& config)
{
  SimLensConfig lens = config.lens_model;
  lens.focus.present = config.lens.focus;
  lens.iris.present = config.lens.iris;
  return lens;
}

bool ViscaEmulator::isLensPacket(const visca::Packet& packet)
{
  if (packet.size() < 5 || packet[1] != 0x01 || packet[2] != 0x04)
  {
    return false;
  }
  const std::uint8_t command = packet[3];
  return command == 0x08 || command == 0x48 || command == 0x38 || command == 0x18 || command == 0x39 || command == 0x4B;
}

std::uint8_t ViscaEmulator::runLens(const visca::Packet& packet, TimePoint at)
{
  const visca::ViscaLens& lens = config_.lens;
  const std::size_t size = packet.size();
  const std::uint8_t command = packet[3];
  const std::uint8_t value = packet[4];
  const bool focus_command = command == 0x08 || command == 0x48 || command == 0x38 || command == 0x18;
  if (!(focus_command ? lens.focus : lens.iris))
  {
    return visca::SYNTAX;  // a camera without it does not know the command
  }
  const bool focus_auto = lens_model_.isAuto(LensFunction::FOCUS);
  if (command == 0x38 && size == 6 && (value == 0x02 || value == 0x03 || value == 0x10))
  {
    lens_model_.setAuto(LensFunction::FOCUS, value == 0x10 ? !focus_auto : value == 0x02, at);
    return 0;
  }
  if (command == 0x39 && size == 6 &&
      (value == 0x00 || value == 0x03 || value == 0x0A || value == 0x0B || value == 0x0D))
  {
    // Full auto and shutter priority set the iris by themselves; manual, iris priority and bright take it as set.
    lens_model_.setAuto(LensFunction::IRIS, value == 0x00 || value == 0x0A, at);
    return 0;
  }
  const bool manual_focus = command == 0x08 || command == 0x48 || command == 0x18;
  if (manual_focus && focus_auto)
  {
    return visca::NOT_EXECUTABLE;
  }
  if (command == 0x18 && size == 6 && value == 0x01)
  {
    lens_model_.onePush(at);
    return 0;
  }
  if (command == 0x08 && size == 6)
  {
    const std::uint8_t form = value & 0xF0;
    const double share = value == 0x00 ? 0.0 :
                         value == 0x02 ? 0.5 :
                         value == 0x03 ? -0.5 :
                         form == 0x20  ? ((value & 0x0F) + 1) / 8.0 :
                         form == 0x30  ? -((value & 0x0F) + 1) / 8.0 :
                                         2.0;
    if (share > 1.0 || share < -1.0)
    {
      return visca::SYNTAX;
    }
    lens_model_.drive(LensFunction::FOCUS, share, at);
    return 0;
  }
  if (command == 0x48 && size == 9)
  {
    const auto position = static_cast<std::uint16_t>(visca::getNibbles(packet.data() + 4, 4));
    if (position < std::min(lens.focus_near, lens.focus_far) || position > std::max(lens.focus_near, lens.focus_far))
    {
      return visca::SYNTAX;
    }
    lens_model_.goTo(LensFunction::FOCUS, lens.focusShare(position), at);
    return 0;
  }
  if (command == 0x4B && size == 9 && packet[4] == 0x00 && packet[5] == 0x00)
  {
    if (lens_model_.isAuto(LensFunction::IRIS))
    {
      return visca::NOT_EXECUTABLE;
    }
    const auto position = static_cast<std::uint8_t>(visca::getNibbles(packet.data() + 6, 2));
    if (position < std::min(lens.iris_closed, lens.iris_open) || position > std::max(lens.iris_closed, lens.iris_open))
    {
      return visca::SYNTAX;
    }
    lens_model_.goTo(LensFunction::IRIS, lens.irisShare(position), at);
    return 0;
  }
  return visca::SYNTAX;
}

bool ViscaEmulator::answerLensInquiry(const visca::Packet& packet, TimePoint at, visca::Packet& answer) const
{
  const visca::ViscaLens& lens = config_.lens;
  const std::uint8_t address = config_.address;
  const LensState state = lensStateOf(lens_model_, at);
  if (lens.focus && packet == visca::focusModeInquiry(address))
  {
    answer.push_back(state.modeOf(LensFunction::FOCUS) == LensMode::AUTO ? 0x02 : 0x03);
  }
  else if (lens.focus && packet == visca::focusPositionInquiry(address))
  {
    visca::putNibbles(answer, lens.focusPosition(state.positionOf(LensFunction::FOCUS)), 4);
  }
  else if (lens.iris && packet == visca::irisPositionInquiry(address))
  {
    answer.insert(answer.end(), { 0x00, 0x00 });
    visca::putNibbles(answer, lens.irisPosition(state.positionOf(LensFunction::IRIS)), 2);
  }
  else
  {
    return false;
  }
  return true;
}

LensState ViscaEmulator::lensState() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return lensStateOf(lens_model_, SteadyClock::now());
}

}  // namespace ptz_action_server
