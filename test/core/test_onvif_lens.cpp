/**
 * \file
 * \brief ONVIF focus and iris through the Imaging service: golden requests, replies read in other prefixes, the iris'
 * dB to shares both ways; against onvif_camera_emulator's camera on 127.0.0.1 the lens declared from GetOptions and
 * GetMoveOptions, each command reaching the camera in its own XML words and moving its lens, read back, the camera's
 * refusal of a focus Move in AUTO, and a camera without the Imaging service saying it lacks them.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "onvif_backend_test_support.h"
#include "onvif_test_client.h"
#include "ptz_action_server/core/lens_commander.h"
#include "ptz_action_server/core/onvif/onvif_imaging.h"
#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif_backend_test;
using namespace onvif;

constexpr LensFunction FOCUS = LensFunction::FOCUS;
constexpr LensFunction IRIS = LensFunction::IRIS;
constexpr const char* TIMG = "xmlns:timg=\"http://www.onvif.org/ver20/imaging/wsdl\"";

TEST(OnvifImagingCodec, RequestsAreGolden)
{
  const std::string head = std::string("<timg:Move ") + TIMG + "><timg:VideoSourceToken>vs_0</timg:VideoSourceToken>";
  EXPECT_EQ(moveFocusContinuous("vs_0", -2.5), head + "<timg:Focus><tt:Continuous><tt:Speed>-2.5</tt:Speed></"
                                                      "tt:Continuous></timg:Focus></timg:Move>");
  EXPECT_EQ(moveFocusAbsolute("vs_0", 250), head + "<timg:Focus><tt:Absolute><tt:Position>250</tt:Position></"
                                                   "tt:Absolute></timg:Focus></timg:Move>");
  EXPECT_EQ(stopFocus("v<1>"), std::string("<timg:Stop ") + TIMG +
                                   "><timg:VideoSourceToken>v&lt;1&gt;</timg:VideoSourceToken></timg:Stop>");
  const std::string set = std::string("<timg:SetImagingSettings ") + TIMG +
                          "><timg:VideoSourceToken>vs_0</timg:VideoSourceToken><timg:ImagingSettings>";
  EXPECT_EQ(setFocusMode("vs_0", false), set + "<tt:Focus><tt:AutoFocusMode>MANUAL</tt:AutoFocusMode></tt:Focus>"
                                               "</timg:ImagingSettings></timg:SetImagingSettings>");
  EXPECT_EQ(setExposure("vs_0", false, -11.0), set + "<tt:Exposure><tt:Mode>MANUAL</tt:Mode><tt:Iris>-11</tt:Iris>"
                                                     "</tt:Exposure></timg:ImagingSettings></timg:SetImagingSettings>");
  EXPECT_EQ(setExposure("vs_0", true, NAN), set + "<tt:Exposure><tt:Mode>AUTO</tt:Mode></tt:Exposure>"
                                                  "</timg:ImagingSettings></timg:SetImagingSettings>");
  for (const auto& [body, operation] : { std::make_pair(getImagingSettings("vs_0"), "GetImagingSettings"),
                                         std::make_pair(getImagingOptions("vs_0"), "GetOptions"),
                                         std::make_pair(getMoveOptions("vs_0"), "GetMoveOptions"),
                                         std::make_pair(getImagingStatus("vs_0"), "GetStatus") })
  {
    EXPECT_EQ(body, std::string("<timg:") + operation + " " + TIMG +
                        "><timg:VideoSourceToken>vs_0</timg:VideoSourceToken></timg:" + operation + ">");
  }
}

TEST(OnvifImagingCodec, RepliesInOtherPrefixesReadAlike)
{
  SoapMessage message;
  ASSERT_EQ(parseSoap("<e:Envelope xmlns:e=\"http://www.w3.org/2003/05/soap-envelope\" "
                      "xmlns:x=\"http://www.onvif.org/ver10/schema\"><e:Body><GetOptionsResponse "
                      "xmlns=\"http://www.onvif.org/ver20/imaging/wsdl\"><ImagingOptions><x:Exposure><x:Mode>AUTO"
                      "</x:Mode><x:Mode>MANUAL</x:Mode><x:Iris><x:Min>-22</x:Min><x:Max>0</x:Max></x:Iris>"
                      "</x:Exposure><x:Focus><x:AutoFocusModes>AUTO</x:AutoFocusModes></x:Focus></ImagingOptions>"
                      "</GetOptionsResponse></e:Body></e:Envelope>",
                      message),
            "");
  ImagingOptions options;
  ASSERT_EQ(readImagingOptions(message.content, options), "");
  EXPECT_TRUE(options.exposure_auto && options.exposure_manual && options.focus_auto);
  EXPECT_FALSE(options.focus_manual);  // AUTO only: no auto/manual switch
  ASSERT_TRUE(options.iris.known);
  EXPECT_EQ(options.iris.min, -22.0);
  // The iris' fully open end is 0 dB whichever way the camera writes the attenuation.
  EXPECT_EQ(irisShare(options.iris, 0.0), 1.0);
  EXPECT_EQ(irisShare(options.iris, -22.0), 0.0);
  EXPECT_EQ(irisValue(options.iris, 0.25), -16.5);
  const FloatRange positive{ true, 0.0, 22.0 };
  EXPECT_EQ(irisShare(positive, 0.0), 1.0);
  EXPECT_EQ(irisValue(positive, 0.25), 16.5);
  const LensCapabilities lens = imagingLens(options, ImagingReading());
  EXPECT_FALSE(lens.focus.present);  // AUTO only and no move options: nothing to drive
  EXPECT_TRUE(lens.iris.present && lens.iris.auto_mode && lens.iris.absolute);
  EXPECT_FALSE(lens.iris.feedback);  // no settings read with an Iris
  EXPECT_NE(readImagingOptions(message.content->FirstChildElement(), options), "");
}

class OnvifLensTest : public ::testing::Test
{
protected:
  void start(const OnvifCameraEmulatorConfig& camera_config = OnvifCameraEmulatorConfig())
  {
    camera_ = std::make_unique<OnvifCameraEmulator>(camera_config);
    backend_ = makeDeviceBackend<OnvifProtocol>(configFor(*camera_));
    backend_->start();
    commander_ = std::make_unique<LensCommander>(*backend_, backend_->capabilities().lens, "onvif", 0.5);
  }
  /// Waits for a request to the Imaging service whose body has \p words; true once it came.
  bool requested(const std::string& words) const
  {
    return camera_->server().received().waitFor(
        [&](const HttpExchange& item) {
          return item.target == "/onvif/imaging_service" && item.body.find(words) != std::string::npos;
        },
        WAIT);
  }
  std::string command(const LensCommand& lens_command)
  {
    return commander_->command(lens_command, SteadyClock::now());
  }

  std::unique_ptr<OnvifCameraEmulator> camera_;
  std::unique_ptr<DeviceBackend> backend_;
  std::unique_ptr<LensCommander> commander_;
};

TEST_F(OnvifLensTest, TheLensIsDeclaredFromTheImagingServicesOptions)
{
  start();
  const LensCapabilities lens = backend_->capabilities().lens;
  EXPECT_TRUE(lens.focus.present && lens.focus.auto_mode && lens.focus.velocity && lens.focus.absolute);
  EXPECT_TRUE(lens.focus.feedback);
  EXPECT_FALSE(lens.focus.one_push);
  EXPECT_TRUE(lens.iris.present && lens.iris.auto_mode && lens.iris.absolute && lens.iris.feedback);
  EXPECT_FALSE(lens.iris.velocity);
  EXPECT_EQ(command(LensCommand::velocity(IRIS, 0.5)), "the 'onvif' device takes no iris velocity (near/far, "
                                                       "close/open drive) (the ONVIF Imaging service has no "
                                                       "iris drive (only Exposure Iris values))");
  const LensState state = backend_->lensState();
  EXPECT_EQ(state.modeOf(FOCUS), LensMode::AUTO);
  EXPECT_EQ(state.modeOf(IRIS), LensMode::AUTO);
  EXPECT_TRUE(std::isfinite(state.positionOf(FOCUS)));  // read from the Imaging GetStatus
  EXPECT_TRUE(std::isfinite(state.positionOf(IRIS)));   // and from the settings' Exposure Iris
}

TEST_F(OnvifLensTest, AFocusVelocityGoesManualFirstThenMovesAndStops)
{
  start();
  ASSERT_EQ(command(LensCommand::velocity(FOCUS, -0.4)), "");
  ASSERT_TRUE(requested("<tt:Focus><tt:AutoFocusMode>MANUAL</tt:AutoFocusMode></tt:Focus>"));
  ASSERT_TRUE(requested("<tt:Continuous><tt:Speed>-2</tt:Speed></tt:Continuous>"));  // -0.4 of the listed 5
  ASSERT_TRUE(waitUntil([&] { return camera_->lensState().modeOf(FOCUS) == LensMode::MANUAL; }, WAIT));
  const double before = camera_->lensState().positionOf(FOCUS);
  ASSERT_TRUE(waitUntil([&] { return camera_->lensState().positionOf(FOCUS) < before - 0.05; }, WAIT));
  ASSERT_EQ(command(LensCommand::velocity(FOCUS, 0.0)), "");
  ASSERT_TRUE(requested("<timg:Stop "));
  double last = -1.0;  // at rest once two readings agree (it moves by more between two while driven)
  ASSERT_TRUE(waitUntil(
      [&] {
        const double at = camera_->lensState().positionOf(FOCUS);
        const bool still = at == last;
        last = at;
        return still;
      },
      WAIT));
  const double stopped = camera_->lensState().positionOf(FOCUS);
  EXPECT_GT(stopped, 0.0);  // stopped on the way, not at the near end
  ASSERT_TRUE(waitUntil([&] { return std::abs(backend_->lensState().positionOf(FOCUS) - stopped) < 1e-3; }, WAIT));
  EXPECT_EQ(backend_->lensState().modeOf(FOCUS), LensMode::MANUAL);
  EXPECT_EQ(backend_->lensState().fault_count, 0u);
}

TEST_F(OnvifLensTest, AFocusPositionAndAutoFocusReachTheCamera)
{
  start();
  ASSERT_EQ(command(LensCommand::position(FOCUS, 0.25)), "");
  ASSERT_TRUE(requested("<tt:Absolute><tt:Position>250</tt:Position></tt:Absolute>"));  // of 0..1000
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera_->lensState().positionOf(FOCUS) - 0.25) < 1e-9; }, WAIT));
  ASSERT_TRUE(waitUntil([&] { return std::abs(backend_->lensState().positionOf(FOCUS) - 0.25) < 1e-3; }, WAIT));
  ASSERT_EQ(command(LensCommand::mode(FOCUS, true)), "");
  ASSERT_TRUE(requested("<tt:AutoFocusMode>AUTO</tt:AutoFocusMode>"));
  ASSERT_TRUE(waitUntil([&] { return camera_->lensState().modeOf(FOCUS) == LensMode::AUTO; }, WAIT));
  EXPECT_TRUE(waitUntil([&] { return backend_->lensState().modeOf(FOCUS) == LensMode::AUTO; }, WAIT));
  EXPECT_EQ(backend_->lensState().fault_count, 0u);
}

TEST_F(OnvifLensTest, AnIrisValueIsAManualExposureAndAutoIrisItsAutoMode)
{
  start();
  ASSERT_EQ(command(LensCommand::position(IRIS, 0.25)), "");
  ASSERT_TRUE(requested("<tt:Exposure><tt:Mode>MANUAL</tt:Mode><tt:Iris>-16.5</tt:Iris></tt:Exposure>"));
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera_->lensState().positionOf(IRIS) - 0.25) < 1e-9; }, WAIT));
  EXPECT_EQ(camera_->lensState().modeOf(IRIS), LensMode::MANUAL);
  ASSERT_TRUE(waitUntil([&] { return std::abs(backend_->lensState().positionOf(IRIS) - 0.25) < 1e-3; }, WAIT));
  ASSERT_EQ(command(LensCommand::mode(IRIS, true)), "");
  ASSERT_TRUE(requested("<tt:Exposure><tt:Mode>AUTO</tt:Mode></tt:Exposure>"));
  ASSERT_TRUE(waitUntil([&] { return camera_->lensState().modeOf(IRIS) == LensMode::AUTO; }, WAIT));
  EXPECT_TRUE(waitUntil([&] { return backend_->lensState().modeOf(IRIS) == LensMode::AUTO; }, WAIT));
}

TEST_F(OnvifLensTest, ARefusalIsALensFaultNotTheGoals)
{
  start();
  const std::uint64_t device_faults = backend_->sample().fault_count;
  camera_->setRefuse(true);
  ASSERT_EQ(command(LensCommand::position(IRIS, 1.0)), "");
  ASSERT_TRUE(waitUntil([&] { return backend_->lensState().fault_count == 1; }, WAIT));
  EXPECT_NE(backend_->lastLensFault().find(OnvifCameraEmulator::REFUSAL), std::string::npos)
      << backend_->lastLensFault();
  EXPECT_NE(backend_->lastLensFault().find("refused SetImagingSettings"), std::string::npos);
  EXPECT_EQ(backend_->sample().fault_count, device_faults);
}

TEST_F(OnvifLensTest, TheCameraRefusesAFocusMoveInAutoFocus)
{
  start();
  onvif_test::OnvifClient client(camera_->port());
  ASSERT_FALSE(client.call("/onvif/imaging_service", moveFocusContinuous("video_source_0", 1.0)));
  EXPECT_EQ(client.message().fault_text, "ter:ActionNotSupported: A focus Move is not possible while AutoFocusMode is "
                                         "AUTO");
  EXPECT_EQ(camera_->lensState().modeOf(FOCUS), LensMode::AUTO);
  ASSERT_FALSE(client.call("/onvif/imaging_service", setExposure("video_source_0", false, 3.0)));
  EXPECT_TRUE(faultHas(client.message(), "SettingsInvalid")) << client.message().fault_text;
  EXPECT_EQ(camera_->lensState().modeOf(IRIS), LensMode::AUTO);  // nothing changed by a refused request
}

TEST_F(OnvifLensTest, ACameraWithoutTheImagingServiceSaysItLacksFocusAndIris)
{
  OnvifCameraEmulatorConfig camera_config;
  ASSERT_TRUE(camera_config.applyMode("no-imaging"));
  start(camera_config);
  const LensCapabilities lens = backend_->capabilities().lens;
  EXPECT_FALSE(lens.focus.present);
  EXPECT_FALSE(lens.iris.present);
  EXPECT_EQ(command(LensCommand::mode(FOCUS, true)), "this ONVIF camera lists no Imaging service (GetCapabilities has "
                                                     "no Imaging XAddr)");
  EXPECT_EQ(countOf(camera_->server(), "ver20/imaging"), 0u);
}

}  // namespace
}  // namespace ptz_action_server
