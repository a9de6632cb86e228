/**
 * \file
 * \brief The FLIR (Directed Perception) PTU ASCII protocol: command text and a reply parser that survives any input.
 *
 * A command is `<letters>[<integer>]` ended by a space. In terse mode (`FT`) the unit answers `*` to a command,
 * `* <value>` to a query and `! <message>` to an error; `!P` / `!T` report a pan / tilt limit hit; every reply
 * line ends with CR LF. Before `ED` the unit echoes what it receives, before `FT` its replies are verbose
 * ("* Current Pan position is 1234"), and at power-up it prints a banner. Positions are encoder steps; the unit's
 * positive pan is counter-clockwise, the opposite of ptz_action_server's.
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ptz_action_server
{
namespace flir
{
/// How the unit's start-up banner ends: `Initializing...` (E-series on TCP: `Initializing...*`, once it is ready).
constexpr const char* BANNER_END = "Initializing";

/// One reply line, classified.
struct Reply
{
  enum class Kind
  {
    ACK,    ///< `*` without a number
    VALUE,  ///< `*` with a number: the last number on the line (terse or verbose)
    ERROR,  ///< `! message`
    LIMIT,  ///< `!P` or `!T`: a limit was hit (not an answer to a command)
    TEXT,   ///< anything else: banners (including `Initializing...*`), echoes without a reply, noise
  };
  Kind kind = Kind::TEXT;
  double value = 0.0;  ///< VALUE
  char axis = 0;       ///< LIMIT: 'P' or 'T'
  std::string text;    ///< ERROR: the message; TEXT: the line

  /// The banner's last line: the unit has finished starting.
  bool endsBanner() const
  {
    return kind == Kind::TEXT && text.rfind(BANNER_END, 0) == 0;
  }
};

/// Classifies one line (without its line end). Never throws.
Reply classifyLine(const std::string& line);

/**
 * \brief Splits a byte stream into reply lines (CR and/or LF end a line) and classifies them.
 *
 * Lines longer than MAX_LINE are cut there and reported as TEXT; NUL and other control bytes are dropped.
 */
class ReplyParser
{
public:
  static constexpr std::size_t MAX_LINE = 256;

  /// Appends the replies completed by \p data to \p replies.
  void feed(const std::uint8_t* data, std::size_t size, std::vector<Reply>& replies);
  /// Forgets a partial line (after a reconnect or a timeout).
  void reset();

private:
  std::string line_;
};

/// `<letters> ` (a query or a command without argument).
std::string command(const char* letters);
/// `<letters><value> `.
std::string command(const char* letters, long value);

}  // namespace flir
}  // namespace ptz_action_server
