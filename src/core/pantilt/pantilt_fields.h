/**
 * \file
 * \brief Private to the PanTilt codec: the PanTiltParams fields, one table that serves both wire formats
 * (pantilt_params.cpp) and JSON (pantilt_params_json.cpp).
 */
#pragma once

#include <array>

#include "ptz_action_server/core/pantilt/pantilt_codec.h"

namespace cr
{
namespace pantilt
{
namespace detail
{
// --- Params fields: one table serves both wire formats and JSON.

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
};

constexpr Field intField(const char* name, int PanTiltParams::*member, bool PanTiltParamsMask::*mask)
{
  return Field{ name, FieldType::INT32, member, nullptr, nullptr, mask };
}
constexpr Field floatField(const char* name, float PanTiltParams::*member, bool PanTiltParamsMask::*mask)
{
  return Field{ name, FieldType::FLOAT32, nullptr, member, nullptr, mask };
}
constexpr Field flagField(const char* name, bool PanTiltParams::*member, bool PanTiltParamsMask::*mask)
{
  return Field{ name, FieldType::FLAG, nullptr, nullptr, member, mask };
}

inline const Field PAN_MOTOR_POSITION_FIELD =
    intField("panMotorPosition", &PanTiltParams::panMotorPosition, &PanTiltParamsMask::panMotorPosition);
inline const Field TILT_MOTOR_POSITION_FIELD =
    intField("tiltMotorPosition", &PanTiltParams::tiltMotorPosition, &PanTiltParamsMask::tiltMotorPosition);
inline const Field PAN_ANGLE_FIELD = floatField("panAngle", &PanTiltParams::panAngle, &PanTiltParamsMask::panAngle);
inline const Field TILT_ANGLE_FIELD = floatField("tiltAngle", &PanTiltParams::tiltAngle, &PanTiltParamsMask::tiltAngle);
inline const Field PAN_TILT_MOTOR_POSITION_FIELD =
    intField("panTiltMotorPosition", &PanTiltParams::panTiltMotorPosition, &PanTiltParamsMask::panTiltMotorPosition);
inline const Field PAN_TILT_ANGLE_FIELD =
    floatField("panTiltAngle", &PanTiltParams::panTiltAngle, &PanTiltParamsMask::panTiltAngle);
inline const Field PAN_MOTOR_SPEED_FIELD =
    floatField("panMotorSpeed", &PanTiltParams::panMotorSpeed, &PanTiltParamsMask::panMotorSpeed);
inline const Field TILT_MOTOR_SPEED_FIELD =
    floatField("tiltMotorSpeed", &PanTiltParams::tiltMotorSpeed, &PanTiltParamsMask::tiltMotorSpeed);
inline const Field PAN_TILT_MOTOR_SPEED_FIELD =
    floatField("panTiltMotorSpeed", &PanTiltParams::panTiltMotorSpeed, &PanTiltParamsMask::panTiltMotorSpeed);
inline const Field IS_CONNECTED_FIELD =
    flagField("isConnected", &PanTiltParams::isConnected, &PanTiltParamsMask::isConnected);
inline const Field IS_OPEN_FIELD = flagField("isOpen", &PanTiltParams::isOpen, &PanTiltParamsMask::isOpen);
inline const Field CUSTOM_1_FIELD = floatField("custom1", &PanTiltParams::custom1, &PanTiltParamsMask::custom1);
inline const Field CUSTOM_2_FIELD = floatField("custom2", &PanTiltParams::custom2, &PanTiltParamsMask::custom2);
inline const Field CUSTOM_3_FIELD = floatField("custom3", &PanTiltParams::custom3, &PanTiltParamsMask::custom3);

/// 1.0 frame order: the seed's class declaration.
inline const std::array<const Field*, 9> FIELDS_V1_0 = {
  &PAN_MOTOR_POSITION_FIELD, &TILT_MOTOR_POSITION_FIELD,     &PAN_ANGLE_FIELD,
  &TILT_ANGLE_FIELD,         &PAN_TILT_MOTOR_POSITION_FIELD, &PAN_TILT_ANGLE_FIELD,
  &PAN_MOTOR_SPEED_FIELD,    &TILT_MOTOR_SPEED_FIELD,        &PAN_TILT_MOTOR_SPEED_FIELD
};
/// 1.1 frame order: the published library's.
inline const std::array<const Field*, 11> FIELDS_V1_1 = { &PAN_MOTOR_POSITION_FIELD,
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
