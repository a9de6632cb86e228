#include <gtest/gtest.h>

#include "ptz_action_server/core/units.h"
#include "ptz_action_server/core/visca/visca_codec.h"
#include "ptz_action_server/core/visca/visca_model.h"

namespace ptz_action_server
{
namespace
{
using visca::Packet;

visca::ViscaModel model(const char* name)
{
  visca::ViscaModel chosen;
  EXPECT_TRUE(visca::ViscaModel::preset(name, chosen)) << name;
  return chosen;
}

// ---------------------------------------------------------------- golden packets of protocols.md section 8

TEST(ViscaCodec, StartUpBroadcastsAreTheGoldens)
{
  EXPECT_EQ(visca::toHex(visca::addressSet()), "88 30 01 FF");
  EXPECT_EQ(visca::toHex(visca::ifClear()), "88 01 00 01 FF");
  EXPECT_EQ(visca::toHex(visca::sequenceReset(0)), "02 00 00 01 00 00 00 00 01");
}

TEST(ViscaCodec, TheOverIpExampleIsPan45Tilt10AtPtzOpticsUnits)
{
  const visca::ViscaModel ptzoptics = model("ptzoptics");
  const Packet command = visca::panTiltPosition(1, 0x18, 0x14, ptzoptics.toSteps(PAN, toRadians(45.0)),
                                                ptzoptics.toSteps(TILT, toRadians(10.0)));
  EXPECT_EQ(visca::toHex(command), "81 01 06 02 18 14 00 02 08 08 00 00 09 00 FF");
  EXPECT_EQ(visca::toHex(visca::encodeIp({ visca::IP_COMMAND, 1, command })), "01 00 00 0F 00 00 00 01 81 01 06 02 18 "
                                                                              "14 00 02 08 08 00 00 09 00 FF");

  const Packet datagram = visca::encodeIp({ visca::IP_COMMAND, 1, command });
  visca::IpMessage message;
  ASSERT_EQ(visca::decodeIp(datagram.data(), datagram.size(), message), visca::IpError::NONE);
  EXPECT_EQ(message.type, visca::IP_COMMAND);
  EXPECT_EQ(message.sequence, 1u);
  EXPECT_EQ(message.payload, command);
}

TEST(ViscaCodec, CommandsAndInquiriesAreThePublishedLayouts)
{
  EXPECT_EQ(visca::toHex(visca::panTiltDrive(1, 0x10, 0x08, 0, 0)), "81 01 06 01 10 08 03 03 FF");
  EXPECT_EQ(visca::toHex(visca::panTiltDrive(1, 0x10, 0x08, 1, 1)), "81 01 06 01 10 08 02 01 FF");    // right, up
  EXPECT_EQ(visca::toHex(visca::panTiltDrive(3, 0x01, 0x14, -1, -1)), "83 01 06 01 01 14 01 02 FF");  // left, down
  EXPECT_EQ(visca::toHex(visca::panTiltPosition(1, 0x18, 0x14, -1, -400)), "81 01 06 02 18 14 0F 0F 0F 0F 0F 0E 07 00 "
                                                                           "FF");
  EXPECT_EQ(visca::toHex(visca::panTiltPosition(1, 0x01, 0x01, 16, 0, visca::PositionLayout(), true)), "81 01 06 03 01 "
                                                                                                       "01 00 00 01 00 "
                                                                                                       "00 00 00 "
                                                                                                       "00 FF");
  EXPECT_EQ(visca::toHex(visca::panTiltHome(1)), "81 01 06 04 FF");
  EXPECT_EQ(visca::toHex(visca::panTiltInquiry(1)), "81 09 06 12 FF");
  EXPECT_EQ(visca::toHex(visca::zoomStop(1)), "81 01 04 07 00 FF");
  EXPECT_EQ(visca::toHex(visca::zoomDrive(1, 8)), "81 01 04 07 27 FF");
  EXPECT_EQ(visca::toHex(visca::zoomDrive(1, -1)), "81 01 04 07 30 FF");
  EXPECT_EQ(visca::toHex(visca::zoomDrive(1, 0)), "81 01 04 07 00 FF");
  EXPECT_EQ(visca::toHex(visca::zoomDirect(1, 0x4000)), "81 01 04 47 04 00 00 00 FF");
  EXPECT_EQ(visca::toHex(visca::zoomInquiry(1)), "81 09 04 47 FF");
  EXPECT_EQ(visca::toHex(visca::cancel(1, 2)), "81 22 FF");
}

TEST(ViscaCodec, RepliesAreClassifiedWithTheirSocketsAndErrorNames)
{
  using Kind = visca::Reply::Kind;
  const visca::Reply ack = visca::classify({ 0x90, 0x41, 0xFF });
  EXPECT_EQ(ack.kind, Kind::ACK);
  EXPECT_EQ(ack.address, 1);
  EXPECT_EQ(ack.socket, 1);
  EXPECT_EQ(visca::classify({ 0xA0, 0x52, 0xFF }).kind, Kind::COMPLETION);
  EXPECT_EQ(visca::classify({ 0xA0, 0x52, 0xFF }).address, 2);
  EXPECT_EQ(visca::classify({ 0x90, 0x38, 0xFF }).kind, Kind::NETWORK_CHANGE);
  EXPECT_EQ(visca::classify({ 0x88, 0x30, 0x02, 0xFF }).kind, Kind::ADDRESS_SET);
  EXPECT_EQ(visca::classify({ 0x88, 0x01, 0x00, 0x01, 0xFF }).kind, Kind::IF_CLEAR);
  EXPECT_EQ(visca::classify({ 0x81, 0x01, 0x06, 0x04, 0xFF }).kind, Kind::OTHER);  // a command, not a reply

  const std::vector<std::pair<Packet, std::string>> errors = {
    { { 0x90, 0x60, 0x01, 0xFF }, "message length error" },
    { { 0x90, 0x60, 0x02, 0xFF }, "syntax error" },
    { { 0x90, 0x60, 0x03, 0xFF }, "command buffer full" },
    { { 0x90, 0x61, 0x04, 0xFF }, "command cancelled" },
    { { 0x90, 0x62, 0x05, 0xFF }, "no socket" },
    { { 0x90, 0x62, 0x41, 0xFF }, "command not executable" },
    { { 0x90, 0x60, 0x42, 0xFF }, "error 0x42" },
  };
  for (const auto& [packet, name] : errors)
  {
    const visca::Reply reply = visca::classify(packet);
    EXPECT_EQ(reply.kind, Kind::ERROR) << visca::toHex(packet);
    EXPECT_EQ(reply.socket, packet[1] & 0x0F);
    EXPECT_EQ(visca::errorName(reply.error), name);
  }

  std::int32_t pan = 0;
  std::int32_t tilt = 0;
  const visca::PositionLayout four_four;
  const visca::Reply position = visca::classify({ 0x90, 0x50, 0x0F, 0x07, 0x02, 0x05, 0x00, 0x04, 0x0B, 0x00, 0xFF });
  ASSERT_TRUE(visca::decodePanTiltAnswer(position, four_four, pan, tilt));
  EXPECT_EQ(pan, -2267);  // F725h: -170 degrees on an EVI-D70
  EXPECT_EQ(tilt, 1200);  // 04B0h: +90
  std::uint16_t zoom = 0;
  ASSERT_TRUE(visca::decodeZoomAnswer(visca::classify({ 0x90, 0x50, 0x04, 0x00, 0x00, 0x00, 0xFF }), zoom));
  EXPECT_EQ(zoom, 0x4000);
  EXPECT_FALSE(visca::decodeZoomAnswer(position, zoom));
  EXPECT_FALSE(
      visca::decodePanTiltAnswer(visca::classify({ 0x90, 0x50, 0x04, 0x00, 0x00, 0x00, 0xFF }), four_four, pan, tilt));
}

// ---------------------------------------------------------------- units of each model

TEST(ViscaModel, PresetsMatchTheManualsRanges)
{
  const visca::ViscaModel d70 = model("evi_d70");
  EXPECT_EQ(static_cast<std::uint16_t>(d70.toSteps(PAN, toRadians(-170.0))), 0xF725);
  EXPECT_EQ(static_cast<std::uint16_t>(d70.toSteps(PAN, toRadians(170.0))), 0x08DB);
  EXPECT_EQ(static_cast<std::uint16_t>(d70.toSteps(TILT, toRadians(-30.0))), 0xFE70);
  EXPECT_EQ(static_cast<std::uint16_t>(d70.toSteps(TILT, toRadians(90.0))), 0x04B0);
  const visca::ViscaModel d30 = model("evi_d30");
  EXPECT_EQ(static_cast<std::uint16_t>(d30.toSteps(PAN, toRadians(-100.0))), 0xFC90);
  EXPECT_EQ(static_cast<std::uint16_t>(d30.toSteps(PAN, toRadians(100.0))), 0x0370);
  EXPECT_EQ(static_cast<std::uint16_t>(d30.toSteps(TILT, toRadians(-25.0))), 0xFED4);
  EXPECT_EQ(static_cast<std::uint16_t>(d30.toSteps(TILT, toRadians(25.0))), 0x012C);
  EXPECT_DOUBLE_EQ(model("ptzoptics").axes[PAN].steps_per_degree, 14.4);
  visca::ViscaModel unknown;
  EXPECT_FALSE(visca::ViscaModel::preset("evi_d99", unknown));
  for (const std::string& name : visca::ViscaModel::presets())
  {
    EXPECT_EQ(model(name.c_str()).check(), "") << name;
  }
}

// ---------------------------------------------------------------- Sony's current models, from their command tables

TEST(ViscaModel, TheBrcX1000SendsPanAsFiveNibblesAndTiltAsFour)
{
  // BRC-X1000/H800 command list: `8x 01 06 02 vv ww 0p 0p 0p 0p 0p 0t 0t 0t 0t FF`; 10 degrees is 00937h, listed
  // under "Left", 10 degrees right FF6C9h; tilt up 90 is 52EFh, down 30 E45Bh.
  for (const char* name : { "brc_x1000", "brc_h800" })
  {
    const visca::ViscaModel x1000 = model(name);
    EXPECT_EQ(x1000.toSteps(PAN, toRadians(-10.0)), 0x00937) << name;
    EXPECT_EQ(x1000.toSteps(PAN, toRadians(170.0)) & 0xFFFFF, 0xF6359) << name;
    EXPECT_EQ(x1000.toSteps(TILT, toRadians(90.0)), 0x52EF) << name;
    EXPECT_EQ(x1000.toSteps(TILT, toRadians(-30.0)) & 0xFFFF, 0xE45B) << name;
    const Packet command = visca::panTiltPosition(1, 0x18, 0x18, x1000.toSteps(PAN, toRadians(-10.0)),
                                                  x1000.toSteps(TILT, toRadians(90.0)), x1000.layout);
    EXPECT_EQ(visca::toHex(command), "81 01 06 02 18 18 00 00 09 03 07 05 02 0E 0F FF") << name;
    // The position inquiry's answer: 12 bytes, pan F6359h (170 right), tilt 52EFh.
    std::int32_t pan = 0;
    std::int32_t tilt = 0;
    const visca::Reply answer =
        visca::classify({ 0x90, 0x50, 0x0F, 0x06, 0x03, 0x05, 0x09, 0x05, 0x02, 0x0E, 0x0F, 0xFF });
    ASSERT_TRUE(visca::decodePanTiltAnswer(answer, x1000.layout, pan, tilt)) << name;
    EXPECT_NEAR(toDegrees(x1000.fromSteps(PAN, pan)), 170.0, 0.01);
    EXPECT_NEAR(toDegrees(x1000.fromSteps(TILT, tilt)), 90.0, 0.01);
    EXPECT_FALSE(visca::decodePanTiltAnswer(answer, visca::PositionLayout(), pan, tilt)) << "read as 4 + 4 nibbles";
    EXPECT_EQ(x1000.zoomToPosition(2.0), 0x1800);
    EXPECT_EQ(x1000.zoomToPosition(12.0), 0x4000);
  }
  EXPECT_EQ(model("brc_x1000").model_id, 0x0519);
  EXPECT_EQ(model("brc_h800").model_id, 0x051A);
}

TEST(ViscaModel, TheFr7Am7And360sheSendFiveAndFiveNibbles)
{
  // ILME-FR7: pan F6359h (-170)..09CA7h (+170), tilt FE45Bh (-30)..0B3B0h (+195).
  const visca::ViscaModel fr7 = model("ilme_fr7");
  EXPECT_EQ(fr7.toSteps(PAN, toRadians(-170.0)) & 0xFFFFF, 0xF6359);
  EXPECT_NEAR(fr7.toSteps(TILT, toRadians(195.0)), 0x0B3B0, 1);  // the table rounds 235.9 x 195 down
  EXPECT_EQ(fr7.toSteps(TILT, toRadians(-30.0)) & 0xFFFFF, 0xFE45B);
  // BRC-AM7: pan D5468h (-175)..2AB98h (+175), tilt F8AD0h (-30)..33450h (+210).
  const visca::ViscaModel am7 = model("brc_am7");
  EXPECT_EQ(am7.toSteps(PAN, toRadians(175.0)), 0x2AB98);
  EXPECT_EQ(am7.toSteps(PAN, toRadians(-175.0)) & 0xFFFFF, 0xD5468);
  EXPECT_EQ(am7.toSteps(TILT, toRadians(210.0)), 0x33450);
  // SRG-360SHE: pan EAC00h (-170)..15400h (+170), tilt FC400h (-30)..0B400h (+90); one speed: `VV 00`.
  const visca::ViscaModel she = model("srg_360she");
  EXPECT_EQ(she.toSteps(PAN, toRadians(170.0)), 0x15400);
  EXPECT_EQ(she.toSteps(TILT, toRadians(-30.0)) & 0xFFFFF, 0xFC400);
  EXPECT_EQ(visca::toHex(visca::panTiltPosition(1, 0x18, 0x18, she.toSteps(PAN, toRadians(170.0)),
                                                she.toSteps(TILT, toRadians(90.0)), she.layout)),
            "81 01 06 02 18 00 01 05 04 00 00 00 0B 04 00 00 FF");
  EXPECT_EQ(she.zoomToPosition(10.0), 0x3486);
  // That command is 17 bytes, one more than VISCA's 16: read whole, where 18 are not.
  const Packet absolute = visca::panTiltPosition(1, 0x18, 0x18, she.toSteps(PAN, toRadians(170.0)),
                                                 she.toSteps(TILT, toRadians(90.0)), she.layout);
  ASSERT_EQ(absolute.size(), 17u);
  Packet stream = absolute;
  stream.insert(stream.end(), { 0x81, 0x01, 0x06, 0x02, 0x18, 0x00 });
  stream.insert(stream.end(), 11, 0x01);
  stream.push_back(visca::TERMINATOR);
  visca::PacketSplitter splitter;
  std::vector<Packet> packets;
  splitter.feed(stream.data(), stream.size(), packets);
  ASSERT_EQ(packets.size(), 1u);
  EXPECT_EQ(packets[0], absolute);
  EXPECT_EQ(splitter.counters().broken_packets, 1u);
  // Their answers: 13 bytes, `y0 50 0p*5 0t*5 FF` (360SHE, pan EAC00h, tilt FC400h).
  std::int32_t pan = 0;
  std::int32_t tilt = 0;
  ASSERT_TRUE(visca::decodePanTiltAnswer(
      visca::classify({ 0x90, 0x50, 0x0E, 0x0A, 0x0C, 0x00, 0x00, 0x0F, 0x0C, 0x04, 0x00, 0x00, 0xFF }), she.layout,
      pan, tilt));
  EXPECT_NEAR(toDegrees(she.fromSteps(PAN, pan)), -170.0, 1e-9);
  EXPECT_NEAR(toDegrees(she.fromSteps(TILT, tilt)), -30.0, 1e-9);
  // Positions are clamped to what 5 nibbles hold.
  EXPECT_EQ(am7.toSteps(TILT, toRadians(600.0)), visca::PositionLayout::limit(5));
}

TEST(ViscaModel, TheBrcX400TakesOneSpeedAndItsTablesSpeeds)
{
  // BRC-X400 command list: `8x 01 06 02 vv 00 0p 0p 0p 0p 0t 0t 0t 0t FF`, pan DE00h..2200h = +-170, tilt FC00h (-20)
  // ..1200h (+90); pan speed 18h = 101 deg/s, 06h = 6.7; tilt 17h = 91.
  const visca::ViscaModel x400 = model("brc_x400");
  EXPECT_EQ(x400.toSteps(PAN, toRadians(170.0)), 0x2200);
  EXPECT_EQ(x400.toSteps(TILT, toRadians(-20.0)) & 0xFFFF, 0xFC00);
  EXPECT_EQ(visca::toHex(visca::panTiltPosition(1, 0x18, 0x17, x400.toSteps(PAN, toRadians(170.0)),
                                                x400.toSteps(TILT, toRadians(90.0)), x400.layout)),
            "81 01 06 02 18 00 02 02 00 00 01 02 00 00 FF");
  EXPECT_EQ(x400.axes[PAN].max_speed_byte, 0x18);
  EXPECT_EQ(x400.axes[TILT].max_speed_byte, 0x17);
  EXPECT_NEAR(toDegrees(x400.speedOfByte(PAN, 0x18)), 101.0, 1e-9);
  EXPECT_NEAR(toDegrees(x400.speedOfByte(PAN, 0x06)), 6.7, 1e-9);
  EXPECT_NEAR(toDegrees(x400.speedOfByte(TILT, 0x17)), 91.0, 1e-9);
  EXPECT_EQ(x400.speedByte(PAN, toRadians(6.5)), 0x06);  // the byte whose speed is nearest, not the linear guess
  EXPECT_EQ(x400.speedByte(PAN, toRadians(500.0)), 0x18);
  EXPECT_EQ(x400.speedByte(PAN, toRadians(0.01)), 0x01);
  EXPECT_EQ(x400.speedByte(PAN, 0.0), 0);
  EXPECT_EQ(x400.zoomToPosition(20.0), 0x4000);
  EXPECT_EQ(x400.zoomToPosition(2.0), 0x0DC1);
}

TEST(ViscaModel, ALensThatDecidesTheZoomIsDeclaredAndOnlyTheWidestViewIsAccepted)
{
  for (const char* name : { "ilme_fr7", "brc_am7" })
  {
    const std::array<AxisCapability, AXIS_COUNT> axes = model(name).capabilities();
    EXPECT_TRUE(axes[ZOOM].present) << name;
    EXPECT_FALSE(axes[ZOOM].absolute) << name;
    EXPECT_FALSE(axes[ZOOM].feedback) << name;
    EXPECT_TRUE(axes[ZOOM].widest_view) << name;
    EXPECT_NE(axes[ZOOM].remedy.find("zoom/table"), std::string::npos) << name;
  }
  EXPECT_TRUE(model("brc_x1000").capabilities()[ZOOM].feedback);
}

TEST(ViscaCodec, TheStandardZoomVersionPowerAndAddressedIfClearAreThePublishedPackets)
{
  EXPECT_EQ(visca::toHex(visca::zoomDriveStandard(1, 1)), "81 01 04 07 02 FF");
  EXPECT_EQ(visca::toHex(visca::zoomDriveStandard(1, -5)), "81 01 04 07 03 FF");
  EXPECT_EQ(visca::toHex(visca::zoomDriveStandard(1, 0)), "81 01 04 07 00 FF");
  EXPECT_TRUE(visca::isVariableZoomDrive(visca::zoomDrive(1, 8)));
  EXPECT_TRUE(visca::isVariableZoomDrive(visca::zoomDrive(2, -1)));
  EXPECT_FALSE(visca::isVariableZoomDrive(visca::zoomDriveStandard(1, 1)));
  EXPECT_FALSE(visca::isVariableZoomDrive(visca::zoomStop(1)));
  EXPECT_EQ(visca::toHex(visca::versionInquiry(1)), "81 09 00 02 FF");
  EXPECT_EQ(visca::toHex(visca::powerInquiry(1)), "81 09 04 00 FF");
  EXPECT_EQ(visca::toHex(visca::ifClearAddressed(1)), "81 01 00 01 FF");
}

TEST(ViscaModel, StepsSpeedsAndZoomRoundTrip)
{
  visca::ViscaModel camera = model("evi_d70");
  camera.zoom_table = { { 0x0000, 1.0 }, { 0x1606, 2.0 }, { 0x4000, 18.0 } };
  ASSERT_EQ(camera.check(), "");
  for (double degrees : { -170.0, -45.5, 0.0, 0.075, 33.3, 170.0 })
  {
    EXPECT_NEAR(toDegrees(camera.fromSteps(PAN, camera.toSteps(PAN, toRadians(degrees)))), degrees, 0.04);
  }
  EXPECT_EQ(camera.speedByte(PAN, 0.0), 0);
  EXPECT_EQ(camera.speedByte(PAN, 1e-4), 1);  // never 0 for a motion
  EXPECT_EQ(camera.speedByte(PAN, toRadians(100.0)), 0x18);
  EXPECT_EQ(camera.speedByte(PAN, toRadians(500.0)), 0x18);  // capped
  EXPECT_NEAR(toDegrees(camera.speedOfByte(TILT, 0x17)), 90.0, 1e-9);
  EXPECT_EQ(camera.zoomToPosition(1.0), 0x0000);
  EXPECT_EQ(camera.zoomToPosition(2.0), 0x1606);
  EXPECT_EQ(camera.zoomToPosition(18.0), 0x4000);
  EXPECT_EQ(camera.zoomToPosition(99.0), 0x4000);  // clamped to the table
  EXPECT_NEAR(camera.positionToZoom(0x1606), 2.0, 1e-9);
  EXPECT_NEAR(camera.positionToZoom(camera.zoomToPosition(10.0)), 10.0, 1e-3);
  EXPECT_EQ(camera.zoomSpeed(0.0), 0);
  EXPECT_EQ(camera.zoomSpeed(-camera.zoom_rate), -8);
  EXPECT_NEAR(camera.rateOfZoomSpeed(camera.zoomSpeed(camera.zoom_rate / 2)), camera.zoom_rate / 2, 1e-9);
  camera.zoom_table = { { 0x0000, 1.0 }, { 0x0000, 2.0 } };
  EXPECT_NE(camera.check(), "");
}

// ---------------------------------------------------------------- the splitter, at every offset, with garbage

TEST(ViscaSplitter, ReadsTheSamePacketsHoweverTheStreamIsSplit)
{
  const Packet stream = { 0x00, 0x13,                                                        // noise
                          0x90, 0x41, 0xFF,                                                  // ACK
                          0x90, 0x50, 0x00, 0x02,                                            // cut short...
                          0x90, 0x50, 0x00, 0x02, 0x08, 0x08, 0x00, 0x00, 0x09, 0x00, 0xFF,  // ...by an answer
                          0x7F, 0xFF,                                                        // noise, a stray FF
                          0x90, 0x60, 0x02, 0xFF,                                            // syntax error
                          0x90, 0xFF,                                                        // too short
                          0x90, 0x51, 0xFF };                                                // completion
  std::vector<Packet> whole;
  visca::PacketSplitter reference;
  reference.feed(stream.data(), stream.size(), whole);
  ASSERT_EQ(whole.size(), 4u);
  EXPECT_EQ(visca::toHex(whole[1]), "90 50 00 02 08 08 00 00 09 00 FF");
  const visca::SplitterCounters& counted = reference.counters();
  EXPECT_EQ(counted.skipped_bytes, 4u);
  EXPECT_EQ(counted.broken_packets, 2u);
  EXPECT_EQ(counted.packet_bytes + counted.skipped_bytes + counted.broken_bytes, stream.size());

  for (std::size_t first = 0; first <= stream.size(); ++first)
  {
    for (std::size_t second = first; second <= stream.size(); ++second)
    {
      visca::PacketSplitter splitter;
      std::vector<Packet> packets;
      splitter.feed(stream.data(), first, packets);
      splitter.feed(stream.data() + first, second - first, packets);
      splitter.feed(stream.data() + second, stream.size() - second, packets);
      ASSERT_EQ(packets, whole) << "split at " << first << ", " << second;
      EXPECT_EQ(splitter.counters().skipped_bytes, counted.skipped_bytes);
      EXPECT_EQ(splitter.counters().broken_bytes, counted.broken_bytes);
    }
  }
}

TEST(ViscaSplitter, AnOverlongPacketIsDroppedAndTheNextOneRead)
{
  Packet stream = { 0x90, 0x50 };
  stream.insert(stream.end(), 20, 0x01);
  stream.insert(stream.end(), { 0xFF, 0x90, 0x41, 0xFF });
  visca::PacketSplitter splitter;
  std::vector<Packet> packets;
  splitter.feed(stream.data(), stream.size(), packets);
  ASSERT_EQ(packets.size(), 1u);
  EXPECT_EQ(visca::toHex(packets[0]), "90 41 FF");
  EXPECT_EQ(splitter.counters().broken_packets, 1u);
  const visca::SplitterCounters& counted = splitter.counters();
  EXPECT_EQ(counted.packet_bytes + counted.skipped_bytes + counted.broken_bytes, stream.size());
}

TEST(ViscaOverIp, MalformedDatagramsAreNamed)
{
  visca::IpMessage message;
  const Packet short_one = { 0x01, 0x11, 0x00, 0x03, 0x00, 0x00, 0x00 };
  EXPECT_EQ(visca::decodeIp(short_one.data(), short_one.size(), message), visca::IpError::TOO_SHORT);
  const Packet wrong_length = { 0x01, 0x11, 0x00, 0x04, 0x00, 0x00, 0x00, 0x07, 0x90, 0x41, 0xFF };
  EXPECT_EQ(visca::decodeIp(wrong_length.data(), wrong_length.size(), message), visca::IpError::LENGTH_MISMATCH);
  const Packet unknown = { 0x05, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, 0x07, 0x90, 0x41, 0xFF };
  EXPECT_EQ(visca::decodeIp(unknown.data(), unknown.size(), message), visca::IpError::UNKNOWN_TYPE);
  const Packet reply = { 0x01, 0x11, 0x00, 0x03, 0x00, 0x00, 0x00, 0x07, 0x90, 0x41, 0xFF };
  ASSERT_EQ(visca::decodeIp(reply.data(), reply.size(), message), visca::IpError::NONE);
  EXPECT_EQ(message.type, visca::IP_REPLY);
  EXPECT_EQ(message.sequence, 7u);
  EXPECT_STREQ(visca::toString(visca::IpError::LENGTH_MISMATCH), "payload length does not match the datagram");
}

TEST(ViscaOverIp, ADeviceSettingCommandIsReadAndAnErrorKeepsTheSequenceNumber)
{
  // Payload type 0120h: the VISCA device setting command (IF_Clear broadcast), which libvisca sends.
  visca::IpMessage message;
  const Packet if_clear = { 0x01, 0x20, 0x00, 0x05, 0x00, 0x00, 0x00, 0x09, 0x88, 0x01, 0x00, 0x01, 0xFF };
  ASSERT_EQ(visca::decodeIp(if_clear.data(), if_clear.size(), message), visca::IpError::NONE);
  EXPECT_EQ(message.type, visca::IP_DEVICE_SETTING);
  EXPECT_EQ(message.sequence, 9u);
  EXPECT_EQ(visca::toHex(message.payload), "88 01 00 01 FF");
  // A camera answers an unreadable message with its sequence number: the header's is kept.
  const Packet unknown = { 0x05, 0x00, 0x00, 0x03, 0x00, 0x00, 0x01, 0x02, 0x81, 0x41, 0xFF };
  EXPECT_EQ(visca::decodeIp(unknown.data(), unknown.size(), message), visca::IpError::UNKNOWN_TYPE);
  EXPECT_EQ(message.sequence, 0x0102u);
}

}  // namespace
}  // namespace ptz_action_server
