#include "ptz_action_server/core/visca/visca_lens.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace ptz_action_server
{
namespace visca
{
namespace
{
constexpr std::uint8_t VISCA_LENS_COMMAND = 0x01;
constexpr std::uint8_t VISCA_LENS_INQUIRY = 0x09;
constexpr std::uint8_t VISCA_LENS_CAMERA = 0x04;

std::uint8_t lensHeader(std::uint8_t address)
{
  return static_cast<std::uint8_t>(0x80 | (address & 0x07));
}

/// A share 0..1 between \p from (0) and \p to (1), either way round, rounded to the nearest number.
long lensNumber(double share, long from, long to)
{
  return std::lround(static_cast<double>(from) + std::clamp(share, 0.0, 1.0) * static_cast<double>(to - from));
}

double lensShare(long value, long from, long to)
{
  return to == from ? 0.0 : std::clamp(static_cast<double>(value - from) / static_cast<double>(to - from), 0.0, 1.0);
}
}  // namespace

std::uint16_t ViscaLens::focusPosition(double share) const
{
  return static_cast<std::uint16_t>(lensNumber(share, focus_near, focus_far));
}

double ViscaLens::focusShare(std::uint16_t position) const
{
  return lensShare(position, focus_near, focus_far);
}

std::uint8_t ViscaLens::irisPosition(double share) const
{
  return static_cast<std::uint8_t>(lensNumber(share, iris_closed, iris_open));
}

double ViscaLens::irisShare(std::uint8_t position) const
{
  return lensShare(position, iris_closed, iris_open);
}

LensCapabilities ViscaLens::capabilities(bool focus_polled, bool iris_polled) const
{
  LensCapabilities lens;
  lens.focus.present = focus;
  lens.focus.auto_mode = lens.focus.velocity = lens.focus.absolute = lens.focus.one_push = focus;
  lens.focus.feedback = focus && focus_polled;
  lens.focus.limitation = !focus        ? "the VISCA camera is set without focus" :
                          !focus_polled ? "VISCA: the focus position is not polled" :
                                          "";
  lens.iris.present = iris;
  lens.iris.auto_mode = lens.iris.absolute = iris;
  lens.iris.feedback = iris && iris_polled;
  lens.iris.limitation = !iris        ? "the VISCA camera is set without iris" :
                         !iris_polled ? "VISCA CAM_Iris up/down are single steps, not a drive; the iris position is "
                                        "not polled" :
                                        "VISCA CAM_Iris up/down are single steps, not a drive";
  return lens;
}

Packet focusMode(std::uint8_t address, bool automatic)
{
  return { lensHeader(address), VISCA_LENS_COMMAND, VISCA_LENS_CAMERA, 0x38, std::uint8_t(automatic ? 0x02 : 0x03),
           TERMINATOR };
}

Packet focusOnePush(std::uint8_t address)
{
  return { lensHeader(address), VISCA_LENS_COMMAND, VISCA_LENS_CAMERA, 0x18, 0x01, TERMINATOR };
}

Packet focusDrive(std::uint8_t address, int speed)
{
  const int step = std::clamp(std::abs(speed), 1, 8) - 1;
  const std::uint8_t drive = speed == 0 ? 0x00 : static_cast<std::uint8_t>((speed > 0 ? 0x20 : 0x30) | step);
  return { lensHeader(address), VISCA_LENS_COMMAND, VISCA_LENS_CAMERA, 0x08, drive, TERMINATOR };
}

Packet focusDirect(std::uint8_t address, std::uint16_t position)
{
  Packet packet{ lensHeader(address), VISCA_LENS_COMMAND, VISCA_LENS_CAMERA, 0x48 };
  putNibbles(packet, position, 4);
  packet.push_back(TERMINATOR);
  return packet;
}

Packet irisMode(std::uint8_t address, bool automatic)
{
  return { lensHeader(address), VISCA_LENS_COMMAND, VISCA_LENS_CAMERA, 0x39, std::uint8_t(automatic ? 0x00 : 0x0B),
           TERMINATOR };
}

Packet irisDirect(std::uint8_t address, std::uint8_t position)
{
  Packet packet{ lensHeader(address), VISCA_LENS_COMMAND, VISCA_LENS_CAMERA, 0x4B, 0x00, 0x00 };
  putNibbles(packet, position, 2);
  packet.push_back(TERMINATOR);
  return packet;
}

Packet focusModeInquiry(std::uint8_t address)
{
  return { lensHeader(address), VISCA_LENS_INQUIRY, VISCA_LENS_CAMERA, 0x38, TERMINATOR };
}

Packet focusPositionInquiry(std::uint8_t address)
{
  return { lensHeader(address), VISCA_LENS_INQUIRY, VISCA_LENS_CAMERA, 0x48, TERMINATOR };
}

Packet irisPositionInquiry(std::uint8_t address)
{
  return { lensHeader(address), VISCA_LENS_INQUIRY, VISCA_LENS_CAMERA, 0x4B, TERMINATOR };
}

bool decodeFocusModeAnswer(const Reply& reply, LensMode& mode)
{
  if (reply.kind != Reply::Kind::ANSWER || reply.data.size() != 1 || reply.data[0] < 0x02 || reply.data[0] > 0x04)
  {
    return false;
  }
  mode = reply.data[0] == 0x02 ? LensMode::AUTO : LensMode::MANUAL;
  return true;
}

bool decodeFocusPositionAnswer(const Reply& reply, std::uint16_t& position)
{
  if (reply.kind != Reply::Kind::ANSWER || reply.data.size() != 4)
  {
    return false;
  }
  position = static_cast<std::uint16_t>(getNibbles(reply.data.data(), 4));
  return true;
}

bool decodeIrisPositionAnswer(const Reply& reply, std::uint8_t& position)
{
  if (reply.kind != Reply::Kind::ANSWER || reply.data.size() != 4 || reply.data[0] != 0x00 || reply.data[1] != 0x00)
  {
    return false;
  }
  position = static_cast<std::uint8_t>(getNibbles(reply.data.data() + 2, 2));
  return true;
}

int focusSpeed(double share)
{
  if (share == 0.0 || !std::isfinite(share))
  {
    return 0;
  }
  const int speed = std::clamp(static_cast<int>(std::ceil(std::abs(share) * 8.0)), 1, 8);
  return share > 0.0 ? speed : -speed;
}

std::vector<Packet> lensPackets(std::uint8_t address, const ViscaLens& lens, const LensCommand& command,
                                const LensState& state)
{
  std::vector<Packet> packets;
  const bool focus = command.function == LensFunction::FOCUS;
  if (!(focus ? lens.focus : lens.iris))
  {
    return packets;
  }
  const bool manual_command = command.kind != LensCommand::Kind::MODE;  // one-push too: valid in manual focus only
  if (manual_command && state.modeOf(command.function) != LensMode::MANUAL)
  {
    packets.push_back(focus ? focusMode(address, false) : irisMode(address, false));
  }
  switch (command.kind)
  {
    case LensCommand::Kind::MODE:
      packets.push_back(focus ? focusMode(address, command.automatic()) : irisMode(address, command.automatic()));
      break;
    case LensCommand::Kind::ONE_PUSH:
      packets.push_back(focusOnePush(address));
      break;
    case LensCommand::Kind::VELOCITY:
      if (focus)
      {
        packets.push_back(focusDrive(address, focusSpeed(command.value)));
      }
      else
      {
        packets.clear();  // no iris drive
      }
      break;
    default:
      packets.push_back(focus ? focusDirect(address, lens.focusPosition(command.value)) :
                                irisDirect(address, lens.irisPosition(command.value)));
      break;
  }
  return packets;
}

}  // namespace visca
}  // namespace ptz_action_server
