#include <gtest/gtest.h>

#include <string>

#include "device_fixtures_internal.h"
#include "harness/axis_harness.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
// ---------------------------------------------------------------- Axis (VAPIX)

vapix::ZoomTable zoomTable(const std::string& text)
{
  vapix::ZoomTable table;
  vapix::ZoomTable::parse(text, table);
  return table;
}

/// An Axis camera: by default the emulator's own (zoom attributes, an 18X table); \p camera for a field case, whose
/// zoom goals the backend sends through \p backend_table.
class AxisFixture : public HttpCameraFixture<AxisHarness>
{
public:
  explicit AxisFixture(const AxisCameraEmulatorConfig& camera = AxisCameraEmulatorConfig(),
                       const vapix::ZoomTable& backend_table = zoomTable(AxisCameraEmulatorConfig::DEFAULT_ZOOM_TABLE))
    : HttpCameraFixture(camera), backend_table_(backend_table)
  {
  }

  std::string prepareRefusal(AxisValues& goal) override
  {
    harness_.emulator().setRefuse(true);
    goal = AxisValues{ { 0.3, 0.0, 1.0 } };
    return std::string("the Axis camera refused 'pan=17.1887&tilt=0.0000&zoom=1&speed=100': ") +
           AxisCameraEmulator::REFUSAL;
  }
  void expectGoalCommands(const std::vector<ClassifiedCommand>& commands, const AxisValues& target) const override
  {
    // The zoom value goes out through the table the backend found (the camera's, or its guess).
    std::string expected = "GET /axis-cgi/com/ptz.cgi?camera=1&";
    vapix::appendAbsoluteMove(expected, toDegrees(target[PAN]), toDegrees(target[TILT]),
                              backend_table_.toValue(target[ZOOM]), 100);
    EXPECT_EQ(texts(withoutQueries(commands)), std::vector<std::string>{ expected });
  }

private:
  const vapix::ZoomTable backend_table_;
};

/// The emulator's own Axis camera over https (its certificate pinned).
AxisCameraEmulatorConfig axisTlsCamera()
{
  AxisCameraEmulatorConfig camera;
  camera.http.tls = true;
  return camera;
}

/// The camera of issue 21, as it answered in the field: no `query=attributes` (info=1 does not list it, asking answers
/// `Error:` / `query: unknown value: attributes`), MinZoom=1 and MaxZoom=9999 in the limits, zoom, iris, focus,
/// brightness, autofocus and autoiris in the position; a Q6155-E with a 30X lens, whose family the backend guesses
/// 30X for: the guess and the lens agree, so zoom goals reach their X.
AxisCameraEmulatorConfig axisFieldCamera()
{
  AxisCameraEmulatorConfig camera;
  camera.attributes = false;
  camera.zoom_table = AxisCameraEmulatorConfig::linearZoomTable(30.0);
  camera.model = "Q6155-E";
  return camera;
}

const DeviceFixtureRegistration AXIS_FIXTURES({
    { "AxisHttpDigest", [] { return std::make_unique<AxisFixture>(); } },
    { "AxisHttpsPinned", [] { return std::make_unique<AxisFixture>(axisTlsCamera()); } },
    { "AxisFieldNoZoomAttributes",
      [] { return std::make_unique<AxisFixture>(axisFieldCamera(), vapix::ZoomTable::linear(30.0)); } },
});
}  // namespace

}  // namespace ptz_action_server
