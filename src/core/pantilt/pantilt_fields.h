/**
 * \file
 * \brief Private to the PanTilt codec: the PanTiltParams fields, one table that serves every wire format
 * (pantilt_params.cpp) and JSON (pantilt_params_json.cpp).
 */
#pragma once

#include <array>
#include <limits>

#include "ptz_action_server/core/pantilt/pantilt_codec.h"

namespace cr
{
namespace pantilt
{
namespace detail
{
// --- Params fields: one table serves every wire format and JSON.

enum class FieldType
{
  INT32,
  FLOAT32,
  FLAG,  ///< one byte, 0 or 1
};

struct Field
{
  const char* name;
  FieldType type;
  int PanTiltParams::*int_member;
  float PanTiltParams::*float_member;
  bool PanTiltParams::*flag_member;
  bool PanTiltParamsMask::*mask_member;
  /// What a received value may be: int32 within [0, limit], float32 within [-limit, limit] and neither NaN nor
  /// subnormal (an infinite limit takes anything). Flags are 0 or 1 whatever the limit.
  float limit;
};

constexpr float MAX_MOTOR_POSITION = 65535.0f;
constexpr float MAX_PAN_ANGLE = 180.0f;
constexpr float MAX_TILT_ANGLE = 90.0f;
constexpr float MAX_SPEED = 100.0f;  ///< %, signed where a speed has a direction
constexpr float ANY_VALUE = std::numeric_limits<float>::infinity();

constexpr Field intField(const char* name, int PanTiltParams::*member, bool PanTiltParamsMask::*mask, float limit)
{
  return Field{ name, FieldType::INT32, member, nullptr, nullptr, mask, limit };
}
constexpr Field floatField(const char* name, float PanTiltParams::*member, bool PanTiltParamsMask::*mask, float limit)
{
  return Field{ name, FieldType::FLOAT32, nullptr, member, nullptr, mask, limit };
}
constexpr Field flagField(const char* name, bool PanTiltParams::*member, bool PanTiltParamsMask::*mask)
{
  return Field{ name, FieldType::FLAG, nullptr, nullptr, member, mask, 1.0f };
}

inline const Field PAN_MOTOR_POSITION_FIELD = intField("panMotorPosition", &PanTiltParams::panMotorPosition,
                                                       &PanTiltParamsMask::panMotorPosition, MAX_MOTOR_POSITION);
inline const Field TILT_MOTOR_POSITION_FIELD = intField("tiltMotorPosition", &PanTiltParams::tiltMotorPosition,
                                                        &PanTiltParamsMask::tiltMotorPosition, MAX_MOTOR_POSITION);
inline const Field PAN_ANGLE_FIELD =
    floatField("panAngle", &PanTiltParams::panAngle, &PanTiltParamsMask::panAngle, MAX_PAN_ANGLE);
inline const Field TILT_ANGLE_FIELD =
    floatField("tiltAngle", &PanTiltParams::tiltAngle, &PanTiltParamsMask::tiltAngle, MAX_TILT_ANGLE);
inline const Field PAN_TILT_MOTOR_POSITION_FIELD =
    intField("panTiltMotorPosition", &PanTiltParams::panTiltMotorPosition, &PanTiltParamsMask::panTiltMotorPosition,
             MAX_MOTOR_POSITION);
inline const Field PAN_TILT_ANGLE_FIELD =
    floatField("panTiltAngle", &PanTiltParams::panTiltAngle, &PanTiltParamsMask::panTiltAngle, MAX_PAN_ANGLE);
inline const Field PAN_MOTOR_SPEED_FIELD =
    floatField("panMotorSpeed", &PanTiltParams::panMotorSpeed, &PanTiltParamsMask::panMotorSpeed, MAX_SPEED);
inline const Field TILT_MOTOR_SPEED_FIELD =
    floatField("tiltMotorSpeed", &PanTiltParams::tiltMotorSpeed, &PanTiltParamsMask::tiltMotorSpeed, MAX_SPEED);
inline const Field PAN_TILT_MOTOR_SPEED_FIELD = floatField("panTiltMotorSpeed", &PanTiltParams::panTiltMotorSpeed,
                                                           &PanTiltParamsMask::panTiltMotorSpeed, MAX_SPEED);
inline const Field IS_CONNECTED_FIELD =
    flagField("isConnected", &PanTiltParams::isConnected, &PanTiltParamsMask::isConnected);
inline const Field IS_OPEN_FIELD = flagField("isOpen", &PanTiltParams::isOpen, &PanTiltParamsMask::isOpen);
// The custom values are the implementation's: nothing is implausible for them.
inline const Field CUSTOM_1_FIELD =
    floatField("custom1", &PanTiltParams::custom1, &PanTiltParamsMask::custom1, ANY_VALUE);
inline const Field CUSTOM_2_FIELD =
    floatField("custom2", &PanTiltParams::custom2, &PanTiltParamsMask::custom2, ANY_VALUE);
inline const Field CUSTOM_3_FIELD =
    floatField("custom3", &PanTiltParams::custom3, &PanTiltParamsMask::custom3, ANY_VALUE);

/// Seed frame order: the published seed-era encoder's, which is alphabetical, not the class's declaration order
/// (published-wire-facts.md 2.2).
inline const std::array<const Field*, 9> FIELDS_SEED = {
  &PAN_ANGLE_FIELD,      &PAN_MOTOR_POSITION_FIELD,      &PAN_MOTOR_SPEED_FIELD,
  &PAN_TILT_ANGLE_FIELD, &PAN_TILT_MOTOR_POSITION_FIELD, &PAN_TILT_MOTOR_SPEED_FIELD,
  &TILT_ANGLE_FIELD,     &TILT_MOTOR_POSITION_FIELD,     &TILT_MOTOR_SPEED_FIELD
};
/// v1.0 and v1.1 frame order: the published library's.
inline const std::array<const Field*, 11> FIELDS_V1 = { &PAN_MOTOR_POSITION_FIELD,
                                                        &TILT_MOTOR_POSITION_FIELD,
                                                        &PAN_ANGLE_FIELD,
                                                        &TILT_ANGLE_FIELD,
                                                        &PAN_MOTOR_SPEED_FIELD,
                                                        &TILT_MOTOR_SPEED_FIELD,
                                                        &IS_CONNECTED_FIELD,
                                                        &IS_OPEN_FIELD,
                                                        &CUSTOM_1_FIELD,
                                                        &CUSTOM_2_FIELD,
                                                        &CUSTOM_3_FIELD };
/// JSON: every field, in declaration order.
inline const std::array<const Field*, 14> ALL_FIELDS = { &PAN_MOTOR_POSITION_FIELD,
                                                         &TILT_MOTOR_POSITION_FIELD,
                                                         &PAN_ANGLE_FIELD,
                                                         &TILT_ANGLE_FIELD,
                                                         &PAN_TILT_MOTOR_POSITION_FIELD,
                                                         &PAN_TILT_ANGLE_FIELD,
                                                         &PAN_MOTOR_SPEED_FIELD,
                                                         &TILT_MOTOR_SPEED_FIELD,
                                                         &PAN_TILT_MOTOR_SPEED_FIELD,
                                                         &IS_CONNECTED_FIELD,
                                                         &IS_OPEN_FIELD,
                                                         &CUSTOM_1_FIELD,
                                                         &CUSTOM_2_FIELD,
                                                         &CUSTOM_3_FIELD };
}  // namespace detail
}  // namespace pantilt
}  // namespace cr
