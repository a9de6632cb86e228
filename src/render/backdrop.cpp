// CameraRenderer's backdrop: sky, ground and the marks, shaded per pixel from the direction lookup, and their labels.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <opencv2/core/hal/intrin.hpp>

#include "ptz_action_server/render/camera_renderer.h"

namespace ptz_action_server
{
namespace
{
constexpr float MINOR_HALF_WIDTH = 0.6F;  ///< px: a mark's line is 1.2 px wide
constexpr float MINOR_ALPHA = 0.55F;
constexpr float MAJOR_HALF_WIDTH = 1.5F;  ///< px: the horizon and the quarters of azimuth
constexpr float MAJOR_ALPHA = 0.9F;
constexpr float LINE = 245.0F;            ///< the marks' grey level
constexpr int MAX_LABELS_PER_KIND = 200;  ///< more marks than this in view (near a pole) go without degrees

constexpr int LANES = 4;           ///< pixels in one 128-bit vector of floats
constexpr int PIXELS = 4 * LANES;  ///< pixels shaded together: one 128-bit vector of bytes per channel

/// The colours (RGB) the backdrop blends between: every channel within [20, 250], as the marker colours require.
constexpr float SKY_LOW[3] = { 185, 210, 235 };  ///< at the horizon
constexpr float SKY_HIGH[3] = { 70, 115, 190 };  ///< at the zenith
constexpr float GROUND_LOW[3] = { 140, 125, 95 };
constexpr float GROUND_DEEP[3] = { 75, 85, 55 };  ///< at the nadir

/// The marks' spacing for one render.
struct MarkGrid
{
  float step = 0.0F;                ///< rad between marks
  float inverse_step = 0.0F;        ///< 1 / step
  float reference_steps = 0.0F;     ///< the reference azimuth's fraction of a step
  float reference_quarters = 0.0F;  ///< its fraction of a quarter turn
};

/// Distance (in units of the spacing) from each of \p t to the nearest integer.
inline cv::v_float32x4 toNearestInteger(const cv::v_float32x4& t)
{
  return cv::v_abs(t - cv::v_cvt_f32(cv::v_round(t)));
}

/// How much of a pixel \p distance px from the middle of a line \p half_width px wide the line covers (1 px falloff).
inline cv::v_float32x4 coverage(const cv::v_float32x4& distance, float half_width)
{
  return cv::v_min(cv::v_max(cv::v_setall_f32(half_width + 0.5F) - distance, cv::v_setzero_f32()),
                   cv::v_setall_f32(1.0F));
}

/// How much the marks cover the pixels looking at \p azimuth and \p elevation, with \p azimuth_scale and
/// \p elevation_scale pixels per rad across their marks: a mark's distance in angle times the scale is in pixels.
cv::v_float32x4 markCoverage(const cv::v_float32x4& azimuth, const cv::v_float32x4& elevation,
                             const cv::v_float32x4& azimuth_scale, const cv::v_float32x4& elevation_scale,
                             const MarkGrid& grid)
{
  const cv::v_float32x4 step = cv::v_setall_f32(grid.step);
  const cv::v_float32x4 inverse_step = cv::v_setall_f32(grid.inverse_step);
  const cv::v_float32x4 quarter = cv::v_setall_f32(static_cast<float>(M_PI_2));
  const cv::v_float32x4 to_meridian =
      toNearestInteger(azimuth * inverse_step + cv::v_setall_f32(grid.reference_steps)) * step * azimuth_scale;
  const cv::v_float32x4 to_parallel = toNearestInteger(elevation * inverse_step) * step * elevation_scale;
  const cv::v_float32x4 quarters = azimuth * cv::v_setall_f32(static_cast<float>(M_2_PI));
  const cv::v_float32x4 to_quarter =
      toNearestInteger(quarters + cv::v_setall_f32(grid.reference_quarters)) * quarter * azimuth_scale;
  const cv::v_float32x4 to_horizon = cv::v_abs(elevation) * elevation_scale;
  const cv::v_float32x4 minor = cv::v_setall_f32(MINOR_ALPHA) * cv::v_max(coverage(to_meridian, MINOR_HALF_WIDTH),
                                                                          coverage(to_parallel, MINOR_HALF_WIDTH));
  const cv::v_float32x4 major = cv::v_setall_f32(MAJOR_ALPHA) * cv::v_max(coverage(to_quarter, MAJOR_HALF_WIDTH),
                                                                          coverage(to_horizon, MAJOR_HALF_WIDTH));
  return cv::v_max(minor, major);
}

/**
 * Shades the PIXELS pixels looking at \p directions (their PixelDirections' floats) into \p rgb (3 bytes each): sky
 * or ground by elevation, deeper away from the horizon (with the square root of the elevation's share of a quarter
 * turn), and the marks blended over it. OpenCV's universal intrinsics: SSE2 or NEON, no call and no branch per pixel.
 */
void shadePixels(const float* directions, const MarkGrid& grid, uchar* rgb)
{
  const cv::v_float32x4 zero = cv::v_setzero_f32();
  cv::v_int32x4 channels[3][LANES];
  for (int quad = 0; quad < LANES; ++quad)
  {
    cv::v_float32x4 azimuth;
    cv::v_float32x4 elevation;
    cv::v_float32x4 azimuth_scale;
    cv::v_float32x4 elevation_scale;
    cv::v_load_deinterleave(directions + 4 * LANES * quad, azimuth, elevation, azimuth_scale, elevation_scale);
    const cv::v_float32x4 line = markCoverage(azimuth, elevation, azimuth_scale, elevation_scale, grid);
    const cv::v_float32x4 height =
        cv::v_sqrt(cv::v_min(cv::v_abs(elevation) * cv::v_setall_f32(static_cast<float>(M_2_PI)), cv::v_setall_f32(1)));
    const cv::v_float32x4 sky = elevation >= zero;
    for (int channel = 0; channel < 3; ++channel)
    {
      const cv::v_float32x4 low =
          cv::v_select(sky, cv::v_setall_f32(SKY_LOW[channel]), cv::v_setall_f32(GROUND_LOW[channel]));
      const cv::v_float32x4 high =
          cv::v_select(sky, cv::v_setall_f32(SKY_HIGH[channel]), cv::v_setall_f32(GROUND_DEEP[channel]));
      const cv::v_float32x4 shade = low + (high - low) * height;
      channels[channel][quad] = cv::v_round(shade + (cv::v_setall_f32(LINE) - shade) * line);
    }
  }
  cv::v_uint8x16 bytes[3];
  for (int channel = 0; channel < 3; ++channel)
  {
    bytes[channel] = cv::v_pack_u(cv::v_pack(channels[channel][0], channels[channel][1]),
                                  cv::v_pack(channels[channel][2], channels[channel][3]));
  }
  cv::v_store_interleave(rgb, bytes[0], bytes[1], bytes[2]);
}

/// The fractional part of \p value, in [0, 1).
double fraction(double value)
{
  return value - std::floor(value);
}

/// \p degrees as a label: as many decimals as \p step_degrees needs.
void formatDegrees(char* text, std::size_t size, const char* prefix, double degrees, double step_degrees, bool sign)
{
  const int decimals = step_degrees >= 1.0 ? 0 : (step_degrees >= 0.1 ? 1 : 2);
  std::snprintf(text, size, sign ? "%s%+.*f" : "%s%.*f", prefix, decimals, degrees);
}
}  // namespace

void CameraRenderer::drawBackdrop(cv::Mat& image) const
{
  const cv::Mat& directions = lookup_.directions();
  MarkGrid grid;
  grid.step = static_cast<float>(mark_step_);
  grid.inverse_step = 1.0F / grid.step;
  // The lookup's azimuths are relative to the reference: the reference's fraction of a step puts the marks back on
  // absolute multiples of the step.
  grid.reference_steps = static_cast<float>(fraction(lookup_.referenceAzimuth() / mark_step_));
  grid.reference_quarters = static_cast<float>(fraction(lookup_.referenceAzimuth() / M_PI_2));
  const int width = image.cols;
  const int whole = width - width % PIXELS;
  for (int v = 0; v < image.rows; ++v)
  {
    const float* direction = directions.ptr<float>(v);
    uchar* pixel = image.ptr<uchar>(v);
    for (int u = 0; u < whole; u += PIXELS)
    {
      shadePixels(direction + 4 * u, grid, pixel + 3 * u);
    }
    if (whole < width)
    {
      // The last few pixels of the row, padded with copies of its last one.
      float tail[4 * PIXELS];
      uchar tail_rgb[3 * PIXELS];
      for (int index = 0; index < PIXELS; ++index)
      {
        std::copy_n(direction + 4 * std::min(whole + index, width - 1), 4, tail + 4 * index);
      }
      shadePixels(tail, grid, tail_rgb);
      std::copy_n(tail_rgb, 3 * (width - whole), pixel + 3 * whole);
    }
  }
}

void CameraRenderer::drawMarkLabels(cv::Mat& image)
{
  double min_azimuth = 0.0;
  double max_azimuth = 0.0;
  double min_elevation = 0.0;
  double max_elevation = 0.0;
  lookup_.range(min_azimuth, max_azimuth, min_elevation, max_elevation);
  const double reference = lookup_.referenceAzimuth();
  const double step = mark_step_;
  const double step_degrees = step * 180.0 / M_PI;
  // The marks crossing nearest the image's centre carry the labels: azimuths along that parallel, elevations along
  // that meridian.
  double u = 0.0;
  double v = 0.0;
  const PixelDirection centre = lookup_.exactAt(intrinsics_.cx, intrinsics_.cy);
  const double label_elevation = std::clamp(std::round(centre.elevation / step) * step, -M_PI_2 + step, M_PI_2 - step);
  const double label_azimuth = std::round(reference / step) * step;
  char text[32];

  const long first_meridian = std::lround(std::ceil((reference + min_azimuth) / step));
  const long last_meridian = std::lround(std::floor((reference + max_azimuth) / step));
  if (last_meridian - first_meridian < MAX_LABELS_PER_KIND)
  {
    for (long mark = first_meridian; mark <= last_meridian; ++mark)
    {
      const double azimuth = static_cast<double>(mark) * step;
      if (pixelOfDirection(azimuth, label_elevation, u, v))
      {
        double degrees = std::remainder(static_cast<double>(mark) * step_degrees, 360.0);
        degrees = degrees <= -180.0 + 1e-9 ? 180.0 : degrees;
        formatDegrees(text, sizeof(text), "az ", degrees, step_degrees, false);
        label_ = text;
        writeLabel(image, u + 3.0, v + 3.0);
      }
    }
  }
  const long first_parallel = std::lround(std::ceil(min_elevation / step));
  const long last_parallel = std::lround(std::floor(max_elevation / step));
  if (last_parallel - first_parallel < MAX_LABELS_PER_KIND)
  {
    for (long mark = first_parallel; mark <= last_parallel; ++mark)
    {
      const double elevation = static_cast<double>(mark) * step;
      if (std::abs(elevation) < M_PI_2 - 1e-9 && pixelOfDirection(label_azimuth, elevation, u, v))
      {
        formatDegrees(text, sizeof(text), "el ", static_cast<double>(mark) * step_degrees, step_degrees, true);
        label_ = mark == 0 ? "horizon" : text;
        writeLabel(image, u + 3.0, v - 16.0);
      }
    }
  }
}

}  // namespace ptz_action_server
