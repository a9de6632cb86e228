/**
 * \file
 * \brief libFuzzer target: the SOAP envelope reader and every ONVIF reply reader (PTZ and Imaging) on arbitrary bytes.
 * They never read out of bounds, never crash on a missing element, and what they accept is sane.
 */
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/onvif/onvif_imaging.h"

using namespace ptz_action_server::onvif;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string xml(reinterpret_cast<const char*>(data), size);
  SoapMessage message;
  if (!parseSoap(xml, message).empty())
  {
    return 0;
  }
  if (message.content == nullptr || (message.fault && message.fault_text.empty()))
  {
    std::abort();
  }
  double seconds = 0.0;
  readSystemTime(message.content, seconds);
  ServicePaths paths;
  if (readCapabilities(message.content, paths).empty() && (paths.ptz.empty() || paths.ptz[0] != '/'))
  {
    std::abort();
  }
  if (readServices(message.content, paths).empty() && (paths.ptz.empty() || paths.ptz[0] != '/'))
  {
    std::abort();
  }
  Profile profile;
  readProfiles(message.content, "", profile);
  Node node;
  if (readNode(message.content, "", node).empty())
  {
    for (const auto* spaces : { &node.absolute_pan_tilt, &node.absolute_zoom, &node.relative_pan_tilt,
                                &node.relative_zoom, &node.continuous_pan_tilt, &node.continuous_zoom })
    {
      for (const Space& space : *spaces)
      {
        if (!(space.x.min <= space.x.max) || space.uri.empty())
        {
          std::abort();
        }
      }
    }
    if (node.max_presets < 0)
    {
      std::abort();
    }
  }
  double low = 0.0;
  double high = 0.0;
  if (readTimeoutRange(message.content, low, high).empty() && low > high)
  {
    std::abort();
  }
  Status status;
  if (readStatus(message.content, status).empty() &&
      !(std::isfinite(status.x) && std::isfinite(status.y) && std::isfinite(status.zoom)))
  {
    std::abort();
  }
  std::vector<Preset> presets;
  if (readPresets(message.content, presets).empty())
  {
    for (const Preset& preset : presets)
    {
      if (preset.token.empty() || !std::isfinite(preset.position.x) || !std::isfinite(preset.position.zoom))
      {
        std::abort();
      }
    }
  }
  std::string token;
  if (readPresetToken(message.content, token).empty() && token.empty())
  {
    std::abort();
  }
  // The Imaging service's readers: ranges they accept are ordered, values finite, shares within 0..1.
  ImagingOptions options;
  readImagingOptions(message.content, options);
  readMoveOptions(message.content, options);
  for (const FloatRange* range : { &options.iris, &options.focus_position, &options.focus_speed })
  {
    if (range->known && !(range->min <= range->max && std::isfinite(range->min) && std::isfinite(range->max)))
    {
      std::abort();
    }
  }
  ImagingReading reading;
  readImagingSettings(message.content, reading);
  readImagingStatus(message.content, reading);
  if ((reading.has_iris && !std::isfinite(reading.iris)) || (reading.has_focus && !std::isfinite(reading.focus)))
  {
    std::abort();
  }
  const double share = irisShare(options.iris, reading.iris);
  if (options.iris.known && !(share >= 0.0 && share <= 1.0))
  {
    std::abort();
  }
  if (faultHas(message, "ActionNotSupported") && !message.fault)
  {
    std::abort();
  }
  return 0;
}
