// ptz_blob_detector: a detector to try detection tracking with. Finds the blobs of one colour in each image of `image`
// (sensor_msgs/Image: rgb8, bgr8, rgba8 or bgra8, through image_transport) and publishes them on `detections`
// (ptz_action_server/Detections) with the image's header, even when it finds none. Remap `image` to the camera's
// topic (image:=/ptz/image_raw); run it in the camera's namespace and `detections` is beside it.
//
// Parameters (private, read once; a bad one exits 1 naming it):
//   colour [255, 0, 255], tolerance 40: the colour (R, G, B, 0..255) and how far each channel may be off it; the
//     default is the simulated camera's first marker colour, magenta.
//   hsv_min, hsv_max: instead of those, a range of [hue (degrees, 0..360; min > max wraps through 0), saturation,
//     value (0..1)]: a real camera's coloured ball under changing light.
//   min_area (4 px), max_detections (10): smaller blobs are noise; the largest ones are kept.
//   id ("blob"): every detection's id.
// Each detection: the blob's centroid (u, v), its bounding box's size, and its area over the largest blob's as score.
// See doc/tracking-detections.md.
#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include <image_transport/image_transport.h>
#include <opencv2/core.hpp>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include "ptz_action_server/Detections.h"
#include "ptz_action_server/core/types.h"
#include "ptz_action_server/ros/param_reader.h"
#include "ptz_action_server/vision/blob_finder.h"

namespace
{
using ptz_action_server::BlobFinder;
using ptz_action_server::BlobFinderSettings;
using ptz_action_server::ChannelOrder;
using ptz_action_server::ConfigError;
using ptz_action_server::ParamReader;

/// Three numbers from \p text ("300, 0.5, 0.5" or "[300, 0.5, 0.5]": rosrun's _name:=value gives a C++ node a
/// string, not a list); false unless there are exactly three.
bool parseTriple(std::string text, double (&values)[3])
{
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '[' || c == ']' || c == ','; }, ' ');
  std::istringstream numbers(text);
  for (double& value : values)
  {
    if (!(numbers >> value))
    {
      return false;
    }
  }
  std::string rest;
  return !(numbers >> rest);
}

/// A list of three numbers (or a string of them), each in [\p min, \p max]; false if \p name is not set.
bool readTriple(const ParamReader& params, const std::string& name, double min, double max, double (&values)[3])
{
  XmlRpc::XmlRpcValue list;
  if (!params.get(name, list))
  {
    return false;
  }
  const ConfigError wrong(params.resolve(name) + " must be a list of three numbers");
  const bool text = list.getType() == XmlRpc::XmlRpcValue::TypeString;
  if (text ? !parseTriple(static_cast<std::string>(list), values) :
             list.getType() != XmlRpc::XmlRpcValue::TypeArray || list.size() != 3)
  {
    throw wrong;
  }
  for (int index = 0; index < 3 && !text; ++index)
  {
    XmlRpc::XmlRpcValue& item = list[index];
    if (item.getType() != XmlRpc::XmlRpcValue::TypeInt && item.getType() != XmlRpc::XmlRpcValue::TypeDouble)
    {
      throw wrong;
    }
    values[index] = item.getType() == XmlRpc::XmlRpcValue::TypeInt ? static_cast<int>(item) : static_cast<double>(item);
  }
  for (const double value : values)
  {
    if (!(value >= min && value <= max))
    {
      std::ostringstream problem;
      problem << params.resolve(name) << " must hold numbers in [" << min << ", " << max << "], not " << value;
      throw ConfigError(problem.str());
    }
  }
  return true;
}

/// The finder's settings from the private parameters.
BlobFinderSettings readSettings(const ParamReader& params)
{
  BlobFinderSettings settings;
  double low[3];
  double high[3];
  const bool has_min = readTriple(params, "hsv_min", 0.0, 360.0, low);
  const bool has_max = readTriple(params, "hsv_max", 0.0, 360.0, high);
  if (has_min != has_max)
  {
    throw ConfigError(params.resolve("hsv_min") + " and hsv_max go together: give both or neither");
  }
  if (has_min)
  {
    settings.colour.hsv = true;
    settings.colour.hue_min = low[0];
    settings.colour.hue_max = high[0];
    settings.colour.saturation_min = low[1];
    settings.colour.saturation_max = high[1];
    settings.colour.value_min = low[2];
    settings.colour.value_max = high[2];
  }
  double rgb[3];
  if (readTriple(params, "colour", 0.0, 255.0, rgb))
  {
    for (int index = 0; index < 3; ++index)
    {
      settings.colour.rgb[index] = static_cast<int>(rgb[index]);
    }
  }
  settings.colour.tolerance = params.integer("tolerance", settings.colour.tolerance, 0, 255);
  settings.min_area = params.integer("min_area", settings.min_area, 1, 1 << 30);
  settings.max_blobs = static_cast<std::size_t>(params.integer("max_detections", 10, 1, 10000));
  const std::string problem = ptz_action_server::findBadBlobSettings(settings);
  if (!problem.empty())
  {
    throw ConfigError(params.resolve(has_min ? "hsv_min" : "colour") + ": " + problem);
  }
  return settings;
}

class BlobDetector
{
public:
  BlobDetector(ros::NodeHandle& node, const ParamReader& params)
    : finder_(readSettings(params)), id_(params.text("id", "blob")), transport_(node)
  {
    publisher_ = node.advertise<ptz_action_server::Detections>("detections", 10);
    subscriber_ = transport_.subscribe("image", 1, &BlobDetector::onImage, this);
    const ptz_action_server::BlobColour& colour = finder_.settings().colour;
    if (colour.hsv)
    {
      ROS_INFO("ptz_blob_detector: blobs of hue %g to %g degrees, saturation %g to %g, value %g to %g in %s, on %s",
               colour.hue_min, colour.hue_max, colour.saturation_min, colour.saturation_max, colour.value_min,
               colour.value_max, subscriber_.getTopic().c_str(), publisher_.getTopic().c_str());
    }
    else
    {
      ROS_INFO("ptz_blob_detector: blobs of RGB (%d, %d, %d) give or take %d in %s, on %s", colour.rgb[0],
               colour.rgb[1], colour.rgb[2], colour.tolerance, subscriber_.getTopic().c_str(),
               publisher_.getTopic().c_str());
    }
  }

private:
  void onImage(const sensor_msgs::ImageConstPtr& image)
  {
    const std::string& encoding = image->encoding;
    const bool four = encoding == "rgba8" || encoding == "bgra8";
    if (!four && encoding != "rgb8" && encoding != "bgr8")
    {
      ROS_WARN_THROTTLE(10.0, "ptz_blob_detector: images in %s are not read (rgb8, bgr8, rgba8 or bgra8)",
                        encoding.c_str());
      return;
    }
    const std::size_t row = static_cast<std::size_t>(image->width) * (four ? 4u : 3u);
    if (image->width == 0 || image->height == 0 || image->step < row ||
        image->data.size() < static_cast<std::size_t>(image->step) * (image->height - 1) + row)
    {
      ROS_WARN_THROTTLE(10.0, "ptz_blob_detector: an image of %u x %u px with step %u holds %zu bytes: not read",
                        image->width, image->height, image->step, image->data.size());
      return;
    }
    // A view of the message's bytes, not a copy: the finder only reads its input.
    const cv::Mat view(static_cast<int>(image->height), static_cast<int>(image->width), four ? CV_8UC4 : CV_8UC3,
                       const_cast<std::uint8_t*>(image->data.data()), image->step);
    const ChannelOrder order = encoding[0] == 'r' ? ChannelOrder::RGB : ChannelOrder::BGR;
    const std::vector<ptz_action_server::Blob>& blobs = finder_.find(view, order);
    detections_.header = image->header;
    detections_.image_width = image->width;
    detections_.image_height = image->height;
    detections_.detections.resize(blobs.size());
    for (std::size_t index = 0; index < blobs.size(); ++index)
    {
      const ptz_action_server::Blob& blob = blobs[index];
      ptz_action_server::Detection& detection = detections_.detections[index];
      detection.id = id_;
      detection.score = static_cast<float>(blob.area) / static_cast<float>(blobs.front().area);
      detection.u = blob.u;
      detection.v = blob.v;
      detection.width = blob.width;
      detection.height = blob.height;
    }
    publisher_.publish(detections_);
  }

  BlobFinder finder_;
  const std::string id_;
  image_transport::ImageTransport transport_;
  image_transport::Subscriber subscriber_;
  ros::Publisher publisher_;
  ptz_action_server::Detections detections_;  ///< reused: its vector and strings keep their capacity
};

}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "ptz_blob_detector");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try
  {
    BlobDetector detector(node, ParamReader(private_node));
    ros::spin();
  }
  catch (const ConfigError& error)
  {
    ROS_FATAL("ptz_blob_detector: %s", error.what());
    return 1;
  }
  return 0;
}
