/**
 * \file
 * \brief Sony VISCA cameras (and the many that copy it) on RS-232/422, over TCP, or over UDP with or without Sony's
 * VISCA over IP header.
 */
#pragma once

#include <array>
#include <atomic>
#include <deque>
#include <memory>
#include <optional>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/device/poll_round.h"
#include "ptz_action_server/core/device/transaction_channel.h"
#include "ptz_action_server/core/visca/visca_codec.h"
#include "ptz_action_server/core/visca/visca_lens.h"
#include "ptz_action_server/core/visca/visca_model.h"

namespace ptz_action_server
{
/// How VISCA packets travel on the link.
enum class ViscaFraming
{
  RAW,      ///< bare packets: a serial line, and most non-Sony cameras over TCP or UDP
  SONY_IP,  ///< Sony's VISCA over IP: each UDP datagram carries an 8-byte header with a sequence number
};
/// "raw" / "sony_ip" -> \p framing; false for anything else.
bool parseViscaFraming(const std::string& text, ViscaFraming& framing);
const char* toString(ViscaFraming framing);

/// How zoom velocity goals drive the zoom.
enum class ViscaZoomDrive
{
  AUTO,      ///< variable speed (`2p`, `3p`); the standard `02`, `03` from the first syntax error the camera answers
  VARIABLE,  ///< always variable speed
  STANDARD,  ///< always the standard speed: cameras that refuse the variable drive
};
/// "auto" / "variable" / "standard" -> \p drive; false for anything else.
bool parseViscaZoomDrive(const std::string& text, ViscaZoomDrive& drive);
const char* toString(ViscaZoomDrive drive);

/// What only the VISCA protocol needs to know.
struct ViscaSettings
{
  std::uint8_t address = 1;  ///< the camera's address, 1..7
  ViscaFraming framing = ViscaFraming::RAW;
  visca::ViscaModel model;  ///< steps a degree, ranges, speed bytes, zoom table
  double reply_timeout =
      0.0;  ///< s: the reply deadline's floor (0: the exchange's wire time plus 100 ms); it learns up to twice that
  /// Replies from another address than the camera's are taken for its own. A network link reaches one camera, and
  /// some answer from another address (PTZOptics G3 firmware: `A0 41 FF` for camera 1); on a serial daisy chain the
  /// address tells the cameras apart. Unset: true on TCP and UDP, false on a serial line.
  std::optional<bool> any_reply_address;
  /// False: the camera is never asked its position (it answers commands, not inquiries) and has no feedback. True: it
  /// is, and a camera that answers a command but none of the first inquiries is taken for one without inquiries.
  bool inquiries = true;
  ViscaZoomDrive zoom_drive = ViscaZoomDrive::AUTO;
  /// VISCA over IP: the sequence numbers count 1, 2, ..., N, then 1 again (NewTek's NDI PTZ1 takes 1..3 only); 0:
  /// Sony's count, which goes on up (and is cut to the numbers a camera answers once it answers no more, see the
  /// backend's page).
  std::uint32_t sequence_cycle = 0;
  visca::ViscaLens lens;  ///< focus and iris (lens/... parameters)
};

/// Counters for diagnostics (reply timeouts and late replies are the channel's).
struct ViscaCounters
{
  Counter packets;             ///< packets read
  Counter skipped_bytes;       ///< dropped: bytes outside packets
  Counter broken_packets;      ///< dropped: packets cut short (a new start byte, overlong, a datagram's tail)
  Counter bad_datagrams;       ///< dropped: VISCA over IP datagrams without a valid header
  Counter other_address;       ///< dropped: replies from another camera of the chain
  Counter unexpected_replies;  ///< well-formed replies that answer nothing asked
  Counter completions;         ///< `z0 5y FF`: a command finished
  Counter device_errors;       ///< error replies (each a fault of the command it answers, if still current)
  Counter sequence_resets;     ///< VISCA over IP: sequence errors answered by a reset
  Counter network_changes;     ///< `z0 38 FF`: the chain changed; the set-up runs again
  Counter foreign_address;     ///< replies from another address taken for the camera's (any_reply_address)
};

/**
 * \brief VISCA over a DeviceSession.
 *
 * Start-up: on a serial line the address set and IF_Clear broadcasts; over VISCA over IP the sequence reset. Then
 * the pan-tilt and zoom position inquiries are polled for state. Every request (command or inquiry) is one exchange
 * of the TransactionChannel: a command is answered by its ACK (or an error without a socket), an inquiry by its
 * answer, so a reply is never guessed; completions and socket errors arrive later and are matched by socket. Position
 * goals are the absolute pan-tilt command at the model's top speeds and zoom direct; velocity goals the pan-tilt drive
 * and zoom drive; cancel the drive stop (the camera decelerates). Error replies are faults of the command they
 * answer, named ("syntax error", "command not executable", ...).
 *
 * Dialects (doc/backends/visca.md): positions in 4 or 5 nibbles and one or two speed bytes as the model writes them;
 * replies from another address on a network link; the standard zoom drive where the camera refuses the variable one;
 * a camera that answers no inquiries, run without feedback (the last drive command is repeated to keep the link
 * alive); VISCA over IP sequence numbers cut to the numbers a camera answers, and no sequence reset where it answers
 * none.
 */
class ViscaProtocol : public DeviceProtocol
{
public:
  /// DeviceConfig<ViscaProtocol> (device_backend.h): these settings, and the defaults of the link and the session.
  using Settings = ViscaSettings;
  /// serial, tcp, or udp (port 52381 for Sony's VISCA over IP)
  static LinkConfig defaultLink()
  {
    return LinkConfig();
  }
  static DeviceSessionConfig defaultSession()
  {
    return { 0.25, 0.05, 10.0, 0.1, 0.5 };
  }

  ViscaProtocol(const ViscaSettings& settings, DeviceSession& session);

  std::string name() const override
  {
    return "visca";
  }
  std::string deviceName() const override;
  Capabilities capabilities() const override;
  /// Address set and IF_Clear (serial), the sequence reset (VISCA over IP), or nothing (raw over a network).
  void onConnected() override;
  void onReceived(const std::uint8_t* data, std::size_t size) override;
  void onDisconnected() override;
  void onClosing() override
  {
    channel_.close();
  }
  /// The pan-tilt and zoom inquiries, whenever the line is free; after them, every `lens.poll_period` at most, one
  /// lens inquiry in turn (focus mode, focus position, iris position) for the functions the camera has.
  void poll() override;
  void goTo(const AxisValues& position) override
  {
    goToAtSpeed(position, AxisValues{});
  }
  /// The pan-tilt absolute move's speed bytes (VV, WW) at \p speed, the nearest byte (1 at the slowest).
  void goToAtSpeed(const AxisValues& position, const AxisValues& speed) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  /// The pan-tilt drive stop at once, ahead of anything queued, then the zoom stop.
  void stop() override;
  /// Focus and iris (visca::lensPackets()), queued behind the goal's commands; their refusals are lens faults.
  void lens(const LensCommand& command) override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const ViscaCounters& counters() const
  {
    return counters_;
  }

private:
  enum Tag
  {
    ADDRESS_SET,
    IF_CLEAR,
    SEQUENCE_RESET,
    PAN_TILT_INQUIRY,
    ZOOM_INQUIRY,
    COMMAND,
    PROBE,  ///< a command sent to learn whether a camera that answers no inquiry answers commands
    LENS,   ///< a focus or iris command: its refusal is a lens fault, never the goal's
    FOCUS_MODE_INQUIRY,
    FOCUS_INQUIRY,
    IRIS_INQUIRY,
  };
  /// The command a socket runs: the node command it serves, and its bytes (for messages).
  struct SocketUse
  {
    std::uint64_t command = 0;
    std::string bytes;
    bool lens = false;  ///< a lens command's (LENS)
  };

  void queueSetup();
  void queuePacket(const visca::Packet& packet, Tag tag, bool poll = false);
  /// Writes a request: bare, or in a VISCA over IP message with the next sequence number.
  void write(const std::string& bytes);
  void readPackets(const std::uint8_t* data, std::size_t size);
  void handle(const visca::Packet& packet);
  void handleAnswer(const visca::Reply& reply, Tag tag);
  void handleError(const visca::Reply& reply);
  void handleControl(const visca::Packet& payload);
  void setUpDone();
  void updateSplitterCounters();
  std::string refusal(const std::string& bytes, std::uint8_t error) const;
  /// A request had no reply in time (the channel's on_timeout): what a dialect learns from it.
  void onReplyTimeout(const TransactionChannel::Request& lost);
  /// A reply from \p address: true if it is the camera's (counted and warned once when another address is taken).
  bool fromCamera(std::uint8_t address);
  /// The camera refused the variable zoom drive \p refused: drive it with the standard one from now on. False where
  /// the settings keep the variable drive.
  bool fallBackToStandardZoom(const TransactionChannel::Request& refused);
  /// The camera answers commands but no inquiries: run it without feedback.
  void runWithoutFeedback();
  /// The packet of a zoom drive at \p speed (1..8, signed) as this camera takes it.
  visca::Packet zoomDrivePacket(int speed) const;
  /// The next lens inquiry in turn, if one is due (visca_protocol_lens.cpp).
  void pollLens();
  static bool isLensInquiry(int tag)
  {
    return tag == FOCUS_MODE_INQUIRY || tag == FOCUS_INQUIRY || tag == IRIS_INQUIRY;
  }
  /// The answer \p reply fits the lens inquiry \p tag.
  bool answersLensInquiry(const visca::Reply& reply, int tag) const;
  void handleLensAnswer(const visca::Reply& reply, Tag tag);
  /// The camera refused a lens inquiry (\p error), or answered none of several (\p error 0): that function (every
  /// function on silence) is not polled any more, said in one warning.
  void stopLensPolling(Tag tag, std::uint8_t error);
  /// Without feedback: repeats the last pan-tilt drive (a stop at first) now and then, the ACK keeping the link alive.
  void keepAlive();
  /// Completes the request on the wire (see TransactionChannel::complete()) and forgets its sequence number; notes
  /// what a VISCA over IP reply says of the camera's sequence numbers.
  std::optional<TransactionChannel::Request>
  completeRequest(const std::function<bool(const TransactionChannel::Request&)>& answers);

  const ViscaSettings settings_;
  const bool serial_;
  const bool any_reply_address_;  ///< settings_.any_reply_address, or the link's default
  DeviceSession& session_;
  TransactionChannel channel_;
  visca::PacketSplitter splitter_;
  std::uint64_t dropped_reported_ = 0;  ///< of splitter_'s dropped bytes, those reported to the session
  ViscaCounters counters_;

  // I/O thread only.
  bool set_up_ = false;
  std::uint32_t sequence_ = 0;
  /// VISCA over IP: the sequence numbers of the requests on the wire, oldest first (as the channel's).
  std::deque<std::uint32_t> wire_sequences_;
  /// VISCA over IP: those of the requests that were on the wire at the last reply timeout, oldest first, while the
  /// channel still awaits their late replies (until the next request goes out).
  std::deque<std::uint32_t> overdue_sequences_;
  std::uint32_t reply_sequence_ = 0;  ///< VISCA over IP: the sequence number of the datagram being read
  // What the camera's dialect turned out to be, kept across reconnections (the camera stays the same). Atomic: read
  // by capabilities() and diagnostics() on other threads.
  std::atomic<bool> feedback_;       ///< false: the camera answers no inquiries
  std::atomic<bool> variable_zoom_;  ///< false: the standard zoom drive
  std::atomic<std::uint32_t> sequence_cycle_;
  std::atomic<int> reply_address_{ -1 };  ///< the other address the camera answers from; -1: its own
  std::atomic<bool> focus_polled_;        ///< the focus mode and position are asked (until the camera refuses)
  std::atomic<bool> iris_polled_;         ///< the iris position is asked
  std::uint32_t inquiry_answers_ = 0;     ///< answers to inquiries (on any connection)
  // Learning on this connection.
  std::uint32_t inquiry_timeouts_ = 0;  ///< inquiries without answer since the last answer
  bool probe_answered_ = false;         ///< a camera that answered no inquiry answered a command: one more inquiry
  std::uint32_t reset_timeouts_ = 0;    ///< VISCA over IP: sequence resets without answer in a row
  std::uint32_t highest_answered_ = 0;  ///< VISCA over IP: the highest sequence number answered
  std::uint32_t timeouts_beyond_ = 0;   ///< VISCA over IP: requests unanswered in a row, numbered above it
  bool replies_echo_sequence_ = true;   ///< false once a reply carried another sequence number than its request
  visca::Packet keep_alive_;            ///< without feedback: the pan-tilt drive repeated to keep the link alive
  TimePoint kept_alive_at_{};
  std::array<std::optional<SocketUse>, 16> sockets_;
  AxisValues polled_{ { 0.0, 0.0, 1.0 } };
  PollRound round_;            ///< the pan-tilt answer, then the zoom answer (where the model has zoom)
  std::size_t lens_turn_ = 0;  ///< the next lens inquiry: focus mode, focus position, iris position
  TimePoint lens_polled_at_{};
  std::uint32_t lens_timeouts_ = 0;     ///< lens inquiries without answer in a row
  std::vector<visca::Packet> packets_;  ///< reused for every read
};

}  // namespace ptz_action_server
