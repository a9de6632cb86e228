/**
 * \file
 * \brief PanTilt: a standard interface for pan-tilt devices with a binary command protocol (ConstantRobotics'
 * PanTilt library, as its v1.0.0 documentation specifies it), in each of the three wire formats its published code
 * has spoken.
 *
 * Wire formats (all multi-byte fields little-endian):
 * - SET_PARAM, 11 bytes: `01 MAJOR MINOR id:int32 value:float32` (every format; the ids differ, see wireId).
 * - COMMAND: seed 7 bytes `00 1 0 id:int32`; v1.0 and v1.1 15 bytes `00 1 MINOR id:int32 arg1:float32 arg2:float32`.
 * - Params frame: `02 MAJOR MINOR mask0 mask1` then each field whose mask bit is set, 4 bytes each (1 byte for the
 *   v1.x flags). mask0 bit 7 is the format's first field, bit 0 its eighth; mask1 bit 7 the ninth, and so on.
 *   The seed's order is the published seed-era encoder's, alphabetical: panAngle, panMotorPosition, panMotorSpeed,
 *   panTiltAngle, panTiltMotorPosition, panTiltMotorSpeed, tiltAngle, tiltMotorPosition, tiltMotorSpeed (not the
 *   class's declaration order). v1.0 and v1.1: panMotorPosition, tiltMotorPosition, panAngle, tiltAngle,
 *   panMotorSpeed, tiltMotorSpeed, isConnected, isOpen, custom1..3.
 *
 * The seed's inconsistency: it describes a one-byte mask for nine fields and a buffer of at least 48 bytes. Nine
 * fields cannot fit one byte, so this library uses two mask bytes, as the published code does; a full seed frame is
 * 5 + 9 x 4 = 41 bytes and a full v1.x frame 43, so the seed's 48-byte buffer is enough for any.
 *
 * The seed and v1.0 share the version bytes `1 0`: a receiver cannot tell them apart by the header. Decoders check the
 * exact size, the version bytes, the ids, the reserved mask bits and (params) that every field is plausible; a frame
 * that fails these in the selected format but passes them in another is reported as DecodeError::FOREIGN_FORMAT.
 * SET_PARAM ids 1..9 and some params masks mean different things in the seed and v1.0 and cannot be told apart at
 * all: the format must be configured, never guessed.
 *
 * Sign conventions: positive pan is clockwise seen from above (the v1.x formats say so of their MOVE_* speeds) and
 * positive tilt is up, the same as ptz_action_server's contract, so the backend converts degrees to radians only.
 *
 * No ROS here: this is core code.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace cr
{
namespace pantilt
{
/// Which of the published wire formats frames use.
enum class WireFormat
{
  SEED,  ///< the seed's (seed-era code): version bytes 1 0, 7-byte COMMAND without arguments, nine params fields
  V1_0,  ///< published tags 1.0.x: version bytes 1 0, 15-byte COMMAND with two float arguments, eleven fields
  V1_1,  ///< published tags 1.1.x: as V1_0 under version bytes 1 1
};

/// Every format, for loops.
constexpr WireFormat ALL_WIRE_FORMATS[] = { WireFormat::SEED, WireFormat::V1_0, WireFormat::V1_1 };

/// "seed", "v1.0" or "v1.1" -> \p format; false for anything else.
bool parseWireFormat(const std::string& text, WireFormat& format);
/// "seed", "v1.0" or "v1.1".
const char* toString(WireFormat format);
/// True where COMMAND frames carry two float arguments (v1.0, v1.1).
bool hasCommandArguments(WireFormat format);

/// Action commands. Ids 1..9 are the same in every format; MOVE_* exist only in v1.0 and v1.1.
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
  /// v1.x only: move pan at a speed (arg1, % of max speed, positive = clockwise) until stopped or at a limit.
  MOVE_PAN,
  /// v1.x only: move tilt at a speed (arg1, % of max speed, positive = up).
  MOVE_TILT,
  /// v1.x only: move pan and tilt at speeds (arg1, arg2).
  MOVE_PAN_TILT,
};

/// Parameters. Ids 1..9 are the seed's wire ids; the v1.x-only params have no seed id (their enum values are not wire
/// ids: the v1.0 and v1.1 ids come from a table, see PanTilt::wireId, and give 5..9 other meanings).
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
  /// Pan and tilt motor position for encoder (both). Range: 0 - 65535. Seed only.
  PAN_TILT_MOTOR_POSITION,
  /// Pan and tilt angle (both). Range: -180.0 - 180.0. Seed only.
  PAN_TILT_ANGLE,
  /// Pan motor speed. Range: 0.0 - 100.0 (%).
  PAN_MOTOR_SPEED,
  /// Tilt motor speed. Range: 0.0 - 100.0 (%).
  TILT_MOTOR_SPEED,
  /// Pan and tilt motor speed (both). Range: 0.0 - 100.0 (%). Seed only.
  PAN_TILT_MOTOR_SPEED,
  /// v1.x only: device connected (read only).
  IS_CONNECTED = 101,
  /// v1.x only: device open (read only; IS_INITIALIZED in v1.0).
  IS_OPEN,
  /// v1.x only: free for the implementation.
  CUSTOM_1,
  CUSTOM_2,
  CUSTOM_3,
};

/// Why a frame was refused. Every refused frame has exactly one reason.
enum class DecodeError
{
  NONE = 0,
  BAD_SIZE,        ///< too short for a header, or not the exact size its type (and mask) requires
  BAD_HEADER,      ///< first byte is not a known frame type for this decoder
  BAD_VERSION,     ///< version bytes do not match the selected wire format
  BAD_ID,          ///< command or param id outside the selected format's tables
  BAD_MASK,        ///< params mask has bits set for fields the format does not have
  BAD_VALUE,       ///< a params field outside what its kind can hold (see PanTiltParams::decode)
  FOREIGN_FORMAT,  ///< not a frame of the selected format, but a valid frame of another PanTilt format
};
/// How many DecodeError values there are (for counters indexed by them).
constexpr std::size_t DECODE_ERROR_COUNT = static_cast<std::size_t>(DecodeError::FOREIGN_FORMAT) + 1;

const char* toString(DecodeError error);

/// Frame types (first byte).
constexpr std::uint8_t COMMAND_HEADER = 0x00;
constexpr std::uint8_t SET_PARAM_HEADER = 0x01;
constexpr std::uint8_t PARAMS_HEADER = 0x02;

constexpr int SET_PARAM_SIZE = 11;
constexpr int COMMAND_SIZE_SEED = 7;             ///< a seed COMMAND: no arguments
constexpr int COMMAND_SIZE_WITH_ARGUMENTS = 15;  ///< a v1.0 or v1.1 COMMAND
constexpr int MAX_COMMAND_SIZE = COMMAND_SIZE_WITH_ARGUMENTS;
constexpr int PARAMS_HEADER_SIZE = 5;
/// Largest params frame of any format: the seed's buffer size.
constexpr int MAX_PARAMS_FRAME_SIZE = 48;

/// The size of a COMMAND frame in \p format.
int commandSize(WireFormat format);

/// Which fields PanTiltParams::encode writes (all by default).
struct PanTiltParamsMask
{
  bool panMotorPosition{ true };
  bool tiltMotorPosition{ true };
  bool panAngle{ true };
  bool tiltAngle{ true };
  bool panTiltMotorPosition{ true };  ///< seed only
  bool panTiltAngle{ true };          ///< seed only
  bool panMotorSpeed{ true };
  bool tiltMotorSpeed{ true };
  bool panTiltMotorSpeed{ true };  ///< seed only
  bool isConnected{ true };        ///< v1.x only
  bool isOpen{ true };             ///< v1.x only
  bool custom1{ true };            ///< v1.x only
  bool custom2{ true };            ///< v1.x only
  bool custom3{ true };            ///< v1.x only

  /// A mask with every field excluded.
  static PanTiltParamsMask none();
};

/// The device's parameters: the seed's nine fields, plus the v1.x formats' flags and custom values.
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
  /// v1.x: device connected.
  bool isConnected{ false };
  /// v1.x: device open.
  bool isOpen{ false };
  /// v1.x: custom values.
  float custom1{ 0.0f };
  float custom2{ 0.0f };
  float custom3{ 0.0f };

  bool operator==(const PanTiltParams& other) const;
  bool operator!=(const PanTiltParams& other) const
  {
    return !(*this == other);
  }

  /**
   * \brief Encodes (serialises) the params in \p format into \p data.
   *
   * Fields the mask excludes (and fields the format does not have) are left out. Returns false, with size 0, when
   * \p bufferSize is too small for the frame.
   */
  bool encode(std::uint8_t* data, int bufferSize, int& size, const PanTiltParamsMask* mask = nullptr,
              WireFormat format = WireFormat::SEED) const;

  /**
   * \brief Decodes (deserialises) a params frame of \p format. Fields absent from the mask decode as 0.
   *
   * Checks the header, both version bytes, that no mask bit names a field the format lacks, the exact size the mask
   * asks for, and that every field is plausible: motor positions 0..65535, pan angles within +-180, tilt angles
   * within +-90, speeds within +-100, flags 0 or 1, no subnormal float (a small integer read as a float is one); the
   * custom values may hold anything. A frame that fails but passes in another format is DecodeError::FOREIGN_FORMAT.
   * Never reads outside [data, data + dataSize). On failure returns false, leaves this object unchanged and, when
   * \p error is given, says why.
   */
  bool decode(const std::uint8_t* data, int dataSize, WireFormat format = WireFormat::SEED,
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
  /// Executes a command; \p arg1 and \p arg2 are the v1.x formats' arguments (0 in the seed's). True if executed.
  virtual bool executeCommand(PanTiltCommand id, float arg1 = 0.0f, float arg2 = 0.0f) = 0;
  /// Decodes a SET_PARAM or COMMAND frame and executes it. True if decoded and executed.
  virtual bool decodeAndExecuteCommand(const std::uint8_t* data, int size) = 0;

  /// Encodes SET_PARAM (11 bytes; \p data must hold them). False, with size 0, if \p id has no id in \p format.
  static bool encodeSetParamCommand(std::uint8_t* data, int& size, PanTiltParam id, float value,
                                    WireFormat format = WireFormat::SEED);

  /// Encodes COMMAND (7 bytes in the seed's format, 15 with the arguments in v1.x; MAX_COMMAND_SIZE holds either).
  /// False, with size 0, if \p id does not exist in \p format.
  static bool encodeCommand(std::uint8_t* data, int& size, PanTiltCommand id, WireFormat format = WireFormat::SEED,
                            float arg1 = 0.0f, float arg2 = 0.0f);

  /**
   * \brief Decodes a SET_PARAM or COMMAND frame on the device controller side.
   *
   * Returns 0 for a COMMAND, 1 for a SET_PARAM, -1 on error. Checks the exact size, both version bytes and that the
   * id exists in \p format; a frame that fails these but passes them in another format is
   * DecodeError::FOREIGN_FORMAT. Never reads outside the frame. Every output is written on every path: on error the
   * ids are value-initialised (0, no enumerator), the values 0 and \p error (if given) says why. For a v1.x COMMAND,
   * \p value is the first argument and \p secondValue (if given) the second.
   */
  static int decodeCommand(const std::uint8_t* data, int size, PanTiltParam& paramId, PanTiltCommand& commandId,
                           float& value, WireFormat format = WireFormat::SEED, float* secondValue = nullptr,
                           DecodeError* error = nullptr);

  /// The wire id of \p param in \p format, or 0 if it has none.
  static std::int32_t wireId(PanTiltParam param, WireFormat format);
  /// The param with wire id \p id in \p format; false if none.
  static bool paramFromWireId(std::int32_t id, WireFormat format, PanTiltParam& param);
  /// True if \p command exists in \p format.
  static bool commandExists(PanTiltCommand command, WireFormat format);
};

}  // namespace pantilt
}  // namespace cr
