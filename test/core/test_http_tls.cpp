/**
 * \file
 * \brief TLS for the IP cameras, against the emulators serving https on 127.0.0.1 with the certificate they make:
 * a pinned fingerprint, the certificate as ca_file, a wrong pin and an untrusted certificate refused with the cause
 * named (at start, at once and not at startup_timeout, for Axis and ONVIF; and later as the link-loss reason),
 * verification off with its one warning, and an https camera
 * that is never asked over plain http.
 */
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <future>

#include "startup_error.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "ptz_action_server/core/transport/http_link.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
constexpr double WAIT = 15.0;
const std::string OTHER_PIN = "00:11:22:33:44:55:66:77:88:99:AA:BB:CC:DD:EE:FF:00:11:22:33:44:55:66:77:88:99:AA:BB:CC:"
                              "DD:EE:FF";

AxisCameraEmulatorConfig tlsAxisCamera(std::uint16_t port = 0)
{
  AxisCameraEmulatorConfig camera;
  camera.http.tls = true;
  camera.http.port = port;
  return camera;
}

/// An Axis backend for the TLS camera on \p port, verification as the caller sets it.
DeviceConfig<AxisProtocol> axisConfig(std::uint16_t port)
{
  DeviceConfig<AxisProtocol> config;
  config.link.port = port;
  config.link.http.tls = true;
  config.link.http.username = "root";
  config.link.http.password = "pass";
  config.session.startup_timeout = 1.5;
  config.session.state_timeout = 1.0;
  config.link.reconnect_min = 0.05;
  config.link.reconnect_max = 0.2;
  return config;
}

/// start()'s error for \p backend, which must come within WAIT s although start-up would wait 60 s: a refused
/// certificate settles start-up at once (no deadline on the clock, only on the condition).
std::string refusedAtOnce(std::unique_ptr<DeviceBackend> backend)
{
  std::future<std::string> error = std::async(std::launch::async, [&backend] { return startupError(*backend); });
  const std::future_status status = error.wait_for(std::chrono::duration<double>(WAIT));
  EXPECT_EQ(status, std::future_status::ready) << "start-up waits for startup_timeout after a refused certificate";
  return error.get();
}

/// axisConfig() with a start-up time no test waits for.
DeviceConfig<AxisProtocol> patientAxisConfig(std::uint16_t port)
{
  DeviceConfig<AxisProtocol> config = axisConfig(port);
  config.session.startup_timeout = 60.0;
  return config;
}

/// Goes to a position and waits until the backend reports it.
bool reaches(DeviceBackend& backend, double pan)
{
  backend.goTo({ pan, 0.1, 2.0 });
  return waitUntil([&] { return std::abs(backend.sample().position[PAN] - pan) < 0.01; }, WAIT);
}

std::size_t moves(HttpCameraServer& server)
{
  const auto& items = server.received().items();
  return static_cast<std::size_t>(std::count_if(items.begin(), items.end(), [](const HttpExchange& exchange) {
    return exchange.target.find("&pan=") != std::string::npos;
  }));
}

/// A file removed at the end of the test.
struct TemporaryFile
{
  std::string path = "/tmp/ptz_tls_test_" + std::to_string(::getpid()) + ".pem";
  ~TemporaryFile()
  {
    std::remove(path.c_str());
  }
};

TEST(CertificateFingerprint, TakesTheUsualFormsAndNothingElse)
{
  const std::string hex = "ab01cd23ef45ab01cd23ef45ab01cd23ef45ab01cd23ef45ab01cd23ef45ab01";
  const std::string colons = formatCertificateFingerprint(hex);
  EXPECT_EQ(colons, "AB:01:CD:23:EF:45:AB:01:CD:23:EF:45:AB:01:CD:23:EF:45:AB:01:CD:23:EF:45:AB:01:CD:23:EF:45:AB:01");
  EXPECT_EQ(parseCertificateFingerprint(colons), hex);
  EXPECT_EQ(parseCertificateFingerprint(hex), hex);
  std::string lower_colons = colons;
  std::transform(lower_colons.begin(), lower_colons.end(), lower_colons.begin(), ::tolower);
  EXPECT_EQ(parseCertificateFingerprint(" " + lower_colons + " "), hex);
  EXPECT_EQ(parseCertificateFingerprint(hex.substr(2)), "");      // a byte short
  EXPECT_EQ(parseCertificateFingerprint(hex + "ab"), "");         // SHA-1 or SHA-512 sizes are not SHA-256
  EXPECT_EQ(parseCertificateFingerprint("SHA256:" + hex), "");    // letters that are not hex
  EXPECT_EQ(parseCertificateFingerprint(hex.substr(0, 40)), "");  // a SHA-1
}

TEST(HttpTls, TheEmulatorMakesACertificateAndCountsPlainHttpSentToIt)
{
  AxisCameraEmulator camera(tlsAxisCamera());
  EXPECT_EQ(camera.server().url(), "https://127.0.0.1:" + std::to_string(camera.port()));
  EXPECT_FALSE(parseCertificateFingerprint(camera.server().fingerprint()).empty()) << camera.server().fingerprint();
  EXPECT_EQ(camera.server().certificatePem().rfind("-----BEGIN CERTIFICATE-----", 0), 0u);

  // A plain-http client (tls off) is answered 400 and counted, never served: the counter the tests below read
  // to see that no request went out over plain http.
  DeviceConfig<AxisProtocol> config = axisConfig(camera.port());
  config.link.http.tls = false;
  const std::string error = startupError(*makeDeviceBackend<AxisProtocol>(config));
  EXPECT_NE(error.find("HTTP 400"), std::string::npos) << error;
  EXPECT_GE(camera.server().counters().plain_requests.value(), 1u);
  EXPECT_EQ(camera.server().counters().requests.value(), 0u);
}

TEST(HttpTls, APinnedFingerprintReachesTheCameraOverTls)
{
  AxisCameraEmulator camera(tlsAxisCamera());
  DeviceConfig<AxisProtocol> config = axisConfig(camera.port());
  // As a user copies it from a browser, in lower case without colons: the same pin.
  config.link.http.fingerprint = parseCertificateFingerprint(camera.server().fingerprint());
  std::unique_ptr<DeviceBackend> backend = makeDeviceBackend<AxisProtocol>(config);
  backend->start();
  EXPECT_TRUE(backend->takeWarnings().empty());
  ASSERT_TRUE(reaches(*backend, 0.3));
  EXPECT_EQ(moves(camera.server()), 1u);
  EXPECT_NEAR(camera.sample().position[PAN], 0.3, 0.01);
  EXPECT_GE(camera.server().counters().tls_handshakes.value(), 1u);
  EXPECT_EQ(camera.server().counters().tls_failures.value(), 0u);
  EXPECT_EQ(camera.server().counters().plain_requests.value(), 0u);
}

TEST(HttpTls, TheCertificateAsCaFileIsTrustedByAnOnvifBackend)
{
  OnvifCameraEmulatorConfig camera_config;
  camera_config.http.tls = true;
  OnvifCameraEmulator camera(camera_config);
  TemporaryFile ca_file;
  camera.server().writeCertificate(ca_file.path);

  DeviceConfig<OnvifProtocol> config;
  config.link.port = camera.port();
  config.link.http.tls = true;
  config.link.http.ca_file = ca_file.path;  // the chain and the name (127.0.0.1) are checked against it
  config.settings.username = camera_config.username;
  config.settings.password = camera_config.password;
  config.session.startup_timeout = 5.0;
  config.session.state_timeout = 1.0;
  std::unique_ptr<DeviceBackend> backend = makeDeviceBackend<OnvifProtocol>(config);
  backend->start();
  EXPECT_TRUE(backend->takeWarnings().empty());
  ASSERT_TRUE(reaches(*backend, -0.2));
  EXPECT_NEAR(camera.sample().position[PAN], -0.2, 0.01);
  EXPECT_EQ(camera.server().counters().plain_requests.value(), 0u);
}

TEST(HttpTls, AWrongPinIsRefusedNamingBothFingerprintsAndNothingGoesOutInPlain)
{
  AxisCameraEmulator camera(tlsAxisCamera());
  DeviceConfig<AxisProtocol> config = patientAxisConfig(camera.port());
  config.link.http.fingerprint = parseCertificateFingerprint(OTHER_PIN);
  const std::string error = refusedAtOnce(makeDeviceBackend<AxisProtocol>(config));
  EXPECT_NE(error.find("https://127.0.0.1:" + std::to_string(camera.port()) + ": GET /axis-cgi/"), std::string::npos)
      << error;
  EXPECT_NE(error.find("TLS refused: the camera's certificate has SHA-256 " + camera.server().fingerprint() +
                       ", not the pinned tls_fingerprint " + OTHER_PIN),
            std::string::npos)
      << error;
  // The attempt was over TLS and refused; no request reached the camera, none in plain.
  EXPECT_TRUE(waitUntil([&] { return camera.server().counters().tls_failures.value() >= 1; }, WAIT));
  EXPECT_EQ(camera.server().counters().tls_handshakes.value(), 0u);
  EXPECT_EQ(camera.server().counters().requests.value(), 0u);
  EXPECT_EQ(camera.server().counters().plain_requests.value(), 0u);
}

TEST(HttpTls, AnUntrustedCertificateIsRefusedWithWhatToDo)
{
  AxisCameraEmulator camera(tlsAxisCamera());
  const std::string error =
      refusedAtOnce(makeDeviceBackend<AxisProtocol>(patientAxisConfig(camera.port())));  // the system's CAs
  EXPECT_NE(error.find("TLS refused: the camera's certificate is not trusted by the system's CAs ("), std::string::npos)
      << error;
  EXPECT_NE(error.find("give its CA in ca_file, or pin its SHA-256 in tls_fingerprint"), std::string::npos) << error;
  EXPECT_TRUE(waitUntil([&] { return camera.server().counters().tls_failures.value() >= 1; }, WAIT));
  EXPECT_EQ(camera.server().counters().requests.value(), 0u);
  EXPECT_EQ(camera.server().counters().plain_requests.value(), 0u);

  // Another camera's certificate as ca_file does not make this one trusted.
  AxisCameraEmulator other(tlsAxisCamera());
  TemporaryFile ca_file;
  other.server().writeCertificate(ca_file.path);
  DeviceConfig<AxisProtocol> config = patientAxisConfig(camera.port());
  config.link.http.ca_file = ca_file.path;
  const std::string with_ca = refusedAtOnce(makeDeviceBackend<AxisProtocol>(config));
  EXPECT_NE(with_ca.find("not trusted by ca_file " + ca_file.path), std::string::npos) << with_ca;
  EXPECT_EQ(camera.server().counters().requests.value(), 0u);
}

TEST(HttpTls, AnOnvifCameraWithAnotherCertificateThanThePinnedOneFailsStartUpAtOnce)
{
  OnvifCameraEmulatorConfig camera_config;
  camera_config.http.tls = true;
  OnvifCameraEmulator camera(camera_config);
  DeviceConfig<OnvifProtocol> config;
  config.link.port = camera.port();
  config.link.http.tls = true;
  config.link.http.fingerprint = parseCertificateFingerprint(OTHER_PIN);
  config.settings.username = camera_config.username;
  config.settings.password = camera_config.password;
  config.session.startup_timeout = 60.0;
  const std::string error = refusedAtOnce(makeDeviceBackend<OnvifProtocol>(config));
  EXPECT_NE(error.find("TLS refused: the camera's certificate has SHA-256 " + camera.server().fingerprint() +
                       ", not the pinned tls_fingerprint " + OTHER_PIN),
            std::string::npos)
      << error;
  EXPECT_EQ(camera.server().counters().requests.value(), 0u);
  EXPECT_EQ(camera.server().counters().plain_requests.value(), 0u);
}

TEST(HttpTls, VerificationOffWorksAndWarnsOnce)
{
  AxisCameraEmulator camera(tlsAxisCamera());
  DeviceConfig<AxisProtocol> config = axisConfig(camera.port());
  config.link.http.verify_peer = false;
  std::unique_ptr<DeviceBackend> backend = makeDeviceBackend<AxisProtocol>(config);
  backend->start();
  ASSERT_TRUE(reaches(*backend, 0.2));
  // The link is lost and comes back (a new connection, a new handshake): still the one warning.
  camera.server().dropConnections();
  camera.server().setListening(false);
  ASSERT_TRUE(waitUntil([&] { return !backend->sample().link_up; }, WAIT));
  camera.server().setListening(true);
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
  ASSERT_TRUE(reaches(*backend, -0.1));
  std::vector<std::string> warnings = backend->takeWarnings();
  for (const std::string& more : backend->takeWarnings())
  {
    warnings.push_back(more);
  }
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind("TLS certificate verification is off (tls_verify: false) for https://127.0.0.1:", 0), 0u)
      << warnings[0];
  EXPECT_GE(camera.server().counters().tls_handshakes.value(), 2u);
  EXPECT_EQ(camera.server().counters().plain_requests.value(), 0u);
}

TEST(HttpTls, ACertificateThatChangesLaterLosesTheLinkWithTheReasonAndNeverFallsBackToPlain)
{
  AxisCameraEmulator camera(tlsAxisCamera());
  DeviceConfig<AxisProtocol> config = axisConfig(camera.port());
  config.link.http.fingerprint = parseCertificateFingerprint(camera.server().fingerprint());
  std::unique_ptr<DeviceBackend> backend = makeDeviceBackend<AxisProtocol>(config);
  backend->start();
  ASSERT_TRUE(reaches(*backend, 0.1));
  const std::uint64_t requests = camera.server().counters().requests.value();

  // The camera's address answers with another certificate now (a reset camera, or someone in between).
  camera.server().renewCertificate();
  ASSERT_TRUE(waitUntil([&] { return camera.server().counters().tls_failures.value() >= 3; }, WAIT));
  EXPECT_FALSE(backend->sample().link_up);
  EXPECT_EQ(backend->sample().link_losses, 1u);
  const std::string loss = backend->lastLinkLoss();
  EXPECT_NE(loss.find("TLS refused: the camera's certificate has SHA-256 " + camera.server().fingerprint() +
                      ", not the pinned tls_fingerprint "),
            std::string::npos)
      << loss;
  EXPECT_EQ(camera.server().counters().requests.value(), requests);  // nothing served since
  EXPECT_EQ(camera.server().counters().plain_requests.value(), 0u);
}

}  // namespace
}  // namespace ptz_action_server
