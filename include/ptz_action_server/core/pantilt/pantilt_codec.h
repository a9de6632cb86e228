/**
 * \file
 * \brief PanTilt: a standard interface for pan-tilt devices with a binary command protocol (ConstantRobotics'
 * PanTilt library, as its v1.0.0 documentation specifies it), plus the published 1.1 wire format as an option.
 *
 * Wire formats (all multi-byte fields little-endian):
 * - SET_PARAM, 11 bytes: `01 MAJOR MINOR id:int32 value:float32` (both versions).
 * - COMMAND, 1.0: 7 bytes `00 1 0 id:int32`; 1.1: 15 bytes `00 1 1 id:int32 arg1:float32 arg2:float32`.
 * - Params frame: `02 MAJOR MINOR mask0 mask1` then each field whose mask bit is set, 4 bytes each (1 byte for the
 *   1.1 flags). mask0 bit 7 is the first field, bit 0 the eighth; mask1 bit 7 the ninth, and so on.
 *
 * The seed's inconsistency: it describes a one-byte mask for nine fields and a buffer of at least 48 bytes. Nine
 * fields cannot fit one byte, so this library uses two mask bytes, as the published code does; a full 1.0 frame is
 * 5 + 9 x 4 = 41 bytes and a full 1.1 frame 43, so the seed's 48-byte buffer is enough for either.
 *
 * Sign conventions: positive pan is clockwise seen from above (the 1.1 format says so of its MOVE_* speeds) and
 * positive tilt is up, the same as ptz_action_server's contract, so the backend converts degrees to radians only.
 *
 * No ROS here: this is core code.
 */
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace cr
{
namespace pantilt
{
/// Which wire format frames use.
enum class WireVersion
{
  V1_0,  ///< the seed's format (default): 7-byte COMMAND without arguments
  V1_1,  ///< the published library's format: 15-byte COMMAND with two float arguments, its own param ids
};

/// "1.0" or "1.1" -> \p version; false for anything else.
bool parseWireVersion(const std::string& text, WireVersion& version);
const char* toString(WireVersion version);

/// Action commands. Ids 1..9 are the same in both formats; MOVE_* exist only in 1.1.
enum class PanTiltCommand
{
  /// Restart Pan-Tilt device.
  RESTART = 1,
  /// Stop Pan-Tilt device, block all running commands and leave the device in its current state.
  STOP,
  /// Go to given pan motor position (0..65535).
  GO_TO_PAN_POSITION,
  /// Go to given tilt motor position (0..65535).
  GO_TO_TILT_POSITION,
  /// Go to given pan and tilt motor positions.
  GO_TO_PAN_TILT_POSITION,
  /// Go to given pan angle (-180..180 deg).
  GO_TO_PAN_ANGLE,
  /// Go to given tilt angle (-90..90 deg).
  GO_TO_TILT_ANGLE,
  /// Go to given pan and tilt angles.
  GO_TO_PAN_TILT_ANGLE,
  /// Go to home position.
  GO_TO_HOME,
  /// 1.1 only: move pan at a speed (arg1, % of max speed, positive = clockwise) until stopped or at a limit.
  MOVE_PAN,
  /// 1.1 only: move tilt at a speed (arg1, % of max speed, positive = up).
  MOVE_TILT,
  /// 1.1 only: move pan and tilt at speeds (arg1, arg2).
  MOVE_PAN_TILT,
};

/// Parameters. Ids 1..9 are the seed's 1.0 wire ids; the 1.1-only params have no 1.0 id (their enum values are not
/// wire ids: the 1.1 ids come from a table, see PanTilt::wireId).
enum class PanTiltParam
{
  /// Pan motor position for encoder. Range: 0 - 65535.
  PAN_MOTOR_POSITION = 1,
  /// Tilt motor position for encoder. Range: 0 - 65535.
  TILT_MOTOR_POSITION,
  /// Pan angle. Range: -180.0 - 180.0.
  PAN_ANGLE,
  /// Tilt angle. Range: -90.0 - 90.0.
  TILT_ANGLE,
  /// Pan and tilt motor position for encoder (both). Range: 0 - 65535. 1.0 only.
  PAN_TILT_MOTOR_POSITION,
  /// Pan and tilt angle (both). Range: -180.0 - 180.0. 1.0 only.
  PAN_TILT_ANGLE,
  /// Pan motor speed. Range: 0.0 - 100.0 (%).
  PAN_MOTOR_SPEED,
  /// Tilt motor speed. Range: 0.0 - 100.0 (%).
  TILT_MOTOR_SPEED,
  /// Pan and tilt motor speed (both). Range: 0.0 - 100.0 (%). 1.0 only.
  PAN_TILT_MOTOR_SPEED,
  /// 1.1 only: device connected (read only).
  IS_CONNECTED = 101,
  /// 1.1 only: device open (read only).
  IS_OPEN,
  /// 1.1 only: free for the implementation.
  CUSTOM_1,
  CUSTOM_2,
  CUSTOM_3,
};

/// Why a frame was refused. Every refused frame has exactly one reason.
enum class DecodeError
{
  NONE = 0,
  BAD_SIZE,     ///< too short for a header, or not the exact size its type (and mask) requires
  BAD_HEADER,   ///< first byte is not a known frame type for this decoder
  BAD_VERSION,  ///< version bytes do not match the selected wire format
  BAD_ID,       ///< command or param id outside the selected format's tables
  BAD_MASK,     ///< params mask has bits set for fields the format does not have
};

const char* toString(DecodeError error);

/// Frame types (first byte).
constexpr std::uint8_t COMMAND_HEADER = 0x00;
constexpr std::uint8_t SET_PARAM_HEADER = 0x01;
constexpr std::uint8_t PARAMS_HEADER = 0x02;

constexpr int SET_PARAM_SIZE = 11;
constexpr int COMMAND_SIZE_V1_0 = 7;
constexpr int COMMAND_SIZE_V1_1 = 15;
constexpr int PARAMS_HEADER_SIZE = 5;
/// Largest params frame of either format: the seed's buffer size.
constexpr int MAX_PARAMS_FRAME_SIZE = 48;

/// Which fields PanTiltParams::encode writes (all by default).
struct PanTiltParamsMask
{
  bool panMotorPosition{ true };
  bool tiltMotorPosition{ true };
  bool panAngle{ true };
  bool tiltAngle{ true };
  bool panTiltMotorPosition{ true };  ///< 1.0 only
  bool panTiltAngle{ true };          ///< 1.0 only
  bool panMotorSpeed{ true };
  bool tiltMotorSpeed{ true };
  bool panTiltMotorSpeed{ true };  ///< 1.0 only
  bool isConnected{ true };        ///< 1.1 only
  bool isOpen{ true };             ///< 1.1 only
  bool custom1{ true };            ///< 1.1 only
  bool custom2{ true };            ///< 1.1 only
  bool custom3{ true };            ///< 1.1 only

  /// A mask with every field excluded.
  static PanTiltParamsMask none();
};

/// The device's parameters: the seed's nine fields, plus the 1.1 format's flags and custom values.
class PanTiltParams
{
public:
  /// Pan motor position for encoder. Range: 0 - 65535.
  int panMotorPosition{ 0 };
  /// Tilt motor position for encoder. Range: 0 - 65535.
  int tiltMotorPosition{ 0 };
  /// Pan angle. Range: -180.0 - 180.0.
  float panAngle{ 0.0f };
  /// Tilt angle. Range: -90.0 - 90.0.
  float tiltAngle{ 0.0f };
  /// Pan tilt motor position for encoder. Range: 0 - 65535.
  int panTiltMotorPosition{ 0 };
  /// Pan tilt angle. Range: -180.0 - 180.0.
  float panTiltAngle{ 0.0f };
  /// Pan motor speed. Range: 0.0 - 100.0.
  float panMotorSpeed{ 0.0f };
  /// Tilt motor speed. Range: 0.0 - 100.0.
  float tiltMotorSpeed{ 0.0f };
  /// Pan tilt motor speed. Range: 0.0 - 100.0.
  float panTiltMotorSpeed{ 0.0f };
  /// 1.1: device connected.
  bool isConnected{ false };
  /// 1.1: device open.
  bool isOpen{ false };
  /// 1.1: custom values.
  float custom1{ 0.0f };
  float custom2{ 0.0f };
  float custom3{ 0.0f };

  bool operator==(const PanTiltParams& other) const;
  bool operator!=(const PanTiltParams& other) const
  {
    return !(*this == other);
  }

  /**
   * \brief Encodes (serialises) the params of \p version's format into \p data.
   *
   * Fields the mask excludes (and fields the format does not have) are left out. Returns false, with size 0, when
   * \p bufferSize is too small for the frame.
   */
  bool encode(std::uint8_t* data, int bufferSize, int& size, const PanTiltParamsMask* mask = nullptr,
              WireVersion version = WireVersion::V1_0) const;

  /**
   * \brief Decodes (deserialises) a params frame. Fields absent from the mask decode as 0.
   *
   * Never reads outside [data, data + dataSize). On failure returns false, leaves this object unchanged and, when
   * \p error is given, says why.
   */
  bool decode(const std::uint8_t* data, int dataSize, WireVersion version = WireVersion::V1_0,
              DecodeError* error = nullptr);

  /// Every field as a JSON object member of the field's name.
  nlohmann::json toJson() const;
  /// Reads the fields present in \p json (others keep their value); false (and \p error) on a wrong type.
  bool fromJson(const nlohmann::json& json, std::string* error = nullptr);
  /// Writes { key: params } to \p path, as the seed's ConfigReader does.
  bool writeToFile(const std::string& path, const std::string& key = "panTiltParams") const;
  /// Reads the params under \p key from the JSON file \p path.
  bool readFromFile(const std::string& path, const std::string& key = "panTiltParams", std::string* error = nullptr);
};

/**
 * \brief Interface of a pan-tilt device controller, with the static codecs for the control side.
 *
 * Implementations must make setParam, getParam, getParams, executeCommand and decodeAndExecuteCommand safe to call
 * from any thread.
 */
class PanTilt
{
public:
  virtual ~PanTilt();

  /// Version of the library: "1.0.0".
  static std::string getVersion();

  /// Sets a parameter. Returns true if it was set.
  virtual bool setParam(PanTiltParam id, float value) = 0;
  /// The value of a parameter, or -1 if it does not exist.
  virtual float getParam(PanTiltParam id) const = 0;
  /// All parameters.
  virtual void getParams(PanTiltParams& params) const = 0;
  /// Executes a command; \p arg1 and \p arg2 are the 1.1 format's arguments (0 in 1.0). True if executed.
  virtual bool executeCommand(PanTiltCommand id, float arg1 = 0.0f, float arg2 = 0.0f) = 0;
  /// Decodes a SET_PARAM or COMMAND frame and executes it. True if decoded and executed.
  virtual bool decodeAndExecuteCommand(const std::uint8_t* data, int size) = 0;

  /// Encodes SET_PARAM (11 bytes; \p data must hold them). False, with size 0, if \p id has no id in \p version.
  static bool encodeSetParamCommand(std::uint8_t* data, int& size, PanTiltParam id, float value,
                                    WireVersion version = WireVersion::V1_0);

  /// Encodes COMMAND (7 bytes in 1.0, 15 in 1.1 with the arguments). False, with size 0, if \p id does not exist
  /// in \p version.
  static bool encodeCommand(std::uint8_t* data, int& size, PanTiltCommand id, WireVersion version = WireVersion::V1_0,
                            float arg1 = 0.0f, float arg2 = 0.0f);

  /**
   * \brief Decodes a SET_PARAM or COMMAND frame on the device controller side.
   *
   * Returns 0 for a COMMAND, 1 for a SET_PARAM, -1 on error. Checks the exact size, both version bytes and that the
   * id exists in \p version; never reads outside the frame. Every output is written on every path: on error the ids
   * are value-initialised (0, no enumerator), the values 0 and \p error (if given) says why. For a 1.1 COMMAND,
   * \p value is the first argument and \p secondValue (if given) the second.
   */
  static int decodeCommand(const std::uint8_t* data, int size, PanTiltParam& paramId, PanTiltCommand& commandId,
                           float& value, WireVersion version = WireVersion::V1_0, float* secondValue = nullptr,
                           DecodeError* error = nullptr);

  /// The wire id of \p param in \p version, or 0 if it has none.
  static std::int32_t wireId(PanTiltParam param, WireVersion version);
  /// The param with wire id \p id in \p version; false if none.
  static bool paramFromWireId(std::int32_t id, WireVersion version, PanTiltParam& param);
  /// True if \p command exists in \p version.
  static bool commandExists(PanTiltCommand command, WireVersion version);
};

}  // namespace pantilt
}  // namespace cr
