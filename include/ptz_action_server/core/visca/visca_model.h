/**
 * \file
 * \brief What a VISCA camera model means by its numbers: steps a degree, ranges, how it writes positions, speed bytes,
 * the zoom position to X-factor table. Presets for the common models, from their makers' command tables
 * (doc/backends/visca.md names the source of each figure); every field is a setting.
 */
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "ptz_action_server/core/types.h"
#include "ptz_action_server/core/visca/visca_codec.h"

namespace ptz_action_server
{
namespace visca
{
/// One row of a zoom table: the camera's zoom position and the X-factor it gives.
struct ZoomPoint
{
  std::uint16_t position = 0;
  double zoom = 1.0;
};

/// One pan or tilt axis of a model.
struct ViscaAxis
{
  double steps_per_degree = 14.4;
  double min_degrees = -170.0;
  double max_degrees = 170.0;
  std::uint8_t max_speed_byte = 0x18;  ///< the fastest drive speed byte (VV or WW)
  double max_speed = 100.0;            ///< deg/s at max_speed_byte; a byte n gives n / max_speed_byte of it
  /// deg/s of the speed bytes 1, 2, ... where the maker's table gives them (its last is max_speed at max_speed_byte);
  /// empty: speeds in proportion to the byte.
  std::vector<double> speed_table;
  /// The camera counts this axis' steps the other way round (positive pan left, positive tilt down).
  bool reversed = false;
};

/**
 * \brief A camera model's units. Signs are the contract's (positive pan right, positive tilt up), as VISCA's own
 * unless the model's table says otherwise (ViscaAxis::reversed) or the image is flipped.
 */
struct ViscaModel
{
  std::string name = "ptzoptics";
  std::array<ViscaAxis, 2> axes{ { { 14.4, -170.0, 170.0, 0x18, 100.0, {}, false },
                                   { 14.4, -30.0, 90.0, 0x14, 70.0, {}, false } } };
  PositionLayout layout;  ///< nibbles of pan and tilt, one or two speed bytes
  /// Zoom position -> X, positions rising; at least two rows. Between rows the X is interpolated linearly.
  std::vector<ZoomPoint> zoom_table{ { 0x0000, 1.0 }, { 0x4000, 20.0 } };
  /// False where the X-factor of the zoom positions is not known (a camera with interchangeable lenses): zoom goals
  /// other than the widest view (zoom 1) are refused until zoom/table gives the lens's rows.
  bool zoom_table_known = true;
  double zoom_rate = 8.0;     ///< X/s at the fastest zoom drive speed (7)
  double acceleration = 3.0;  ///< rad/s^2, for goal timeouts and the emulator's motion
  bool has_zoom = true;
  std::uint16_t vendor_id = 0;  ///< what the version inquiry answers (0001: Sony), where the maker's table gives it
  std::uint16_t model_id = 0;

  /// A preset by name ("evi_d70", "brc_x1000", ...; see presetNames()) -> \p model; false for another name.
  static bool preset(const std::string& name, ViscaModel& model);
  /// The preset names, for messages and parameter checks.
  static const std::vector<std::string>& presets();
  /// The preset names in one line, for messages.
  static std::string presetNames();

  /// Radians (pan or tilt) <-> steps, rounded and clamped to what the layout's nibbles hold.
  std::int32_t toSteps(Axis axis, double radians) const;
  double fromSteps(Axis axis, std::int32_t steps) const;
  /// rad/s -> the speed byte 1..max (0 stays 0): the byte whose speed is nearest; and back.
  std::uint8_t speedByte(Axis axis, double speed) const;
  double speedOfByte(Axis axis, std::uint8_t byte) const;
  /// X/s -> zoom drive speed 1..8 (p + 1, signed; 0 stays 0), and back.
  int zoomSpeed(double rate) const;
  double rateOfZoomSpeed(int speed) const;
  /// X-factor <-> zoom position through the table (clamped to its ends).
  std::uint16_t zoomToPosition(double zoom) const;
  double positionToZoom(std::uint16_t position) const;
  /// Ranges (rad, X), top speeds and accelerations, as the node sees them.
  std::array<AxisCapability, AXIS_COUNT> capabilities() const;
  /// "" if usable; else what is wrong ("the zoom table needs ...").
  std::string check() const;
};

}  // namespace visca
}  // namespace ptz_action_server
