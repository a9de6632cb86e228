/**
 * \file
 * \brief The FLIR PTU reply classifier and command text: replies as published-wire-facts.md section 3 quotes them
 * (terse, verbose, echoed, errors, limit reports, the reset answers, the E-series banner), split at every offset,
 * binary junk and overlong lines; a partial reply dropped after a timeout keeps the limit reports it starts with.
 */
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ptz_action_server/core/flir/flir_codec.h"

using namespace ptz_action_server;
using Kind = flir::Reply::Kind;

namespace
{
std::vector<flir::Reply> parseText(flir::ReplyParser& parser, const std::string& text)
{
  std::vector<flir::Reply> replies;
  parser.feed(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), replies);
  return replies;
}

std::vector<flir::Reply> parseText(const std::string& text)
{
  flir::ReplyParser parser;
  return parseText(parser, text);
}

std::vector<Kind> kindsOf(const std::vector<flir::Reply>& replies)
{
  std::vector<Kind> kinds;
  for (const flir::Reply& reply : replies)
  {
    kinds.push_back(reply.kind);
  }
  return kinds;
}

std::vector<flir::Reply> classify(const std::string& line)
{
  std::vector<flir::Reply> replies;
  flir::classifyLine(line, replies);
  return replies;
}
}  // namespace

TEST(FlirReplies, PublishedReplyLinesAreClassifiedAsTheirTextSays)
{
  struct Golden
  {
    const char* line;  ///< as published (M46, M300, INDI and STANG captures, DRV), without its line end
    Kind kind;
    double value;
    const char* text;
  };
  const std::vector<Golden> goldens = {
    { "*", Kind::ACK, 0.0, "" },
    { "* 185.1428", Kind::VALUE, 185.1428, "" },                                   // TR / PR, terse
    { "* 185.1428 seconds arc per Pan position", Kind::VALUE, 185.1428, "" },      // verbose
    { "* -3090", Kind::VALUE, -3090.0, "" },                                       // PN of a D46
    { "* 604", Kind::VALUE, 604.0, "" },                                           // TX
    { "* 31", Kind::VALUE, 31.0, "" },                                             // PL
    { "* 2902", Kind::VALUE, 2902.0, "" },                                         // PU
    { "PP * 22", Kind::VALUE, 22.0, "" },                                          // echo on
    { "PP * 100", Kind::VALUE, 100.0, "" },                                        // E-series echo
    { "PP * 0", Kind::VALUE, 0.0, "" },                                            // FT
    { "PP * Current pan position is 0", Kind::VALUE, 0.0, "" },                    // FV
    { "PA * Pan acceleration is 2000 positions/sec^2", Kind::VALUE, 2000.0, "" },  // the value, not the ^2
    { "* 2000", Kind::VALUE, 2000.0, "" },
    { "* ASCII terse mode", Kind::ACK, 0.0, "" },  // F
    { "ft *", Kind::ACK, 0.0, "" },                // the driver's start-up, echo still on
    { "! Motor speed cannot be less than 31 pos/sec", Kind::ERROR, 0.0, "Motor speed cannot be less than 31 pos/sec" },
    { "! Pan speed cannot exceed 2902 positions/sec", Kind::ERROR, 0.0, "Pan speed cannot exceed 2902 positions/sec" },
    { "! Maximum allowable Pan position is 3090", Kind::ERROR, 0.0, "Maximum allowable Pan position is 3090" },
    { "PP3200 ! Maximum allowable Pan position is 3090", Kind::ERROR, 0.0, "Maximum allowable Pan position is 3090" },
    { "!", Kind::ERROR, 0.0, "error" },
    { "### PAN-TILT CONTROLLER", Kind::BANNER, 0.0, "### PAN-TILT CONTROLLER" },
    { "Initializing...*", Kind::BANNER, 0.0, "Initializing...*" },  // E-series: ready, but no reply to anything
    { "Initializing...", Kind::BANNER, 0.0, "Initializing..." },
    { "TP", Kind::TEXT, 0.0, "TP" },  // a command echoed before a CR delimiter, its reply on the next line
    // A reset's answer, what the published drivers read after ` r ` (DRV, P46; INDI: RE, RT, RP): no limit hits, and
    // no acknowledgement of anything else.
    { "!T!T!P!P*", Kind::RESET, 0.0, "!T!T!P!P*" },
    { "!T!T*", Kind::RESET, 0.0, "!T!T*" },
    { "!P!P*", Kind::RESET, 0.0, "!P!P*" },
    { "r !T!T!P!P*", Kind::RESET, 0.0, "!T!T!P!P*" },  // echo on: the command, then the answer on its line
    { "RE !T!T!P!P* ", Kind::RESET, 0.0, "!T!T!P!P*" },
  };
  for (const Golden& golden : goldens)
  {
    const std::vector<flir::Reply> replies = classify(golden.line);
    ASSERT_EQ(replies.size(), 1u) << golden.line;
    EXPECT_EQ(replies[0].kind, golden.kind) << golden.line;
    EXPECT_DOUBLE_EQ(replies[0].value, golden.value) << golden.line;
    EXPECT_EQ(replies[0].text, golden.text) << golden.line;
  }
}

TEST(FlirReplies, LimitReportsAreTakenOutWhereverTheyCome)
{
  // A velocity move reports each axis' limit once, and the report may lead the next acknowledgement.
  const std::vector<flir::Reply> hits = classify("!T!P*");
  EXPECT_EQ(kindsOf(hits), (std::vector<Kind>{ Kind::LIMIT, Kind::LIMIT, Kind::ACK }));
  EXPECT_EQ(std::string({ hits[0].axis, hits[1].axis }), "TP");
  EXPECT_EQ(kindsOf(classify("!P*")), (std::vector<Kind>{ Kind::LIMIT, Kind::ACK }));
  // Two reports of one axis ahead of a bare `*` with anything but an echoed command before them: no reset answer.
  EXPECT_EQ(kindsOf(classify("* 3 !T!T*")), (std::vector<Kind>{ Kind::LIMIT, Kind::LIMIT, Kind::VALUE }));
  EXPECT_EQ(kindsOf(classify("!P!T!T*")), (std::vector<Kind>{ Kind::LIMIT, Kind::LIMIT, Kind::LIMIT, Kind::ACK }));

  EXPECT_EQ(kindsOf(classify("!P")), std::vector<Kind>{ Kind::LIMIT });
  EXPECT_EQ(classify("!T").front().axis, 'T');
  // A report that came without a line end of its own, ahead of a reply (and its echo).
  const std::vector<flir::Reply> glued = classify("!PPP * 12");
  EXPECT_EQ(kindsOf(glued), (std::vector<Kind>{ Kind::LIMIT, Kind::VALUE }));
  EXPECT_DOUBLE_EQ(glued[1].value, 12.0);
  // An error message that starts with P is no limit report.
  EXPECT_EQ(kindsOf(classify("! Pan speed cannot exceed 2902 positions/sec")), std::vector<Kind>{ Kind::ERROR });
}

TEST(FlirReplies, TheEseriesBannerIsNoReplyAndEndsOnItsLastLine)
{
  const std::vector<flir::Reply> replies = parseText("\r\n\r\n### PAN-TILT CONTROLLER\r\n### v3.3.0, (C)2010-2011 FLIR "
                                                     "Commercial Systems, Inc., All Rights "
                                                     "Reserved\r\nInitializing...*\r\n");
  EXPECT_EQ(kindsOf(replies), (std::vector<Kind>{ Kind::BANNER, Kind::BANNER, Kind::BANNER }));
  EXPECT_FALSE(replies[0].endsBanner());
  EXPECT_FALSE(replies[1].endsBanner());
  EXPECT_TRUE(replies[2].endsBanner());
}

TEST(FlirReplies, EchoedRepliesAndTheirLineBreaks)
{
  // E-series: a CR / LF delimiter is echoed as a line break, so the echo is a line of its own.
  const std::vector<flir::Reply> own_line = parseText("TP\r\n* 600\r\n");
  EXPECT_EQ(kindsOf(own_line), (std::vector<Kind>{ Kind::TEXT, Kind::VALUE }));
  EXPECT_DOUBLE_EQ(own_line[1].value, 600.0);
  // What a unit answers to the published driver's `ft ` `ed ` `ci `: 15 bytes, three acknowledgements.
  EXPECT_EQ(kindsOf(parseText("ft *\r\ned *\r\n*\r\n")), (std::vector<Kind>{ Kind::ACK, Kind::ACK, Kind::ACK }));
}

TEST(FlirReplies, LinesSplitAtEveryOffsetAndAnyLineEnd)
{
  const std::string stream = "\r\nPan-Tilt Controller\r\n* 12\r\n*\n! Illegal Command\r* -3\r\n!T!T!P!P*\r\n";
  for (std::size_t split = 0; split <= stream.size(); ++split)
  {
    flir::ReplyParser parser;
    std::vector<flir::Reply> replies = parseText(parser, stream.substr(0, split));
    const std::vector<flir::Reply> rest = parseText(parser, stream.substr(split));
    replies.insert(replies.end(), rest.begin(), rest.end());
    ASSERT_EQ(kindsOf(replies),
              (std::vector<Kind>{ Kind::BANNER, Kind::VALUE, Kind::ACK, Kind::ERROR, Kind::VALUE, Kind::RESET }))
        << "split at " << split;
    EXPECT_DOUBLE_EQ(replies[1].value, 12.0);
    EXPECT_DOUBLE_EQ(replies[4].value, -3.0);
  }
}

TEST(FlirReplies, APartialReplyDroppedAfterATimeoutKeepsTheLimitReportsItStartsWith)
{
  // A calibration reports each limit as the axis reaches it, seconds apart: requests time out meanwhile.
  flir::ReplyParser parser;
  EXPECT_TRUE(parseText(parser, "!T!T").empty());
  parser.dropPartialReply();
  EXPECT_TRUE(parseText(parser, "!P").empty());
  parser.dropPartialReply();
  EXPECT_EQ(kindsOf(parseText(parser, "!P*\r\n")), std::vector<Kind>{ Kind::RESET });
  // The rest of a reply cut short is dropped: its end never makes the next reply's value.
  EXPECT_TRUE(parseText(parser, "!T* 12").empty());
  parser.dropPartialReply();
  const std::vector<flir::Reply> next = parseText(parser, "* 34\r\n");
  EXPECT_EQ(kindsOf(next), (std::vector<Kind>{ Kind::LIMIT, Kind::VALUE }));
  EXPECT_DOUBLE_EQ(next[1].value, 34.0);
  // An error cut short right after its `!` leaves nothing behind.
  EXPECT_TRUE(parseText(parser, "!").empty());
  parser.dropPartialReply();
  EXPECT_EQ(kindsOf(parseText(parser, "* 5\r\n")), std::vector<Kind>{ Kind::VALUE });
}

TEST(FlirReplies, BinaryJunkAndOverlongLinesNeverBreakTheParser)
{
  std::string junk(1000, 'x');
  junk[10] = '\0';
  junk[20] = '\x7F';
  junk[30] = '\x01';
  const std::vector<flir::Reply> replies = parseText(junk + "\r\n* 5\r\n");
  ASSERT_GE(replies.size(), 2u);
  EXPECT_EQ(replies.front().kind, Kind::TEXT);
  EXPECT_LE(replies.front().text.size(), flir::ReplyParser::MAX_LINE);
  EXPECT_EQ(replies.back().kind, Kind::VALUE);
  EXPECT_DOUBLE_EQ(replies.back().value, 5.0);
}

TEST(FlirReplies, AReplyThatNeverEndsIsDroppedAndCountedAndTheNextLineRead)
{
  flir::ReplyParser parser;
  std::vector<flir::Reply> replies;
  const std::string endless(100, 'A');
  for (int chunk = 0; chunk < 100; ++chunk)  // 10000 bytes without a line end
  {
    parser.feed(reinterpret_cast<const std::uint8_t*>(endless.data()), endless.size(), replies);
  }
  ASSERT_EQ(replies.size(), 1u) << "the overlong line is reported once";
  EXPECT_EQ(replies.front().kind, Kind::TEXT);
  EXPECT_EQ(parser.droppedBytes(), 10000u);
  const std::string next = "\r\n* 7\r\n";
  parser.feed(reinterpret_cast<const std::uint8_t*>(next.data()), next.size(), replies);
  ASSERT_EQ(replies.size(), 2u);
  EXPECT_EQ(replies.back().kind, Kind::VALUE);
  EXPECT_DOUBLE_EQ(replies.back().value, 7.0);
  EXPECT_EQ(parser.droppedBytes(), 10000u);
}

TEST(FlirCommands, Text)
{
  EXPECT_EQ(flir::command("PP", -557), "PP-557 ");
  EXPECT_EQ(flir::command("TS", 1114), "TS1114 ");
  EXPECT_EQ(flir::command("H"), "H ");
}
