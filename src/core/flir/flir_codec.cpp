#include "ptz_action_server/core/flir/flir_codec.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace flir
{
namespace
{
/// The first number (-12, 3.5, 185.1428) in \p text; false if there is none. Verbose replies put the value first and
/// may carry other numbers after it (`* Pan acceleration is 2000 positions/sec^2`).
bool firstNumber(const std::string& text, double& value)
{
  for (std::size_t index = 0; index < text.size(); ++index)
  {
    if (!std::isdigit(static_cast<unsigned char>(text[index])))
    {
      continue;
    }
    const std::size_t begin = index > 0 && text[index - 1] == '-' ? index - 1 : index;
    std::size_t end = index;
    while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.'))
    {
      ++end;
    }
    const std::string number = text.substr(begin, end - begin);
    char* parsed_end = nullptr;
    value = std::strtod(number.c_str(), &parsed_end);
    return parsed_end != number.c_str();
  }
  return false;
}

bool contains(const std::string& text, const char* part)
{
  return text.find(part) != std::string::npos;
}

/// A line of a start-up banner: the E-series' (`### PAN-TILT CONTROLLER`, `### v3.3.0, (C)2010-2011 FLIR Commercial
/// Systems, Inc., All Rights Reserved`, `Initializing...*`) or one like it.
bool isBannerLine(const std::string& trimmed)
{
  std::string lower;
  for (const char character : trimmed)
  {
    lower.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(character))));
  }
  return trimmed.rfind("###", 0) == 0 || trimmed.rfind(BANNER_END, 0) == 0 || contains(lower, "pan-tilt controller") ||
         contains(lower, "pan tilt controller") || contains(lower, "directed perception") ||
         contains(lower, "flir commercial systems") || contains(lower, "all rights reserved");
}

/// What a reset's calibration answers: both axes (`R`, `RE`), tilt only (`RT`), pan only (`RP`); longest first.
const char* const RESET_ANSWERS[] = { "!T!T!P!P*", "!T!T*", "!P!P*" };

/// The reset answer \p line is, alone or after the echo of the command that asked for it (`r !T!T!P!P*`); "" if none.
/// A limit hit reports each axis once, so two reports of one axis ahead of a bare `*` come from nothing else.
std::string resetAnswer(const std::string& line)
{
  const std::string bare = trimmed(line);
  for (const char* answer : RESET_ANSWERS)
  {
    const std::size_t length = std::strlen(answer);
    if (bare.size() < length || bare.compare(bare.size() - length, length, answer) != 0)
    {
      continue;
    }
    const std::string echo = trimmed(bare.substr(0, bare.size() - length));
    if (std::all_of(echo.begin(), echo.end(),
                    [](char character) { return std::isalpha(static_cast<unsigned char>(character)) != 0; }))
    {
      return answer;
    }
  }
  return {};
}

/// The length of the limit reports (`!P`, `!T`) \p text starts with.
std::size_t leadingLimitReports(const std::string& text)
{
  std::size_t length = 0;
  while (length + 1 < text.size() && text[length] == '!' && (text[length + 1] == 'P' || text[length + 1] == 'T'))
  {
    length += 2;
  }
  return length;
}

/// What a line without limit reports is.
Reply classifyRest(const std::string& line)
{
  Reply reply;
  const std::string bare = trimmed(line);
  if (isBannerLine(bare))
  {
    // An E-series unit ends its banner with `Initializing...*` once it is ready, which is no reply to anything.
    reply.kind = Reply::Kind::BANNER;
    reply.text = bare;
    return reply;
  }
  const std::size_t start = line.find_first_of("*!");
  if (start == std::string::npos)
  {
    reply.text = line;
    return reply;  // TEXT: an echo without a reply, noise
  }
  const std::string rest = trimmed(line.substr(start + 1));
  if (line[start] == '!')
  {
    reply.kind = Reply::Kind::ERROR;
    reply.text = rest.empty() ? "error" : rest;
    return reply;
  }
  reply.kind = firstNumber(rest, reply.value) ? Reply::Kind::VALUE : Reply::Kind::ACK;
  return reply;
}
}  // namespace

void classifyLine(const std::string& line, std::vector<Reply>& replies)
{
  const std::string reset = resetAnswer(line);
  if (!reset.empty())
  {
    Reply calibrated;
    calibrated.kind = Reply::Kind::RESET;
    calibrated.text = reset;
    replies.push_back(calibrated);
    return;
  }
  // `!P` / `!T` come whenever a limit is hit, with no line end of their own: take them out wherever they are. (An
  // error is `! <message>`, with a space.)
  std::string rest;
  for (std::size_t index = 0; index < line.size(); ++index)
  {
    if (line[index] == '!' && index + 1 < line.size() && (line[index + 1] == 'P' || line[index + 1] == 'T'))
    {
      Reply limit;
      limit.kind = Reply::Kind::LIMIT;
      limit.axis = line[index + 1];
      replies.push_back(limit);
      ++index;
      continue;
    }
    rest.push_back(line[index]);
  }
  if (!trimmed(rest).empty())
  {
    replies.push_back(classifyRest(rest));
  }
}

void ReplyParser::feed(const std::uint8_t* data, std::size_t size, std::vector<Reply>& replies)
{
  for (std::size_t index = 0; index < size; ++index)
  {
    const char character = static_cast<char>(data[index]);
    if (character == '\r' || character == '\n')
    {
      if (!overlong_)
      {
        classifyLine(line_, replies);
      }
      overlong_ = false;
      line_.clear();
      continue;
    }
    if (overlong_)
    {
      ++dropped_bytes_;  // the rest of a line past MAX_LINE, up to its line end
      continue;
    }
    if (!std::isprint(static_cast<unsigned char>(character)))
    {
      continue;
    }
    line_.push_back(character);
    if (line_.size() >= MAX_LINE)
    {
      Reply overlong;
      overlong.text = line_;
      replies.push_back(overlong);
      dropped_bytes_ += line_.size();
      line_.clear();
      overlong_ = true;
    }
  }
}

void ReplyParser::reset()
{
  line_.clear();
  overlong_ = false;
}

void ReplyParser::dropPartialReply()
{
  const std::size_t kept = leadingLimitReports(line_);
  dropped_bytes_ += line_.size() - kept;
  line_.resize(kept);
}

std::string command(const char* letters)
{
  return std::string(letters) + " ";
}

std::string command(const char* letters, long value)
{
  return std::string(letters) + std::to_string(value) + " ";
}

}  // namespace flir
}  // namespace ptz_action_server
