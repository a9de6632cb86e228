#include "ptz_action_server/panel/image_view_model.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <Eigen/Geometry>

namespace ptz_action_server::panel
{
std::vector<std::string> imageTopics(const std::vector<TopicInfo>& topics, const std::string& ns)
{
  const std::string prefix = inNamespace(ns, "");
  std::vector<std::string> names;
  for (const TopicInfo& topic : topics)
  {
    if (topic.datatype == IMAGE_TYPE && topic.name.compare(0, prefix.size(), prefix) == 0)
    {
      names.push_back(topic.name);
    }
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

std::string defaultImageTopic(const std::string& ns)
{
  return ns.empty() ? "" : inNamespace(ns, DEFAULT_IMAGE);
}

Letterbox letterbox(int image_width, int image_height, int widget_width, int widget_height)
{
  Letterbox box;
  box.image_width = image_width;
  box.image_height = image_height;
  if (image_width <= 0 || image_height <= 0 || widget_width <= 0 || widget_height <= 0)
  {
    return box;
  }
  box.scale =
      std::min(static_cast<double>(widget_width) / image_width, static_cast<double>(widget_height) / image_height);
  box.left = 0.5 * (widget_width - box.width());
  box.top = 0.5 * (widget_height - box.height());
  return box;
}

std::optional<Pixel> pixelAt(const Letterbox& box, const WidgetPoint& at)
{
  if (!(box.scale > 0.0))
  {
    return std::nullopt;
  }
  // Both as distances from the image's top-left outer corner, in image pixels: a pixel's centre lies half a pixel in.
  const double x = (at.x + 0.5 - box.left) / box.scale;
  const double y = (at.y + 0.5 - box.top) / box.scale;
  if (!(x >= 0.0 && x <= box.image_width && y >= 0.0 && y <= box.image_height))
  {
    return std::nullopt;
  }
  return Pixel{ x - 0.5, y - 0.5 };
}

WidgetPoint widgetPointOf(const Letterbox& box, const Pixel& pixel)
{
  return { box.left + (pixel.u + 0.5) * box.scale - 0.5, box.top + (pixel.v + 0.5) * box.scale - 0.5 };
}

bool isDrag(const WidgetPoint& from, const WidgetPoint& to, double threshold)
{
  return std::abs(to.x - from.x) + std::abs(to.y - from.y) >= threshold;
}

std::optional<PixelBox> draggedBox(const Letterbox& box, const WidgetPoint& from, const WidgetPoint& to)
{
  if (!(box.scale > 0.0))
  {
    return std::nullopt;
  }
  // The corners are the pixels' centres pressed and released, as outer distances from the image's corner, clipped.
  const auto outer = [&box](double widget, double start, int size) {
    return std::clamp((widget + 0.5 - start) / box.scale, 0.0, static_cast<double>(size));
  };
  const double x0 = outer(from.x, box.left, box.image_width);
  const double x1 = outer(to.x, box.left, box.image_width);
  const double y0 = outer(from.y, box.top, box.image_height);
  const double y1 = outer(to.y, box.top, box.image_height);
  PixelBox result;
  result.width = std::abs(x1 - x0);
  result.height = std::abs(y1 - y0);
  if (result.width < 1.0 || result.height < 1.0)
  {
    return std::nullopt;
  }
  result.u = 0.5 * (x0 + x1) - 0.5;
  result.v = 0.5 * (y0 + y1) - 0.5;
  return result;
}

void ViewTrack::add(std::deque<Sample>& samples, const Sample& sample)
{
  if (!samples.empty() && sample.stamp < samples.back().stamp)
  {
    samples.clear();  // time went back (a bag played again, a simulator restarted): what came before is void
  }
  samples.push_back(sample);
  while (samples.front().stamp < sample.stamp - TRACK_SPAN)
  {
    samples.pop_front();
  }
}

void ViewTrack::addPose(double stamp, double pan, double tilt)
{
  add(poses_, { stamp, pan, tilt });
}

void ViewTrack::addFieldOfView(double stamp, double horizontal, double vertical)
{
  add(views_, { stamp, horizontal, vertical });
}

void ViewTrack::clear()
{
  poses_.clear();
  views_.clear();
}

std::optional<ViewTrack::Sample> ViewTrack::lookUp(const std::deque<Sample>& samples, double stamp, bool extrapolate,
                                                   bool angles)
{
  if (samples.empty() || stamp < samples.front().stamp || stamp > samples.back().stamp + MAX_AHEAD)
  {
    return std::nullopt;
  }
  // The shorter way round for pan; the field of view and tilt never wrap.
  const auto difference = [angles](double to, double from) {
    const double d = to - from;
    return angles ? std::remainder(d, 2.0 * M_PI) : d;
  };
  const auto blend = [&difference](const Sample& from, const Sample& to, double stamp) {
    const double span = to.stamp - from.stamp;
    const double f = span > 0.0 ? (stamp - from.stamp) / span : 0.0;
    return Sample{ stamp, from.a + f * difference(to.a, from.a), from.b + f * (to.b - from.b) };
  };
  if (stamp >= samples.back().stamp)
  {
    if (!extrapolate || samples.size() < 2)
    {
      return samples.back();
    }
    return blend(*std::prev(samples.end(), 2), samples.back(), stamp);
  }
  const auto after = std::upper_bound(samples.begin(), samples.end(), stamp,
                                      [](double t, const Sample& sample) { return t < sample.stamp; });
  return blend(*std::prev(after), *after, stamp);
}

std::optional<View> ViewTrack::at(double stamp) const
{
  const std::optional<Sample> pose = lookUp(poses_, stamp, true, true);
  const std::optional<Sample> view = lookUp(views_, stamp, false, false);
  if (!pose || !view)
  {
    return std::nullopt;
  }
  View result{ pose->a, pose->b, view->a, view->b };
  if (!std::isfinite(result.pan) || !std::isfinite(result.tilt) ||
      !(result.horizontal > 0.0 && result.horizontal < M_PI) || !(result.vertical > 0.0 && result.vertical < M_PI))
  {
    return std::nullopt;
  }
  return result;
}

bool PixelAim::operator==(const PixelAim& other) const
{
  return goal_id == other.goal_id && target.u == other.target.u && target.v == other.target.v &&
         target.width == other.target.width && target.height == other.target.height &&
         image_width == other.image_width && image_height == other.image_height && stamp == other.stamp;
}

namespace
{
/// The pinhole of a `width` x `height` image spanning `view`'s field of view, principal point at its centre (the
/// node's model of a picture without a calibrated camera_info: core/motion/pinhole_view.h's intrinsicsFor).
struct Pinhole
{
  double fx, fy, cx, cy;
  Pinhole(const View& view, int width, int height)
    : fx(0.5 * width / std::tan(0.5 * view.horizontal))
    , fy(0.5 * height / std::tan(0.5 * view.vertical))
    , cx(0.5 * (width - 1))
    , cy(0.5 * (height - 1))
  {
  }
};

/// The camera link's axes (x forward, y left, z up) in the base at the contract's pan and tilt (URDF: pan about -z,
/// then tilt about the turned -y).
Eigen::Matrix3d linkInBase(const View& view)
{
  return (Eigen::AngleAxisd(-view.pan, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(-view.tilt, Eigen::Vector3d::UnitY()))
      .toRotationMatrix();
}

/// The direction in the base that `pixel` of an image seen from `view` shows (far away).
Eigen::Vector3d directionOf(const Pixel& pixel, const View& view, int width, int height)
{
  const Pinhole lens(view, width, height);
  // Optical (x right, y down, z forward) to the link's axes.
  const Eigen::Vector3d in_link(1.0, -(pixel.u - lens.cx) / lens.fx, -(pixel.v - lens.cy) / lens.fy);
  return linkInBase(view) * in_link;
}

/// The pixel of an image seen from `view` that shows `direction`; nullopt behind the camera.
std::optional<Pixel> pixelOf(const Eigen::Vector3d& direction, const View& view, int width, int height)
{
  const Eigen::Vector3d in_link = linkInBase(view).transpose() * direction;
  if (!(in_link.x() > 1e-9))
  {
    return std::nullopt;
  }
  const Pinhole lens(view, width, height);
  return Pixel{ lens.cx - lens.fx * in_link.y() / in_link.x(), lens.cy - lens.fy * in_link.z() / in_link.x() };
}
}  // namespace

std::optional<AimInImage> aimInImage(const PixelAim& aim, const std::optional<View>& aim_view, int width, int height,
                                     const std::optional<View>& view)
{
  if (width <= 0 || height <= 0 || aim.image_width <= 0 || aim.image_height <= 0)
  {
    return std::nullopt;
  }
  const PixelBox& t = aim.target;
  const std::array<Pixel, 4> corners = { { { t.u - 0.5 * t.width, t.v - 0.5 * t.height },
                                           { t.u + 0.5 * t.width, t.v - 0.5 * t.height },
                                           { t.u + 0.5 * t.width, t.v + 0.5 * t.height },
                                           { t.u - 0.5 * t.width, t.v + 0.5 * t.height } } };
  const auto place = [&](const Pixel& pixel) -> std::optional<Pixel> {
    if (aim_view && view)
    {
      return pixelOf(directionOf(pixel, *aim_view, aim.image_width, aim.image_height), *view, width, height);
    }
    // The same place of the picture: outer distances scale with the size.
    return Pixel{ (pixel.u + 0.5) * width / aim.image_width - 0.5, (pixel.v + 0.5) * height / aim.image_height - 0.5 };
  };
  AimInImage result;
  result.tracked = aim_view.has_value() && view.has_value();
  const std::optional<Pixel> centre = place({ t.u, t.v });
  if (!centre)
  {
    return std::nullopt;
  }
  result.centre = *centre;
  result.box = t.width > 0.0 && t.height > 0.0;
  if (result.box)
  {
    for (std::size_t i = 0; i < corners.size(); ++i)
    {
      const std::optional<Pixel> corner = place(corners[i]);
      if (!corner)
      {
        return std::nullopt;
      }
      result.corners[i] = *corner;
    }
  }
  return result;
}

void PixelGoalWatch::goalSent(const PixelAim& aim, double now)
{
  aim_ = aim;
  heard_ = now;
  listed_ = false;
  running_ = true;
}

void PixelGoalWatch::status(const std::vector<GoalStatusEntry>& goals)
{
  if (!aim_)
  {
    return;
  }
  constexpr std::uint8_t PENDING = 0, ACTIVE = 1, PREEMPTING = 6, RECALLING = 7;
  for (const GoalStatusEntry& goal : goals)
  {
    if (goal.id == aim_->goal_id)
    {
      listed_ = true;
      running_ =
          goal.status == PENDING || goal.status == ACTIVE || goal.status == PREEMPTING || goal.status == RECALLING;
      return;
    }
  }
  if (listed_)
  {
    running_ = false;  // named before, gone now: it ended
  }
}

void PixelGoalWatch::clear()
{
  aim_.reset();
  listed_ = false;
  running_ = false;
}

std::optional<PixelAim> PixelGoalWatch::active(double now) const
{
  if (!aim_ || !running_ || (!listed_ && now - heard_ > UNLISTED_TIMEOUT))
  {
    return std::nullopt;
  }
  return aim_;
}

}  // namespace ptz_action_server::panel
