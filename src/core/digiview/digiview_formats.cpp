/**
 * \file
 * \brief The DigiView format table: what differs between the published revisions of msg_defs.hpp (sizes, names,
 * type numbers, units, subscriptions, status values), and the names of the enums.
 */
#include "ptz_action_server/core/digiview/digiview_codec.h"

#include <algorithm>
#include <iterator>

namespace ptz_action_server
{
namespace digiview
{
namespace
{
/// 1.2's wire value of each ParamType, by its value here (1cbc39f: LENS 7 .. CAM_CONTROL_MODE 11 inserted, 12
/// retired, CAM_TARGETING 13 .. SINGLE_TARGET_TRACKING 18, CALIBRATION 19, NAVIGATION 20).
constexpr std::uint8_t V1_2_PARAMS[] = { 0, 1, 2, 3, 4, 5, 6, 13, 14, 15, 16, 17, 18, 19, 20, 7, 8, 9, 10, 11 };
/// The parameters before 1.2: the seed's 0..12.
constexpr std::uint8_t SEED_PARAMS = static_cast<std::uint8_t>(ParamType::SINGLE_TARGET_TRACKING) + 1;
/// 1.2's DEBUG on the wire (after UNKNOWN 8).
constexpr std::uint8_t DEBUG_WIRE = 9;
}  // namespace

const char* toString(Format format)
{
  switch (format)
  {
    case Format::V0_5:
      return "0.5";
    case Format::V1_0:
      return "1.0";
    case Format::V1_1:
      return "1.1";
    case Format::V1_2:
      return "1.2";
  }
  return "?";
}

bool parseFormat(const std::string& text, Format& format)
{
  for (Format candidate : FORMATS)
  {
    if (text == toString(candidate))
    {
      format = candidate;
      return true;
    }
  }
  return false;
}

std::string formatsOfSize(std::size_t size)
{
  std::string names;
  for (Format format : FORMATS)
  {
    if (layoutOf(format).size == size)
    {
      names += (names.empty() ? "" : " or ") + std::string(toString(format));
    }
  }
  return names;
}

Layout layoutOf(Format format)
{
  switch (format)
  {
    case Format::V0_5:
      return Layout{ 80, 11, 64, 75, 0 };
    case Format::V1_2:
      return Layout{ 96, 16, 72, 88, 12 };
    default:
      return Layout{ 88, 16, 64, 80, 12 };
  }
}

std::size_t nameSizeOf(Format format)
{
  return format == Format::V1_2 ? 16 : 8;
}

std::uint32_t minIntervalOf(Format format)
{
  return format == Format::V1_2 ? 50 : 100;
}

bool shortIntervalIsOneShot(Format format)
{
  return format == Format::V1_2;
}

const char* toString(AngleUnit unit)
{
  return unit == AngleUnit::DEGREES ? "degrees" : "radians";
}

bool parseAngleUnit(const std::string& text, AngleUnit& unit)
{
  if (text != "radians" && text != "degrees")
  {
    return false;
  }
  unit = text == "degrees" ? AngleUnit::DEGREES : AngleUnit::RADIANS;
  return true;
}

AngleUnit documentedAngleUnit(Format format)
{
  return format == Format::V0_5 || format == Format::V1_0 ? AngleUnit::RADIANS : AngleUnit::DEGREES;
}

const char* toString(ChecksumRule rule)
{
  return rule == ChecksumRule::ZERO_ACCEPTED ? "zero_accepted" : "required";
}

bool parseChecksumRule(const std::string& text, ChecksumRule& rule)
{
  if (text != "required" && text != "zero_accepted")
  {
    return false;
  }
  rule = text == "required" ? ChecksumRule::REQUIRED : ChecksumRule::ZERO_ACCEPTED;
  return true;
}

bool toWire(Format format, MessageType type, std::uint8_t& wire)
{
  const auto value = static_cast<std::uint8_t>(type);
  if (type == MessageType::DEBUG)
  {
    if (format != Format::V1_2)
    {
      return false;
    }
    wire = DEBUG_WIRE;
    return true;
  }
  if (format == Format::V0_5 || value < static_cast<std::uint8_t>(MessageType::GET_INTERVAL) ||
      type == MessageType::QUIT)
  {
    wire = value;
    return true;
  }
  if (type == MessageType::GET_INTERVAL)
  {
    return false;
  }
  wire = static_cast<std::uint8_t>(value - 1);  // 1.0 removed GET_INTERVAL: the replies moved down by one (1.1 too)
  return true;
}

bool fromWire(Format format, std::uint8_t wire, MessageType& type)
{
  const auto last = static_cast<std::uint8_t>(MessageType::UNKNOWN);
  if (wire == static_cast<std::uint8_t>(MessageType::QUIT) ||
      wire < static_cast<std::uint8_t>(MessageType::GET_INTERVAL))
  {
    type = static_cast<MessageType>(wire);
    return true;
  }
  if (format == Format::V0_5 && wire <= last)
  {
    type = static_cast<MessageType>(wire);
    return true;
  }
  if (format != Format::V0_5 && wire < last)
  {
    type = static_cast<MessageType>(wire + 1);
    return true;
  }
  if (format == Format::V1_2 && wire == DEBUG_WIRE)
  {
    type = MessageType::DEBUG;
    return true;
  }
  return false;
}

bool paramToWire(Format format, ParamType param, std::uint8_t& wire)
{
  const auto value = static_cast<std::uint8_t>(param);
  if (format != Format::V1_2)
  {
    wire = value;
    return value < SEED_PARAMS;
  }
  if (value >= std::size(V1_2_PARAMS))
  {
    return false;
  }
  wire = V1_2_PARAMS[value];
  return true;
}

bool paramFromWire(Format format, std::uint8_t wire, ParamType& param)
{
  if (format != Format::V1_2)
  {
    param = static_cast<ParamType>(wire);
    return wire < SEED_PARAMS;
  }
  const auto found = std::find(std::begin(V1_2_PARAMS), std::end(V1_2_PARAMS), wire);
  if (found == std::end(V1_2_PARAMS))
  {
    return false;
  }
  param = static_cast<ParamType>(found - std::begin(V1_2_PARAMS));
  return true;
}

bool hasAppStatus(Format format)
{
  return format == Format::V1_1 || format == Format::V1_2;
}

std::uint8_t runningStatus(Format format)
{
  return hasAppStatus(format) ? APP_STATUS_RUNNING : 1;
}

const char* describeStatus(Format format, std::uint8_t status)
{
  static const char* const SEED[] = { "idle", "running", "finished", "error" };
  static const char* const APP[] = { "STARTUP", "LOADING", "RUNNING", "ERROR", "HALT" };
  if (hasAppStatus(format))
  {
    return status < std::size(APP) ? APP[status] : "?";
  }
  return status < std::size(SEED) ? SEED[status] : "?";
}

const char* toString(MessageType type)
{
  switch (type)
  {
    case MessageType::EMPTY:
      return "EMPTY";
    case MessageType::GET_PARAMETERS:
      return "GET_PARAMETERS";
    case MessageType::SET_PARAMETERS:
      return "SET_PARAMETERS";
    case MessageType::CURRENT_PARAMETERS:
      return "CURRENT_PARAMETERS";
    case MessageType::GET_INTERVAL:
      return "GET_INTERVAL";
    case MessageType::ACKNOWLEDGEMENT:
      return "ACKNOWLEDGEMENT";
    case MessageType::CHECKSUM_ERROR:
      return "CHECKSUM_ERROR";
    case MessageType::DATA_ERROR:
      return "DATA_ERROR";
    case MessageType::FORBIDDEN:
      return "FORBIDDEN";
    case MessageType::UNKNOWN:
      return "UNKNOWN";
    case MessageType::DEBUG:
      return "DEBUG";
    case MessageType::QUIT:
      return "QUIT";
  }
  return "?";
}

const char* toString(ParamType type)
{
  static const char* const NAMES[] = { "SYSTEM_STATUS",
                                       "AI",
                                       "MODEL",
                                       "VIDEO_OUTPUT",
                                       "CAPTURE",
                                       "DETECTION",
                                       "DETECTED_ROI",
                                       "CAM_TARGETING",
                                       "CAM_OPTICS_AND_CONTROL",
                                       "CAM_OFFSET",
                                       "SENSOR",
                                       "CAM_DEPTH_ESTIMATION",
                                       "SINGLE_TARGET_TRACKING",
                                       "CALIBRATION",
                                       "NAVIGATION",
                                       "LENS",
                                       "CAM_EULER",
                                       "CAM_ZOOM",
                                       "CAM_LOCK_FLAGS",
                                       "CAM_CONTROL_MODE" };
  const auto index = static_cast<std::size_t>(type);
  return index < std::size(NAMES) ? NAMES[index] : "?";
}

const char* describeError(MessageType type)
{
  switch (type)
  {
    case MessageType::CHECKSUM_ERROR:
      return "the checksum of the message did not match";
    case MessageType::DATA_ERROR:
      return "DigiView could not interpret the data";
    case MessageType::FORBIDDEN:
      return "the sender does not have permission to perform the requested action";
    case MessageType::UNKNOWN:
      return "the parameter or message type is unknown to DigiView";
    default:
      return "not an error";
  }
}

}  // namespace digiview
}  // namespace ptz_action_server
