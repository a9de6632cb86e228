/**
 * \file
 * \brief The panel's image view without Qt or ROS: which image topics a camera has, where a widget position falls on
 * the letterboxed image and back, a drag's box, the camera's recent views, and where a pixel goal's aim lies in a
 * later image. ImageView only wires these to the widget; test_core tests them.
 *
 * Image pixels count as camera_info's K and PtzPixel do: (0, 0) is the centre of the top-left pixel. Widget positions
 * count as QMouseEvent::pos() does: position (x, y) is the widget pixel whose centre lies (x + 0.5, y + 0.5) from the
 * widget's top-left corner.
 */
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "ptz_action_server/panel/panel_model.h"

namespace ptz_action_server::panel
{
/// The type of the topics the image view offers, and the image it shows by default in the camera's namespace.
inline constexpr const char* IMAGE_TYPE = "sensor_msgs/Image";
inline constexpr const char* DEFAULT_IMAGE = "image_raw";

/// The topics of type sensor_msgs/Image in `ns` and below ("/ptz": /ptz/image_raw, /ptz/left/image; "/": all),
/// sorted, each once.
std::vector<std::string> imageTopics(const std::vector<TopicInfo>& topics, const std::string& ns);
/// The camera's own image, `<ns>/image_raw` (the simulated camera's; "" for no camera).
std::string defaultImageTopic(const std::string& ns);

/// A pixel of an image, in camera_info's convention.
struct Pixel
{
  double u = 0.0;  ///< px, column
  double v = 0.0;  ///< px, row
};

/// A position in the widget, as QMouseEvent::pos() counts (not rounded).
struct WidgetPoint
{
  double x = 0.0;
  double y = 0.0;
};

/// Where an image lies in the widget: scaled to fit with its aspect ratio kept, centred (letterbox or pillarbox).
struct Letterbox
{
  int image_width = 0;   ///< px
  int image_height = 0;  ///< px
  double scale = 0.0;    ///< widget px per image px; 0: nothing is drawn (an empty image or widget)
  double left = 0.0;     ///< widget px from the widget's left edge to the image's left edge
  double top = 0.0;      ///< widget px from the widget's top edge to the image's top edge
  double width() const
  {
    return image_width * scale;
  }
  double height() const
  {
    return image_height * scale;
  }
};

/// The letterbox of an `image_width` x `image_height` image in a `widget_width` x `widget_height` widget.
Letterbox letterbox(int image_width, int image_height, int widget_width, int widget_height);
/// The image pixel shown at widget position `at`; nullopt off the image (on the bars, or outside the widget).
std::optional<Pixel> pixelAt(const Letterbox& box, const WidgetPoint& at);
/// The widget position that shows image pixel `pixel` (the inverse of pixelAt; may lie off the widget).
WidgetPoint widgetPointOf(const Letterbox& box, const Pixel& pixel);

/// A box in image pixels: its centre and size, as PtzPixel's u, v, box_width, box_height.
struct PixelBox
{
  double u = 0.0;       ///< px, the centre
  double v = 0.0;       ///< px
  double width = 0.0;   ///< px
  double height = 0.0;  ///< px
};

/// Whether a press at `from` and a release at `to` make a drag: at least `threshold` widget px apart along x plus y
/// (as Qt's startDragDistance counts); else it is a click.
bool isDrag(const WidgetPoint& from, const WidgetPoint& to, double threshold);
/// The box dragged from widget position `from` to `to` (its two corners, either way round), clipped to the image;
/// nullopt when less than a pixel of it is on the image either way.
std::optional<PixelBox> draggedBox(const Letterbox& box, const WidgetPoint& from, const WidgetPoint& to);

/// Where the camera looked at one moment, and how wide: the contract's pan and tilt (rad) and its full field of view.
struct View
{
  double pan = 0.0;         ///< rad, clockwise seen from above
  double tilt = 0.0;        ///< rad, up
  double horizontal = 0.0;  ///< rad, full angle
  double vertical = 0.0;    ///< rad, full angle
};

/// The camera's views of the last TRACK_SPAN seconds, by ROS time: pan and tilt from ptz_state (stamped when it
/// arrives), the field of view from field_of_view (stamped by the node).
class ViewTrack
{
public:
  static constexpr double TRACK_SPAN = 10.0;  ///< s kept behind the newest sample
  static constexpr double MAX_AHEAD = 0.2;    ///< s past the newest sample a view is still given

  void addPose(double stamp, double pan, double tilt);
  void addFieldOfView(double stamp, double horizontal, double vertical);
  void clear();
  /// The view at `stamp`: each part interpolated between the samples around it (pan the shorter way round); past the
  /// newest pose, carried on at the speed of the two newest for up to MAX_AHEAD (the field of view held). nullopt
  /// when a part has no sample there (before the oldest, too far past the newest, a NaN axis).
  std::optional<View> at(double stamp) const;

private:
  struct Sample
  {
    double stamp;
    double a;
    double b;
  };
  static void add(std::deque<Sample>& samples, const Sample& sample);
  static std::optional<Sample> lookUp(const std::deque<Sample>& samples, double stamp, bool extrapolate, bool angles);

  std::deque<Sample> poses_;  ///< pan, tilt
  std::deque<Sample> views_;  ///< horizontal, vertical
};

/// What a pixel goal aims at: a pixel (and a box around it) of an image of the given size.
struct PixelAim
{
  PixelBox target;       ///< width and height 0: a click, no box
  int image_width = 0;   ///< px
  int image_height = 0;  ///< px
  double stamp = 0.0;    ///< s, ROS time: the image's stamp, which picks the view the pixel was seen from
  std::string goal_id;   ///< the action goal's id
  bool operator==(const PixelAim& other) const;
};

/// An aim as drawn on an image: its centre, and a box's four corners (clockwise from the top left).
struct AimInImage
{
  Pixel centre;
  bool box = false;
  std::array<Pixel, 4> corners{};
  bool tracked = false;  ///< re-projected for the image's view; false: drawn where it was clicked
};

/// Where `aim`, seen from `aim_view`, lies in an image of `width` x `height` px seen from `view`: each point
/// re-projected as a direction far away (the camera turning about its axes; its optical centre's offset from them
/// neglected) when both views are known; otherwise at the same place of the image, scaled to its size. nullopt for a
/// point behind the camera, or an empty size.
std::optional<AimInImage> aimInImage(const PixelAim& aim, const std::optional<View>& aim_view, int width, int height,
                                     const std::optional<View>& view);

/// Which pixel goal the view draws: the newest one heard on move_ptz/pixel/goal (the panel's or any client's), while
/// it is pending or active; one the status lists never name is dropped after UNLISTED_TIMEOUT.
class PixelGoalWatch
{
public:
  static constexpr double UNLISTED_TIMEOUT = 2.0;  ///< s

  /// A goal heard at `now` (s, any monotonic clock).
  void goalSent(const PixelAim& aim, double now);
  /// The action's status list: the goals it names (GoalStatusEntry::id) and their status.
  void status(const std::vector<GoalStatusEntry>& goals);
  void clear();
  /// The goal to draw at `now`, if any.
  std::optional<PixelAim> active(double now) const;

private:
  std::optional<PixelAim> aim_;
  double heard_ = 0.0;
  bool listed_ = false;   ///< a status list has named it
  bool running_ = false;  ///< pending, active, preempting or recalling in the newest list that names it
};

}  // namespace ptz_action_server::panel
