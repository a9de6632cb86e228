/**
 * \file
 * \brief axis_camera_emulator's camera as a client without the backend sees it: the field camera's mode (no zoom
 * attributes, the field camera's keys and words) and the default camera's attributes in the documented sections.
 */
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/read_until.hpp>
#include <boost/asio/streambuf.hpp>
#include <boost/asio/write.hpp>

#include "axis_backend_test_support.h"
#include "ptz_action_server/core/axis/vapix_codec.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"

namespace ptz_action_server
{
namespace
{
using namespace axis_backend_test;

/// The body a plain GET of \p target gets from a camera without authentication on 127.0.0.1:\p port.
std::string plainGet(std::uint16_t port, const std::string& target)
{
  boost::asio::io_context context;
  boost::asio::ip::tcp::socket socket(context);
  socket.connect({ boost::asio::ip::make_address("127.0.0.1"), port });
  boost::asio::write(socket, boost::asio::buffer("GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"));
  boost::asio::streambuf buffer;
  const std::size_t header_size = boost::asio::read_until(socket, buffer, "\r\n\r\n");
  std::string text(boost::asio::buffers_begin(buffer.data()), boost::asio::buffers_end(buffer.data()));
  const std::string header = text.substr(0, header_size);
  std::size_t length = 0;
  const std::size_t at = header.find("Content-Length: ");
  if (at != std::string::npos)
  {
    length = std::stoul(header.substr(at + 16));
  }
  if (text.size() < header_size + length)
  {
    boost::asio::read(socket, buffer, boost::asio::transfer_exactly(header_size + length - text.size()));
    text.assign(boost::asio::buffers_begin(buffer.data()), boost::asio::buffers_end(buffer.data()));
  }
  return text.substr(header_size, length);
}

/// The keys of a key=value reply, in order.
std::vector<std::string> keysOf(const std::string& body)
{
  vapix::Reply reply;
  EXPECT_EQ(vapix::parseReply(body, reply), "") << body;
  std::vector<std::string> keys;
  for (const auto& value : reply.values)
  {
    keys.push_back(value.first);
  }
  return keys;
}

TEST(AxisCameraEmulator, TheFieldModeAnswersAsTheFieldCameraDid)
{
  AxisCameraEmulatorConfig config = fieldCamera("Q6155-E");
  config.http.auth = HttpAuth::NONE;
  AxisCameraEmulator camera(config);
  const std::uint16_t port = camera.port();
  const std::string ptz = "/axis-cgi/com/ptz.cgi?camera=1&";
  // info=1 lists the queries the field camera lists: no attributes.
  const std::string info = plainGet(port, ptz + "info=1");
  EXPECT_NE(info.find("\r\nquery={ speed | position | limits | presetposcam | presetposall }\r\n"), std::string::npos)
      << info;
  const vapix::CommandList commands = vapix::readCommandList(info);
  EXPECT_FALSE(commands.offers("query", "attributes"));
  EXPECT_TRUE(commands.has("continuouszoommove") && commands.has("rpan") && commands.offers("move", "home"));
  // Asking for them anyway: the camera's Error: words for an unknown query value.
  const std::string refused = plainGet(port, ptz + "query=attributes&group=zoom");
  EXPECT_EQ(refused, "Error:\r\nquery: unknown value: attributes\r\n");
  vapix::ZoomAttributes attributes;
  ASSERT_EQ(vapix::readZoomAttributes(refused, 1, attributes), "");
  EXPECT_TRUE(attributes.refused);
  // The limits give the zoom 1..9999 and the lens's other limits; the position carries the field camera's keys.
  const std::vector<std::string> limits = keysOf(plainGet(port, ptz + "query=limits"));
  EXPECT_EQ(limits,
            (std::vector<std::string>{ "MinPan", "MaxPan", "MinTilt", "MaxTilt", "MinZoom", "MaxZoom", "MinIris",
                                       "MaxIris", "MinFocus", "MaxFocus", "MinFieldAngle", "MaxFieldAngle" }));
  vapix::Reply reply;
  ASSERT_EQ(vapix::parseReply(plainGet(port, ptz + "query=limits"), reply), "");
  EXPECT_EQ(*reply.find("MinZoom"), "1");
  EXPECT_EQ(*reply.find("MaxZoom"), "9999");
  EXPECT_EQ(
      keysOf(plainGet(port, ptz + "query=position")),
      (std::vector<std::string>{ "pan", "tilt", "zoom", "iris", "focus", "brightness", "autofocus", "autoiris" }));
  // Its model, as param.cgi lists it.
  ASSERT_EQ(vapix::parseReply(plainGet(port, "/axis-cgi/param.cgi?action=list&group=root.Brand"), reply), "");
  vapix::Product product;
  ASSERT_EQ(vapix::readProduct(reply, product), "");
  EXPECT_EQ(product.number, "Q6155-E");
  EXPECT_EQ(plainGet(port, "/axis-cgi/param.cgi?action=list&group=root.Nothing"), "# Error: Error -1 getting param in "
                                                                                  "group 'root.Nothing'\r\n");
}

TEST(AxisCameraEmulator, ByDefaultItAnswersTheAttributesInTheDocumentedSections)
{
  AxisCameraEmulatorConfig config;
  config.http.auth = HttpAuth::NONE;
  AxisCameraEmulator camera(config);
  const std::string body = plainGet(camera.port(), "/axis-cgi/com/ptz.cgi?camera=1&query=attributes&group=zoom");
  EXPECT_EQ(body.rfind("Attributes for camera 1\r\nmaxOpticalZoomMag=18\r\nzoomSteps=value=1 | zoom=1,value=589 | "
                       "zoom=2,value=1177 | zoom=3,",
                       0),
            0u)
      << body;
  vapix::ZoomAttributes attributes;
  ASSERT_EQ(vapix::readZoomAttributes(body, 1, attributes), "");
  vapix::ZoomTable table;
  ASSERT_EQ(vapix::zoomTableOf(attributes, table), "");
  EXPECT_EQ(table.toText(), AxisCameraEmulatorConfig::DEFAULT_ZOOM_TABLE);
  EXPECT_NE(plainGet(camera.port(), "/axis-cgi/com/ptz.cgi?info=1").find("presetposall | attributes }"),
            std::string::npos);
}

}  // namespace
}  // namespace ptz_action_server
