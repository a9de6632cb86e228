/**
 * \file
 * \brief bench_render: what the simulated camera's picture costs. Renders N images (default 300) per size, 640x360
 * (the default) and 1280x720, with the camera sweeping in pan and tilt, zooming from 1 to 24 X and two markers in view,
 * as SimCameraPublisher does for each frame; prints the render time per image (mean, p50, p95, max, in ms, wall clock
 * of this one thread), its CPU time per image and the share of one core at 10 Hz. Prints figures, asserts nothing.
 *
 * usage: bench_render [URDF] [IMAGES]
 */
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ptz_action_server/core/motion/field_of_view.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/render/camera_renderer.h"

namespace
{
double threadCpuSeconds()
{
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

double percentile(std::vector<double> values, double fraction)
{
  std::sort(values.begin(), values.end());
  const std::size_t index = std::min(values.size() - 1, static_cast<std::size_t>(fraction * values.size()));
  return values[index];
}
}  // namespace

int main(int argc, char** argv)
{
  using namespace ptz_action_server;
  const std::string urdf_path = argc > 1 ? argv[1] : std::string(PTZ_SOURCE_DIR) + "/urdf/ptz.urdf";
  const int images = argc > 2 ? std::atoi(argv[2]) : 300;
  std::ifstream file(urdf_path);
  if (!file || images < 10 || images > 100000)
  {
    std::fprintf(stderr, "usage: bench_render [URDF] [IMAGES]  (a readable URDF; 10 <= IMAGES <= 100000)\n");
    return 2;
  }
  std::stringstream urdf;
  urdf << file.rdbuf();
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(urdf.str());
  constexpr double RATE = 10.0;  // Hz, the default

  std::printf("the simulated camera's render, %d images per size (one thread; CPU %% of one core at %.0f Hz)\n", images,
              RATE);
  std::printf("| size | mean ms | p50 ms | p95 ms | max ms | CPU ms/image | CPU at %.0f Hz |\n", RATE);
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const auto& [width, height] : { std::pair<int, int>{ 640, 360 }, std::pair<int, int>{ 1280, 720 } })
  {
    const FieldOfViewModel lens =
        FieldOfViewModel::fromWideEnd({ M_PI / 3.0, 2.0 * std::atan(std::tan(M_PI / 6.0) * height / width) });
    CameraRenderer renderer;
    cv::Mat image;
    std::vector<SceneMarker> markers(2);
    markers[0].name = "ptz_demo_target";
    markers[1].name = "another_frame";
    std::vector<double> wall_ms;
    double cpu = 0.0;
    for (int index = -5; index < images; ++index)  // five to warm up: the first allocates the buffers
    {
      const double phase = static_cast<double>(std::max(index, 0)) / images;
      const double pan = -3.0 + 6.0 * phase;
      const double tilt = 0.6 * std::sin(2.0 * M_PI * phase);
      const double zoom = 1.0 + 23.0 * (0.5 - 0.5 * std::cos(4.0 * M_PI * phase));
      const Eigen::Isometry3d camera = kinematics.cameraInBase(pan, tilt);
      // Both markers in view: 4 m and 9 m along the optical axis, a little aside.
      markers[0].position = camera * Eigen::Vector3d(4.0, 0.05, 0.02);
      markers[1].position = camera * Eigen::Vector3d(9.0, -0.2, -0.1);
      markers[0].present = markers[1].present = true;
      const auto start = std::chrono::steady_clock::now();
      const double cpu_start = threadCpuSeconds();
      renderer.render(camera, intrinsicsFor(lens.at(zoom), width, height), markers, image);
      const double cpu_seconds = threadCpuSeconds() - cpu_start;
      const double elapsed =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (index >= 0)
      {
        wall_ms.push_back(elapsed);
        cpu += cpu_seconds;
      }
    }
    double mean = 0.0;
    for (const double value : wall_ms)
    {
      mean += value / static_cast<double>(wall_ms.size());
    }
    const double cpu_ms = cpu * 1000.0 / images;
    std::printf("| %dx%d | %.2f | %.2f | %.2f | %.2f | %.2f | %.1f %% |\n", width, height, mean,
                percentile(wall_ms, 0.5), percentile(wall_ms, 0.95), percentile(wall_ms, 1.0), cpu_ms,
                cpu_ms * RATE / 10.0);
  }
  return 0;
}
