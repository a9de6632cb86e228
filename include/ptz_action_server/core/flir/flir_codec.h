/**
 * \file
 * \brief The FLIR (Directed Perception) PTU ASCII protocol: command text and a reply parser that survives any input.
 *
 * A command is `<letters>[<integer>]` ended by a space. In terse mode (`FT`) the unit answers `*` to a command,
 * `* <value>` to a query and `! <message>` to an error; every reply line ends with CR LF. `!P` / `!T` report a pan /
 * tilt limit hit whenever it happens, without a line end of their own, so they may lead any line. A reset (`R`, `RE`)
 * calibrates: each axis runs to both its limits, tilt first, and the unit answers `!T!T!P!P*` (`RT` `!T!T*`, `RP`
 * `!P!P*`), the answer the published drivers wait for. Before `ED` the unit echoes what it receives ahead of its
 * reply (`PP * 12`; a CR delimiter is echoed as a line break), before `FT` its replies are verbose ("* Current pan
 * position is 1234"), and it prints a banner at power-up (an E-series unit on every TCP connection). Positions are
 * encoder steps; the unit's positive pan is counter-clockwise, the opposite of ptz_action_server's.
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

/// What the unit said: a reply to a request, a limit report, its banner, or other text.
struct Reply
{
  enum class Kind
  {
    ACK,    ///< `*` without a number (after any echo: `ED *`)
    VALUE,  ///< `*` with a number: the first number after it (terse `* 12`, verbose `* Current pan position is 12`)
    ERROR,  ///< `! message`
    LIMIT,  ///< `!P` or `!T`: a limit was hit (never an answer to a request)
    /// `!T!T!P!P*`, `!T!T*` or `!P!P*` on a line of its own (after the echo of the reset, if any): a reset's
    /// calibration ended. Neither limit hits nor an acknowledgement of whatever was asked last.
    RESET,
    BANNER,  ///< a line of the start-up banner (`### PAN-TILT CONTROLLER`, ..., `Initializing...*`): no reply either
    TEXT,    ///< anything else: an echo without a reply (`TP` before a CR), noise
  };
  Kind kind = Kind::TEXT;
  double value = 0.0;  ///< VALUE
  char axis = 0;       ///< LIMIT: 'P' or 'T'
  std::string text;    ///< ERROR: the message; BANNER, TEXT: the line; RESET: the calibration's answer

  /// The banner's last line: the unit has finished starting.
  bool endsBanner() const
  {
    return kind == Kind::BANNER && text.rfind(BANNER_END, 0) == 0;
  }
};

/**
 * \brief Classifies one line (without its line end) and appends what it says to \p replies: a RESET for a reset's
 * answer; otherwise first a LIMIT for each `!P` / `!T` anywhere in it, then what the rest of the line is (nothing if
 * only limit reports were left). Never throws.
 */
void classifyLine(const std::string& line, std::vector<Reply>& replies);

/**
 * \brief Splits a byte stream into reply lines (CR and/or LF end a line) and classifies them.
 *
 * NUL and other control bytes are dropped. The buffer is bounded: a line that reaches MAX_LINE bytes without its line
 * end is reported once as TEXT (its first MAX_LINE bytes), and everything up to the next line end is dropped and
 * counted (droppedBytes(), the overlong line included): the parser resynchronises on the next line end, and a reply
 * that never ends costs no memory.
 */
class ReplyParser
{
public:
  static constexpr std::size_t MAX_LINE = 256;

  /// Appends the replies completed by \p data to \p replies.
  void feed(const std::uint8_t* data, std::size_t size, std::vector<Reply>& replies);
  /// Forgets a partial line (after a reconnect).
  void reset();
  /// Forgets a partial reply (after a timeout), but keeps the limit reports it starts with: they have no line end of
  /// their own, and a reset's calibration sends them one by one, seconds apart (`!T`, `!T`, `!P`, `!P*`).
  void dropPartialReply();
  /// Bytes dropped so far (never reset): of overlong lines, and of partial replies dropped after a timeout.
  std::uint64_t droppedBytes() const
  {
    return dropped_bytes_;
  }

private:
  std::string line_;
  bool overlong_ = false;  ///< the current line passed MAX_LINE: drop up to its line end
  std::uint64_t dropped_bytes_ = 0;
};

/// `<letters> ` (a query or a command without argument).
std::string command(const char* letters);
/// `<letters><value> `.
std::string command(const char* letters, long value);

}  // namespace flir
}  // namespace ptz_action_server
