/**
 * \file
 * \brief Private to the device fixtures: what the line fixtures (line_device_fixtures.cpp: FLIR, Pelco-D) and the
 * network ones (network_device_fixtures.cpp: PanTilt, DigiView), VISCA's (visca_device_fixtures.cpp), the IP cameras
 * (ip_camera_fixtures.cpp) and MAVLink's share, and their lists, which allDeviceFixtures() (device_fixtures.cpp) joins.
 */
#pragma once

#include <cstdint>
#include <vector>

#include "device_fixtures.h"
#include "ptz_action_server/core/sim_device_model.h"

namespace ptz_action_server
{
/// \p bytes as upper-case hex pairs, each followed by a space.
std::string hex(const std::vector<std::uint8_t>& bytes);

/// A path for an emulator's pseudo-terminal link, unique in this process.
std::string uniqueLink(const char* name);

/// \p commands without the state polls.
std::vector<DeviceCommand> withoutQueries(const std::vector<DeviceCommand>& commands);

/// FLIR (serial, TCP) and Pelco-D (serial in both tilt encodings, TCP).
std::vector<FixtureMaker> lineDeviceFixtures();

/// PanTilt over UDP (every wire format) and DigiView (TCP, UDP; formats 0.5 and 1.0).
std::vector<FixtureMaker> networkDeviceFixtures();

/// VISCA on a pseudo-terminal, raw over TCP, over UDP raw and with Sony's VISCA over IP header.
std::vector<FixtureMaker> viscaDeviceFixtures();
/// The MAVLink gimbal manager over UDP and a serial line.
std::vector<FixtureMaker> mavlinkDeviceFixtures();
/// The IP cameras over HTTP: Axis (VAPIX) and ONVIF, each against its emulated camera.
std::vector<FixtureMaker> ipCameraFixtures();

/// s without a state before a link is lost: generous, a busy test machine may starve the I/O threads for a while
/// (the deadline cases read it back).
constexpr double TEST_STATE_TIMEOUT = 1.0;

}  // namespace ptz_action_server
