#include "ptz_action_server/core/flir/flir_codec.h"

#include <cctype>
#include <cstdlib>

namespace ptz_action_server
{
namespace flir
{
namespace
{
std::string trim(const std::string& text)
{
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos)
  {
    return {};
  }
  const std::size_t last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

/// The last number (-12, 3.5, 185.1428) in \p text; false if there is none.
bool lastNumber(const std::string& text, double& value)
{
  std::size_t end = text.size();
  while (end > 0 && !std::isdigit(static_cast<unsigned char>(text[end - 1])))
  {
    --end;
  }
  if (end == 0)
  {
    return false;
  }
  std::size_t begin = end;
  while (begin > 0 && (std::isdigit(static_cast<unsigned char>(text[begin - 1])) || text[begin - 1] == '.'))
  {
    --begin;
  }
  if (begin > 0 && text[begin - 1] == '-')
  {
    --begin;
  }
  const std::string number = text.substr(begin, end - begin);
  char* parsed_end = nullptr;
  value = std::strtod(number.c_str(), &parsed_end);
  return parsed_end != number.c_str();
}
}  // namespace

Reply classifyLine(const std::string& line)
{
  Reply reply;
  if (trim(line).rfind(BANNER_END, 0) == 0)
  {
    // The banner's last line; an E-series unit ends it with `*` when it is ready, which is no reply to anything.
    reply.text = trim(line);
    return reply;
  }
  const std::size_t start = line.find_first_of("*!");
  if (start == std::string::npos)
  {
    reply.text = line;
    return reply;  // TEXT: a banner, an echo, noise
  }
  const std::string rest = trim(line.substr(start + 1));
  if (line[start] == '!')
  {
    const bool limit = !rest.empty() && (rest[0] == 'P' || rest[0] == 'T') &&
                       (rest.size() == 1 || !std::isalpha(static_cast<unsigned char>(rest[1])));
    if (limit)
    {
      reply.kind = Reply::Kind::LIMIT;
      reply.axis = rest[0];
      return reply;
    }
    reply.kind = Reply::Kind::ERROR;
    reply.text = rest.empty() ? "error" : rest;
    return reply;
  }
  reply.kind = lastNumber(rest, reply.value) ? Reply::Kind::VALUE : Reply::Kind::ACK;
  return reply;
}

void ReplyParser::feed(const std::uint8_t* data, std::size_t size, std::vector<Reply>& replies)
{
  for (std::size_t index = 0; index < size; ++index)
  {
    const char character = static_cast<char>(data[index]);
    if (character == '\r' || character == '\n')
    {
      if (!trim(line_).empty())
      {
        replies.push_back(classifyLine(line_));
      }
      line_.clear();
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
      line_.clear();
    }
  }
}

void ReplyParser::reset()
{
  line_.clear();
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
