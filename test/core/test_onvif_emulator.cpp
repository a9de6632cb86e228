/**
 * \file
 * \brief onvif_camera_emulator driven as other people's ONVIF clients drive a camera: GetServices, GetProfiles and
 * GetVideoSources to pick the profile, the PTZ configurations, presets (get, set, go to, remove), home, relative moves,
 * the status in the profile's default space and per-axis MoveStatus, the faults the specification names
 * (ter:NoPTZProfile, ter:NoProfile, ter:NoConfig, ter:NoToken), and each field mode answering as the field does.
 * Motion runs on a manual clock: a move is over when the test says so.
 */
#include <gtest/gtest.h>

#include <functional>

#include "onvif_test_client.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif;
using namespace onvif_test;

TEST(OnvifEmulatorAsACamera, AStandardClientFindsItsProfileAndRecallsAPreset)
{
  Camera camera;
  OnvifClient client(camera.emulator->port());

  // GetServices: the media, PTZ and Imaging services, with their capabilities when asked.
  ASSERT_TRUE(client.call("/onvif/device_service", getServices(true))) << client.message().fault_text;
  ServicePaths paths;
  ASSERT_EQ(readServices(client.content(), paths), "");
  EXPECT_EQ(paths.media, "/onvif/media_service");
  EXPECT_EQ(paths.ptz, "/onvif/ptz_service");
  EXPECT_EQ(paths.imaging, "/onvif/imaging_service");  // ver20/imaging: focus and iris
  const Element* ptz_capabilities = nullptr;
  for (const Element* service : children(client.content(), ns::DEVICE, "Service"))
  {
    if (text(child(service, ns::DEVICE, "Namespace")) == ns::PTZ)
    {
      ptz_capabilities = child(child(service, ns::DEVICE, "Capabilities"), ns::PTZ, "Capabilities");
    }
  }
  ASSERT_NE(ptz_capabilities, nullptr);
  EXPECT_STREQ(attribute(ptz_capabilities, "StatusPosition"), "true");
  EXPECT_STREQ(attribute(ptz_capabilities, "MoveStatus"), "true");

  // The default profile, as clients pick it: one on a video source GetVideoSources lists, with a PTZConfiguration.
  ASSERT_TRUE(client.call(paths.media, getVideoSources())) << client.message().fault_text;
  const std::vector<std::string> sources = tokensOf(client.content(), ns::MEDIA, "VideoSources");
  ASSERT_EQ(sources, std::vector<std::string>{ "video_source_0" });
  ASSERT_TRUE(client.call(paths.media, getProfiles())) << client.message().fault_text;
  std::string chosen;
  for (const Element* profile : children(client.content(), ns::MEDIA, "Profiles"))
  {
    const std::string source =
        text(path(child(profile, ns::SCHEMA, "VideoSourceConfiguration"), ns::SCHEMA, { "SourceToken" }));
    if (source == sources[0] && child(profile, ns::SCHEMA, "PTZConfiguration") != nullptr && chosen.empty())
    {
      chosen = attribute(profile, "token");
    }
  }
  ASSERT_EQ(chosen, "profile_1");

  // Its PTZ configuration names the default spaces; GetConfiguration gives the same one.
  ASSERT_TRUE(client.ptz(getConfigurations())) << client.message().fault_text;
  ASSERT_EQ(tokensOf(client.content(), ns::PTZ, "PTZConfiguration"), std::vector<std::string>{ "ptz0" });
  EXPECT_EQ(text(child(child(client.content(), ns::PTZ, "PTZConfiguration"), ns::SCHEMA,
                       "DefaultAbsolutePantTiltPositionSpace")),
            DEGREE_SPACE);
  ASSERT_TRUE(client.ptz(getConfiguration("ptz0"))) << client.message().fault_text;
  EXPECT_EQ(text(child(child(client.content(), ns::PTZ, "PTZConfiguration"), ns::SCHEMA, "NodeToken")), "node0");
  ASSERT_TRUE(client.ptz(getNodes()));
  Node node;
  ASSERT_EQ(readNode(client.content(), "node0", node), "");
  EXPECT_EQ(node.max_presets, 64);
  EXPECT_TRUE(node.home_supported);

  // Presets: none yet; one set where the camera went, recalled from elsewhere, listed, removed.
  std::vector<Preset> presets;
  ASSERT_TRUE(client.ptz(getPresets(chosen))) << client.message().fault_text;
  ASSERT_EQ(readPresets(client.content(), presets), "");
  EXPECT_TRUE(presets.empty());
  Vector door;
  door.pan_tilt = true;
  door.x = 30.0;
  door.y = -10.0;  // no space: the default one, degrees here
  door.zoom = true;
  door.z = 0.5;
  ASSERT_TRUE(client.ptz(absoluteMove(chosen, door))) << client.message().fault_text;
  camera.clock->advance(10.0);
  ASSERT_TRUE(client.ptz(setPreset(chosen, "door"))) << client.message().fault_text;
  std::string token;
  ASSERT_EQ(readPresetToken(client.content(), token), "");
  Vector away;
  away.pan_tilt = true;
  away.x = -90.0;
  ASSERT_TRUE(client.ptz(absoluteMove(chosen, away)));
  camera.clock->advance(10.0);
  EXPECT_NEAR(client.status(chosen).x, -90.0, 1e-3);
  ASSERT_TRUE(client.ptz(gotoPreset(chosen, token))) << client.message().fault_text;
  camera.clock->advance(10.0);
  const Status at_door = client.status(chosen);
  EXPECT_NEAR(at_door.x, 30.0, 1e-3);
  EXPECT_NEAR(at_door.y, -10.0, 1e-3);
  EXPECT_NEAR(at_door.zoom, 0.5, 1e-3);
  EXPECT_EQ(at_door.space, DEGREE_SPACE);
  EXPECT_EQ(at_door.move_status, "IDLE");
  ASSERT_TRUE(client.ptz(getPresets(chosen)));
  ASSERT_EQ(readPresets(client.content(), presets), "");
  ASSERT_EQ(presets.size(), 1u);
  EXPECT_EQ(presets[0].token, token);
  EXPECT_EQ(presets[0].name, "door");
  EXPECT_NEAR(presets[0].position.x, 30.0, 1e-3);
  EXPECT_FALSE(client.ptz(setPreset(chosen, "door")));  // a second preset of the same name
  EXPECT_TRUE(faultHas(client.message(), "PresetExist")) << client.message().fault_text;
  ASSERT_TRUE(client.ptz(removePreset(chosen, token)));
  EXPECT_FALSE(client.ptz(gotoPreset(chosen, token)));
  EXPECT_EQ(client.message().subcodes, (std::vector<std::string>{ "ter:InvalidArgVal", "ter:NoToken" }));
}

TEST(OnvifEmulatorAsACamera, HomeIsWhereItWasSetAndRelativeMovesGoByTheirTranslation)
{
  Camera camera;
  OnvifClient client(camera.emulator->port());
  Vector spot;
  spot.pan_tilt = true;
  spot.x = 45.0;
  spot.y = 20.0;
  ASSERT_TRUE(client.ptz(absoluteMove("profile_1", spot)));
  camera.clock->advance(10.0);
  ASSERT_TRUE(client.ptz(setHomePosition("profile_1"))) << client.message().fault_text;
  Vector translation;  // generic translation: x 0.25 is 45 degrees of pan
  translation.pan_tilt = true;
  translation.x = -0.25;
  translation.y = 0.0;
  ASSERT_TRUE(client.ptz(relativeMove("profile_1", translation))) << client.message().fault_text;
  camera.clock->advance(10.0);
  EXPECT_NEAR(client.status("profile_1").x, 0.0, 1e-3);
  ASSERT_TRUE(client.ptz(gotoHomePosition("profile_1"))) << client.message().fault_text;
  camera.clock->advance(10.0);
  const Status home = client.status("profile_1");
  EXPECT_NEAR(home.x, 45.0, 1e-3);
  EXPECT_NEAR(home.y, 20.0, 1e-3);

  Camera without_relative("no-relative");
  OnvifClient other(without_relative.emulator->port());
  EXPECT_FALSE(other.ptz(relativeMove("profile_1", translation)));
  EXPECT_EQ(other.message().fault_text, "ter:ActionNotSupported: The operation RelativeMove is not supported");
  ASSERT_TRUE(other.ptz(getNodes()));
  Node node;
  ASSERT_EQ(readNode(other.content(), "", node), "");
  EXPECT_TRUE(node.relative_pan_tilt.empty());
}

TEST(OnvifEmulatorAsACamera, PtzOnAProfileWithoutPtzIsNoPTZProfileAndUnknownTokensAreNamed)
{
  Camera camera;
  OnvifClient client(camera.emulator->port());
  EXPECT_FALSE(client.ptz(getStatus("profile_0")));
  EXPECT_EQ(client.message().fault_code, "env:Sender");
  EXPECT_EQ(client.message().subcodes, (std::vector<std::string>{ "ter:InvalidArgVal", "ter:NoPTZProfile" }));
  EXPECT_FALSE(client.ptz(gotoHomePosition("profile_0")));
  EXPECT_TRUE(faultHas(client.message(), "NoPTZProfile"));
  EXPECT_FALSE(client.ptz(getPresets("nope")));
  EXPECT_EQ(client.message().subcodes, (std::vector<std::string>{ "ter:InvalidArgVal", "ter:NoProfile" }));
  EXPECT_FALSE(client.ptz(getConfiguration("nope")));
  EXPECT_TRUE(faultHas(client.message(), "NoConfig"));
  Vector far;
  far.pan_tilt = true;
  far.x = 1.5;
  far.pan_tilt_space = GENERIC_PAN_TILT_SPACE;
  EXPECT_FALSE(client.ptz(absoluteMove("profile_1", far)));
  EXPECT_TRUE(faultHas(client.message(), "InvalidPosition")) << client.message().fault_text;
  far.x = 0.5;
  far.pan_tilt_space = "urn:vendor:PixelSpace";
  EXPECT_FALSE(client.ptz(absoluteMove("profile_1", far)));
  EXPECT_TRUE(faultHas(client.message(), "SpaceNotSupported")) << client.message().fault_text;
}

TEST(OnvifEmulatorAsACamera, TheStatusIsInTheDefaultSpaceAndAMoveWithoutASpaceGoesThere)
{
  // Degrees listed, the generic space the configuration's default (as many cameras have it).
  Camera camera("generic-status");
  OnvifClient client(camera.emulator->port());
  Vector target;
  target.pan_tilt = true;
  target.x = 0.25;  // no space: the default, generic: 45 degrees
  target.y = -0.5;
  ASSERT_TRUE(client.ptz(absoluteMove("profile_1", target))) << client.message().fault_text;
  camera.clock->advance(10.0);
  EXPECT_NEAR(camera.emulator->sample().position[PAN], M_PI / 4.0, 1e-6);
  EXPECT_NEAR(camera.emulator->sample().position[TILT], -M_PI / 4.0, 1e-6);
  const Status status = client.status("profile_1");
  EXPECT_EQ(status.space, GENERIC_PAN_TILT_SPACE);
  EXPECT_NEAR(status.x, 0.25, 1e-6);
  EXPECT_NEAR(status.y, -0.5, 1e-6);
  // A degree move is still taken: the space is listed.
  target.x = -90.0;
  target.y = 0.0;
  target.pan_tilt_space = DEGREE_SPACE;
  ASSERT_TRUE(client.ptz(absoluteMove("profile_1", target))) << client.message().fault_text;
  camera.clock->advance(10.0);
  EXPECT_NEAR(client.status("profile_1").x, -0.5, 1e-6);
}

TEST(OnvifEmulatorAsACamera, MoveStatusIsPerAxis)
{
  Camera camera;
  OnvifClient client(camera.emulator->port());
  ASSERT_TRUE(client.ptz(continuousMove("profile_1", 0.2, 0.0, false, 0.0, 10)));
  camera.clock->advance(0.5);
  Status status = client.status("profile_1");
  EXPECT_EQ(status.move_status, "MOVING");
  EXPECT_EQ(status.zoom_move_status, "IDLE");  // a pan-only move leaves the zoom idle
  Vector zoom;
  zoom.zoom = true;
  zoom.z = 1.0;
  ASSERT_TRUE(client.ptz(absoluteMove("profile_1", zoom)));
  camera.clock->advance(0.1);
  status = client.status("profile_1");
  EXPECT_EQ(status.move_status, "MOVING");  // the ContinuousMove goes on: the zoom move left it alone
  EXPECT_EQ(status.zoom_move_status, "MOVING");
  ASSERT_TRUE(client.ptz(stop("profile_1")));
  camera.clock->advance(5.0);
  status = client.status("profile_1");
  EXPECT_EQ(status.move_status, "IDLE");
  EXPECT_EQ(status.zoom_move_status, "IDLE");
}

TEST(OnvifEmulatorAsACamera, EachFieldModeAnswersAsTheFieldDoes)
{
  {
    Camera camera("no-presets");
    OnvifClient client(camera.emulator->port());
    ASSERT_TRUE(client.ptz(getNodes()));
    Node node;
    ASSERT_EQ(readNode(client.content(), "", node), "");
    EXPECT_EQ(node.max_presets, 64);  // still listed
    EXPECT_FALSE(client.ptz(getPresets("profile_1")));
    EXPECT_EQ(client.message().fault_code, "env:Receiver");
    EXPECT_EQ(client.message().subcodes, std::vector<std::string>{ "ter:ActionNotSupported" });
  }
  {
    Camera camera("continuous-only");
    OnvifClient client(camera.emulator->port());
    ASSERT_TRUE(client.ptz(getNodes()));
    Node node;
    ASSERT_EQ(readNode(client.content(), "", node), "");
    EXPECT_TRUE(node.absolute_pan_tilt.empty());
    EXPECT_TRUE(node.absolute_zoom.empty());
    EXPECT_FALSE(node.continuous_pan_tilt.empty());
    EXPECT_FALSE(client.ptz(absoluteMove("profile_1", 0.1, 0.1, GENERIC_PAN_TILT_SPACE, false, 0.0)));
    EXPECT_TRUE(faultHas(client.message(), "ActionNotSupported"));
    ASSERT_TRUE(client.ptz(continuousMove("profile_1", 0.5, 0.0, false, 0.0, 5)));
    camera.clock->advance(1.0);
    const Status status = client.status("profile_1");
    EXPECT_TRUE(status.has_pan_tilt);
    EXPECT_EQ(status.space, GENERIC_PAN_TILT_SPACE);
    EXPECT_GT(status.x, 0.0);
  }
  {
    Camera camera("no-position");
    OnvifClient client(camera.emulator->port());
    const Status status = client.status("profile_1");
    EXPECT_FALSE(status.has_pan_tilt);
    EXPECT_FALSE(status.has_zoom);
    EXPECT_EQ(status.move_status, "IDLE");
    ASSERT_TRUE(client.call("/onvif/ptz_service", "<tptz:GetServiceCapabilities/>"));
    EXPECT_STREQ(attribute(child(client.content(), ns::PTZ, "Capabilities"), "StatusPosition"), "false");
  }
  {
    Camera camera("wrong-generic-range");
    OnvifClient client(camera.emulator->port());
    ASSERT_TRUE(client.ptz(getNodes()));
    Node node;
    ASSERT_EQ(readNode(client.content(), "", node), "");
    const Space* generic = findSpace(node.absolute_pan_tilt, GENERIC_PAN_TILT_SPACE);
    ASSERT_NE(generic, nullptr);
    EXPECT_EQ(generic->x.min, 0.0);
    EXPECT_EQ(generic->x.max, 1.0);
    EXPECT_NEAR(client.status("profile_1").x, -0.864666, 1e-6);  // and it is there
  }
}

/// The host and port of an XAddr ("http://127.0.0.1:8081/onvif/ptz_service" -> "127.0.0.1:8081").
std::string hostOf(const std::string& xaddr)
{
  const std::size_t begin = xaddr.find("://") + 3;
  return xaddr.substr(begin, xaddr.find('/', begin) - begin);
}

TEST(OnvifEmulatorAsACamera, ItsXAddrsNameWhereItListensAndAWrongAddressIsStillThisMachine)
{
  for (const std::string mode : { "standard", "wrong-address" })
  {
    Camera camera(mode);
    OnvifClient client(camera.emulator->port());
    const std::string where = mode == "standard" ? "127.0.0.1" : "127.0.0.2";
    const std::string port = std::to_string(camera.emulator->port());
    // Clients that follow XAddrs (node-onvif, zeep) go where they say: never off this machine.
    ASSERT_TRUE(client.call("/onvif/device_service", getCapabilities())) << client.message().fault_text;
    const Element* capabilities = child(client.content(), ns::DEVICE, "Capabilities");
    for (const char* service : { "Device", "Media", "PTZ" })
    {
      EXPECT_EQ(hostOf(text(path(child(capabilities, ns::SCHEMA, service), ns::SCHEMA, { "XAddr" }))),
                where + ":" + port)
          << mode << " " << service;
    }
    ASSERT_TRUE(client.call("/onvif/device_service", getServices(false))) << client.message().fault_text;
    for (const Element* service : children(client.content(), ns::DEVICE, "Service"))
    {
      EXPECT_EQ(hostOf(text(child(service, ns::DEVICE, "XAddr"))), where + ":" + port) << mode;
    }
  }
}

TEST(OnvifEmulatorAsACamera, ClientsThatTakeTheFirstProfileFindPtzAndEveryVideoSourceHasAProfileWithAnEncoder)
{
  Camera camera;
  OnvifClient client(camera.emulator->port());
  ASSERT_TRUE(client.call("/onvif/media_service", getVideoSources())) << client.message().fault_text;
  const std::vector<std::string> sources = tokensOf(client.content(), ns::MEDIA, "VideoSources");
  ASSERT_EQ(sources.size(), 1u);
  ASSERT_TRUE(client.call("/onvif/media_service", getProfiles())) << client.message().fault_text;
  const std::vector<const Element*> profiles = children(client.content(), ns::MEDIA, "Profiles");
  ASSERT_EQ(profiles.size(), 2u);
  // node-onvif drives the first profile.
  EXPECT_STREQ(attribute(profiles[0], "token"), "profile_1");
  EXPECT_NE(child(profiles[0], ns::SCHEMA, "PTZConfiguration"), nullptr);
  // The npm onvif client's connect() makes a profile with a video source configuration on the source and a video
  // encoder configuration each source's default, and never completes without one (its upstart step throws inside
  // the XML parser's callback, which calls it a second time, with the error, so the count of answers it waits for
  // never comes out even).
  for (const std::string& source : sources)
  {
    bool found = false;
    for (const Element* profile : profiles)
    {
      found = found || (text(path(child(profile, ns::SCHEMA, "VideoSourceConfiguration"), ns::SCHEMA,
                                  { "SourceToken" })) == source &&
                        child(profile, ns::SCHEMA, "VideoEncoderConfiguration") != nullptr);
    }
    EXPECT_TRUE(found) << "no profile on " << source << " with a VideoEncoderConfiguration";
  }
  Camera second("ptz-profile-second");
  OnvifClient other(second.emulator->port());
  ASSERT_TRUE(other.call("/onvif/media_service", getProfiles())) << other.message().fault_text;
  EXPECT_STREQ(attribute(children(other.content(), ns::MEDIA, "Profiles")[0], "token"), "profile_0");
}

TEST(OnvifEmulatorAsACamera, EveryValidXsdDateTimeIsACreatedItTakes)
{
  Camera camera;
  // python-onvif-zeep (Home Assistant's ONVIF integration) stamps "+00:00" and microseconds; others a zone of theirs.
  const std::vector<std::function<std::string(double)>> stamps = {
    [](double utc) { return isoTime(utc).substr(0, 19) + ".123456+00:00"; },
    [](double utc) { return isoTime(utc).substr(0, 19) + "+00:00"; },
    [](double utc) { return isoTime(utc + 5.5 * 3600.0).substr(0, 19) + "+05:30"; },
    [](double utc) { return isoTime(utc - 3600.0).substr(0, 19) + "-01:00"; },
  };
  for (const auto& stamp : stamps)
  {
    OnvifClient client(camera.emulator->port(), "admin", stamp);
    EXPECT_TRUE(client.ptz(getNodes())) << stamp(0.0) << ": " << client.message().fault_text;
  }
  EXPECT_EQ(camera.emulator->refusedTokens(), 0u);
  // An hour off is still refused, however it is written.
  OnvifClient late(camera.emulator->port(), "admin",
                   [](double utc) { return isoTime(utc + 3600.0).substr(0, 19) + "+00:00"; });
  EXPECT_FALSE(late.ptz(getNodes()));
  EXPECT_TRUE(faultHas(late.message(), "NotAuthorized"));
}

}  // namespace
}  // namespace ptz_action_server
