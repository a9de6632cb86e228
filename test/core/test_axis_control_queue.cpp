/**
 * \file
 * \brief The Axis backend and a camera whose PTZ control is queued (VAPIX Queuing API, `CtlQueueing=true`), against
 * axis_camera_emulator's control_queue mode: control asked for and kept (its cookie, its renewals), a command another
 * client holds control for fails naming the queue, control dropped at shutdown; and the queue's replies read as the
 * VAPIX documentation gives them.
 */
#include <gtest/gtest.h>

#include <cmath>

#include "diagnostic_value.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/core/axis/vapix_queue.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
constexpr double WAIT = 15.0;

DeviceConfig<AxisProtocol> configFor(std::uint16_t port)
{
  DeviceConfig<AxisProtocol> config;
  config.link.port = port;
  config.link.http.username = "root";
  config.link.http.password = "pass";
  config.session.startup_timeout = 5.0;
  return config;
}

AxisCameraEmulatorConfig queueingCamera()
{
  AxisCameraEmulatorConfig camera;
  camera.control_queue = true;
  camera.control_time = 2.0;  // short, so that the test sees control kept past it
  camera.queue_period = 1.0;
  return camera;
}

std::size_t countOf(HttpCameraServer& server, const std::string& containing)
{
  std::size_t count = 0;
  for (const HttpExchange& exchange : server.received().items())
  {
    count += exchange.target.find(containing) != std::string::npos ? 1 : 0;
  }
  return count;
}

TEST(VapixQueue, ReadsTheAnswersAndParametersAsTheDocumentationGivesThem)
{
  vapix::QueueStatus status;
  // The VAPIX documentation's example: queue position 3, 410 s to control, ask again in 5 s.
  EXPECT_EQ(vapix::readQueueStatus("<a name=\"3\"></a><a name=\"410\"></a><a name=\"5\"></a>", status), "");
  EXPECT_EQ(status.position, 3);
  EXPECT_EQ(status.seconds, 410.0);
  EXPECT_EQ(status.period, 5.0);
  // Its syntax line, as printed (`<a name="<pos>"</a>`), and an estimate that cannot be made (-1).
  EXPECT_EQ(vapix::readQueueStatus("<a name=\"1\"</a><a name=\"-1\"</a><a name=\"5\"></a>\r\n", status), "");
  EXPECT_EQ(status.position, 1);
  EXPECT_EQ(status.seconds, -1.0);
  EXPECT_EQ(vapix::readQueueStatus("Error:\r\nPTZ control queueing is not enabled\r\n", status), "the camera refused: "
                                                                                                 "PTZ control queueing "
                                                                                                 "is not enabled");
  EXPECT_EQ(status.position, 0);
  EXPECT_NE(vapix::readQueueStatus("<a name=\"x\"></a>", status), "");
  EXPECT_NE(vapix::readQueueStatus("", status), "");

  vapix::QueueSettings settings;
  EXPECT_EQ(vapix::queueParametersPath(2), "/axis-cgi/param.cgi?action=list&group=root.PTZ.Various.V2");
  // Parameters as param.cgi lists them on a field camera (Home Assistant's recorded M1054 and Q-series answers).
  EXPECT_EQ(vapix::readQueueSettings("root.PTZ.Various.V1.CtlQueueing=false\r\nroot.PTZ.Various.V1.CtlQueueLimit=20\r\n"
                                     "root.PTZ.Various.V1.CtlQueuePollTime=20\r\n",
                                     1, settings),
            "");
  EXPECT_FALSE(settings.queueing);
  EXPECT_EQ(settings.poll_time, 20.0);
  EXPECT_EQ(vapix::readQueueSettings("root.PTZ.Various.V2.CtlQueueing=true\r\n", 2, settings), "");
  EXPECT_TRUE(settings.queueing);
  EXPECT_EQ(vapix::readQueueSettings("# Error: Error -1 getting param in group 'root.PTZ.Various.V1'\r\n", 1, settings),
            "no CtlQueueing parameter (# Error: Error -1 getting param in group 'root.PTZ.Various.V1')");
  EXPECT_NE(vapix::readQueueSettings("root.PTZ.Various.V1.CtlQueueing=maybe\r\n", 1, settings), "");
}

TEST(AxisBackendControlQueue, AsksForControlKeepsItAndDropsIt)
{
  AxisCameraEmulator camera(queueingCamera());
  auto backend = makeDeviceBackend<AxisProtocol>(configFor(camera.port()));
  backend->start();
  EXPECT_EQ(diagnosticValue(*backend, "PTZ control queue").rfind("on: control is ours", 0), 0u)
      << diagnosticValue(*backend, "PTZ"
                                   " co"
                                   "ntr"
                                   "ol "
                                   "que"
                                   "u"
                                   "e");
  const std::string ours = camera.controlHolder();
  EXPECT_EQ(ours.rfind("client", 0), 0u) << ours;  // the cookie it was given, sent back

  // A goal moves the camera (a client without control would see it take the command and stay).
  backend->goTo({ 0.3, 0.1, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera.sample().position[PAN] - 0.3) < 1e-3; }, WAIT))
      << camera.sample().position[PAN] << ", holder " << camera.controlHolder() << ", fault " << backend->lastFault()
      << ", queue " << diagnosticValue(*backend, "PTZ control queue");

  // Kept past the camera's 2 s of control without a move: renewed while the backend only polls.
  const std::size_t requests = countOf(camera.server(), "control=request");
  ASSERT_TRUE(waitUntil([&] { return countOf(camera.server(), "control=request") >= requests + 4; }, WAIT));
  EXPECT_EQ(camera.controlHolder(), ours);
  backend->goTo({ -0.3, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera.sample().position[PAN] + 0.3) < 1e-3; }, WAIT));
  EXPECT_EQ(backend->sample().fault_count, 0u);

  backend->stop();
  backend.reset();
  EXPECT_EQ(countOf(camera.server(), "control=drop"), 1u);
  EXPECT_EQ(camera.controlHolder(), "");
}

TEST(AxisBackendControlQueue, ACommandAnotherClientHoldsControlForFailsNamingTheQueue)
{
  AxisCameraEmulator camera(queueingCamera());
  camera.holdControlElsewhere(-1.0);  // a client with infinite control (a guard tour)
  auto backend = makeDeviceBackend<AxisProtocol>(configFor(camera.port()));
  backend->start();  // the state is read all the same
  const std::vector<std::string> warnings = backend->takeWarnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "PTZ control is queued on this Axis camera (CtlQueueing) and another client holds it: we are "
                         "number 2 in its queue, with no end in sight (a client with infinite control): goals fail "
                         "until control is ours");
  backend->goTo({ 0.3, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return backend->sample().fault_count > 0; }, WAIT));
  EXPECT_EQ(backend->lastFault(), "PTZ control is queued on this Axis camera (CtlQueueing) and another client holds "
                                  "it: we are number 2 in its queue, with no end in sight (a client with infinite "
                                  "control)");
  EXPECT_EQ(countOf(camera.server(), "&pan="), 0u);

  // Control free again: the next goal takes it and moves.
  camera.holdControlElsewhere(0.0);
  backend->goTo({ 0.3, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera.sample().position[PAN] - 0.3) < 1e-3; }, WAIT));
}

TEST(AxisBackendControlQueue, ACameraWithoutQueueingIsAskedNothingAndTheSettingWins)
{
  AxisCameraEmulator plain{ AxisCameraEmulatorConfig() };
  auto backend = makeDeviceBackend<AxisProtocol>(configFor(plain.port()));
  backend->start();
  EXPECT_EQ(diagnosticValue(*backend, "PTZ control queue"), "off (CtlQueueing=false)");
  backend->goTo({ 0.2, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(plain.sample().position[PAN] - 0.2) < 1e-3; }, WAIT));
  EXPECT_EQ(countOf(plain.server(), "ptzqueue.cgi"), 0u);

  // control_queue: on asks whatever the parameters say (a user who may not read them).
  AxisCameraEmulator queueing(queueingCamera());
  DeviceConfig<AxisProtocol> config = configFor(queueing.port());
  config.settings.control_queue = AxisControlQueue::ON;
  backend = makeDeviceBackend<AxisProtocol>(config);
  backend->start();
  EXPECT_EQ(countOf(queueing.server(), "param.cgi"), 0u);
  backend->goTo({ 0.2, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(queueing.sample().position[PAN] - 0.2) < 1e-3; }, WAIT));
}

}  // namespace
}  // namespace ptz_action_server
