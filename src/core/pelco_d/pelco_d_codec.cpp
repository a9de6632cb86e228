#include "ptz_action_server/core/pelco_d/pelco_d_codec.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace ptz_action_server
{
namespace pelco
{
namespace
{
int wrap(long hundredths)
{
  const long wrapped = hundredths % FULL_TURN;
  return static_cast<int>(wrapped < 0 ? wrapped + FULL_TURN : wrapped);
}

/// Signed hundredths within (-18000, 18000] from 0..35999.
double signedDegrees(std::uint16_t value)
{
  const int hundredths = value % FULL_TURN;
  return (hundredths > FULL_TURN / 2 ? hundredths - FULL_TURN : hundredths) / 100.0;
}
}  // namespace

bool Frame::operator==(const Frame& other) const
{
  return address == other.address && command1 == other.command1 && command2 == other.command2 && data1 == other.data1 &&
         data2 == other.data2;
}

std::uint8_t checksum(const Frame& frame)
{
  return static_cast<std::uint8_t>(frame.address + frame.command1 + frame.command2 + frame.data1 + frame.data2);
}

Bytes encode(const Frame& frame)
{
  return Bytes{ SYNC, frame.address, frame.command1, frame.command2, frame.data1, frame.data2, checksum(frame) };
}

Frame withValue(std::uint8_t address, std::uint8_t command2, std::uint16_t value)
{
  Frame frame;
  frame.address = address;
  frame.command2 = command2;
  frame.data1 = static_cast<std::uint8_t>(value >> 8);
  frame.data2 = static_cast<std::uint8_t>(value & 0xFF);
  return frame;
}

Frame stop(std::uint8_t address)
{
  Frame frame;
  frame.address = address;
  return frame;
}

Frame move(std::uint8_t address, int pan_speed, int tilt_speed, int zoom_direction, std::uint8_t pan_turbo)
{
  Frame frame;
  frame.address = address;
  frame.command2 = static_cast<std::uint8_t>(
      (pan_speed > 0 ? RIGHT : 0) | (pan_speed < 0 ? LEFT : 0) | (tilt_speed > 0 ? UP : 0) |
      (tilt_speed < 0 ? DOWN : 0) | (zoom_direction > 0 ? ZOOM_TELE : 0) | (zoom_direction < 0 ? ZOOM_WIDE : 0));
  const bool turbo = pan_turbo != 0 && std::abs(pan_speed) > MAX_SPEED;
  frame.data1 =
      turbo ? pan_turbo : static_cast<std::uint8_t>(std::min(std::abs(pan_speed), static_cast<int>(MAX_SPEED)));
  frame.data2 = static_cast<std::uint8_t>(std::min(std::abs(tilt_speed), static_cast<int>(MAX_SPEED)));
  return frame;
}

Frame withLens(Frame frame, int focus, int iris)
{
  frame.command1 = static_cast<std::uint8_t>((frame.command1 & ~(FOCUS_NEAR | IRIS_OPEN | IRIS_CLOSE)) |
                                             (focus < 0 ? FOCUS_NEAR : 0) | (iris > 0 ? IRIS_OPEN : 0) |
                                             (iris < 0 ? IRIS_CLOSE : 0));
  frame.command2 = static_cast<std::uint8_t>((frame.command2 & ~FOCUS_FAR) | (focus > 0 ? FOCUS_FAR : 0));
  return frame;
}

std::uint16_t encodePan(double degrees)
{
  return static_cast<std::uint16_t>(wrap(std::lround(degrees * 100.0)));
}

double decodePan(std::uint16_t value)
{
  return signedDegrees(value);
}

std::uint16_t encodeTilt(double degrees, TiltEncoding encoding)
{
  const double counted = encoding == TiltEncoding::UP_POSITIVE ? degrees : -degrees;
  return static_cast<std::uint16_t>(wrap(std::lround(counted * 100.0)));
}

double decodeTilt(std::uint16_t value, TiltEncoding encoding)
{
  const double degrees = signedDegrees(value);
  return encoding == TiltEncoding::UP_POSITIVE ? degrees : -degrees;
}

bool parseTiltEncoding(const std::string& text, TiltEncoding& encoding)
{
  if (text == "down_positive" || text == "up_positive")
  {
    encoding = text == "down_positive" ? TiltEncoding::DOWN_POSITIVE : TiltEncoding::UP_POSITIVE;
    return true;
  }
  return false;
}

const char* toString(TiltEncoding encoding)
{
  return encoding == TiltEncoding::DOWN_POSITIVE ? "down_positive" : "up_positive";
}

FrameParser::FrameParser(std::uint8_t address, bool general_replies)
  : address_(address), general_replies_(general_replies)
{
}

void FrameParser::reset()
{
  buffer_.clear();
}

void FrameParser::feed(const std::uint8_t* data, std::size_t size, std::vector<Event>& events)
{
  buffer_.insert(buffer_.end(), data, data + size);
  while (!buffer_.empty())
  {
    if (buffer_.front() != SYNC)
    {
      buffer_.pop_front();
      ++counters_.skipped_bytes;
      continue;
    }
    // A 4-byte general reply is told from a frame by its own 4 bytes, so that how the stream was split never
    // changes what is read: a reply checks (sum = addr + alarm), and its last byte is no query reply code.
    const bool reply_checks = general_replies_ && buffer_.size() >= GENERAL_REPLY_SIZE &&
                              static_cast<std::uint8_t>(buffer_[1] + buffer_[2]) == buffer_[3];
    const bool reply_code =
        reply_checks && (buffer_[3] == PAN_REPLY || buffer_[3] == TILT_REPLY || buffer_[3] == ZOOM_REPLY);
    if (reply_checks && !reply_code)
    {
      takeGeneralReply(events);
      continue;
    }
    if (buffer_.size() < FRAME_SIZE)
    {
      return;  // wait for the rest of the frame
    }
    Frame frame;
    frame.address = buffer_[1];
    frame.command1 = buffer_[2];
    frame.command2 = buffer_[3];
    frame.data1 = buffer_[4];
    frame.data2 = buffer_[5];
    if (checksum(frame) == buffer_[6])
    {
      buffer_.erase(buffer_.begin(), buffer_.begin() + FRAME_SIZE);
      if (address_ != 0 && frame.address != address_)
      {
        ++counters_.wrong_address;
        continue;
      }
      ++counters_.frames;
      Event event;
      event.frame = frame;
      events.push_back(event);
      continue;
    }
    if (reply_checks)
    {
      takeGeneralReply(events);
      continue;
    }
    // A 0xFF that starts nothing valid: drop it and look for the next one.
    buffer_.pop_front();
    ++counters_.bad_checksum;
  }
}

void FrameParser::takeGeneralReply(std::vector<Event>& events)
{
  Event event;
  event.general_reply = true;
  event.frame.address = buffer_[1];
  event.alarm = buffer_[2];
  buffer_.erase(buffer_.begin(), buffer_.begin() + GENERAL_REPLY_SIZE);
  ++counters_.general_replies;
  events.push_back(event);
}

}  // namespace pelco
}  // namespace ptz_action_server
