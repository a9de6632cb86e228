/**
 * \file
 * \brief A VISCA camera emulator on a pseudo-terminal, a TCP server or a UDP socket (raw or with Sony's VISCA over IP
 * header), over the simulated motion model, with the dialects of the cameras in the field as modes.
 */
#pragma once

#include <array>
#include <random>
#include <string>
#include <vector>

#include "ptz_action_server/core/sim/sim_lens_model.h"
#include "ptz_action_server/core/visca/visca_codec.h"
#include "ptz_action_server/core/visca/visca_lens.h"
#include "ptz_action_server/core/visca/visca_model.h"
#include "ptz_action_server/core/visca/visca_protocol.h"
#include "ptz_action_server/emulators/line_emulator.h"

namespace ptz_action_server
{
/// What cameras in the field do that the standard does not say (doc/backends/visca.md, "Dialects").
struct ViscaEmulatorModes
{
  /// PTZOptics G2 timing (wire transcripts of five cameras): pan-tilt position inquiries answered in 88-123 ms, zoom
  /// inquiries (and the other inquiries) in 26-58 ms, commands acknowledged in 28-89 ms.
  bool g2_latency = false;
  /// The first byte of every reply; 0: the camera's own (`90` for address 1). PTZOptics G3 firmware: `A0`.
  std::uint8_t reply_header = 0;
  /// NewTek NDI PTZ1: VISCA over IP sequence numbers 1..3 only (others unread, the reset's 0 too), every reply
  /// numbered 1.
  bool ndi_sequence = false;
  /// The standard zoom drive only (`02`, `03`): the variable one (`2p`, `3p`) is a syntax error.
  bool standard_zoom_only = false;
  /// Commands answered, inquiries never.
  bool no_inquiries = false;
  /// udp: replies go to this port of the sender's host, whatever port the request came from (Sony: 52381); 0: to
  /// the sender.
  std::uint16_t reply_port = 0;
};

struct ViscaEmulatorConfig
{
  DevicePortConfig port;                     ///< pty (RS-232), tcp or udp (tick_period: how often completions go out)
  ViscaFraming framing = ViscaFraming::RAW;  ///< sony_ip: udp only
  std::uint8_t address = 1;
  visca::ViscaModel model;  ///< units, ranges, speeds, how positions are written; the motion model follows them
  ViscaEmulatorModes modes;
  visca::ViscaLens lens;     ///< which of focus and iris it has, and their numbers
  SimLensConfig lens_model;  ///< how its focus and iris move (present follows lens)

  /// Turns on the mode \p mode (one of MODES); false for another name.
  bool applyMode(const std::string& mode);
  static const char* const MODES;  ///< the names, for help texts
};

/// A packet as it reached the camera.
struct ReceivedPacket
{
  TimePoint at;  ///< when its last byte had crossed the line
  visca::Packet packet;
  bool control = false;        ///< VISCA over IP control message (packet holds its payload)
  std::uint32_t sequence = 0;  ///< VISCA over IP only
};

/// What the emulator counted.
struct ViscaEmulatorCounters
{
  std::uint64_t syntax_errors = 0;
  std::uint64_t buffer_full = 0;
  std::uint64_t sequence_errors = 0;
  std::uint64_t bad_datagrams = 0;
  std::uint64_t unread_sequences = 0;   ///< ndi_sequence: datagrams numbered outside 1..3, unread
  std::uint64_t inquiries_ignored = 0;  ///< no_inquiries
};

/**
 * \brief Speaks VISCA as a Sony-style camera: the address set and IF_Clear broadcasts (also as VISCA over IP device
 * setting commands, payload type 0120); two command sockets (ACK, then completion when a position is reached, at
 * once for drives and stops; a third command while both run: buffer full); a pan-tilt (or zoom) command replaces the
 * pan-tilt (zoom) command still running, which completes then; cancel (`8x 2y FF`: command cancelled, the axes
 * decelerate; an idle socket: no socket); the addressed IF_Clear (`z0 50 FF`); the position, zoom, power and version
 * inquiries; positions in the model's nibbles and speed form; out-of-range positions, unknown packets or bad speed
 * bytes: syntax error. Over VISCA over IP it checks sequence numbers (each above the last, until a reset, whose own
 * number it ignores) and answers `0F 01` otherwise; every reply carries the number of the message it answers.
 */
class ViscaEmulator : public LineEmulator<ReceivedPacket>
{
public:
  explicit ViscaEmulator(const ViscaEmulatorConfig& config);
  ~ViscaEmulator() override;

  ViscaEmulatorCounters counters() const;
  visca::SplitterCounters splitterCounters() const;
  /// What the camera received, classified (visca_emulator_classify.cpp): inquiries, the pan-tilt drive's stop, the
  /// pan-tilt and zoom commands that move it, and the rest (broadcasts, IF_Clear, cancels, the zoom's stop, VISCA over
  /// IP control messages); each with its bytes' wire time.
  std::vector<ClassifiedCommand> classify() const;
  /// As if another controller had used the camera up to \p sequence: the next lower number is a sequence error.
  void skipSequence(std::uint32_t sequence);
  /// The lens now: focus and iris modes and positions (shares 0..1), for tests.
  LensState lensState() const;

  /// The s a G2 takes to answer \p packet (ViscaEmulatorModes::g2_latency), drawn from \p random: 0 for what it
  /// does not answer (a control message).
  static double g2Latency(const visca::Packet& packet, std::mt19937& random);

private:
  enum class Group
  {
    PAN_TILT,
    ZOOM,
    LENS,
  };
  struct Socket
  {
    bool busy = false;
    Group group = Group::PAN_TILT;
    bool until_rest = false;  ///< completes when its axes rest (positions); else at once
    std::uint32_t sequence = 0;
  };
  using Replies = std::vector<visca::Packet>;

  void powerUp() override;
  double thinkingTime(const std::uint8_t* data, std::size_t size) override;
  void onBytes(const std::uint8_t* data, std::size_t size, TimePoint arrived_at);
  void onDatagram(const std::uint8_t* data, std::size_t size, TimePoint at, Replies& replies);
  void onTick();
  /// Executes a packet; appends the replies (raw VISCA) to \p replies.
  void execute(const visca::Packet& packet, TimePoint at, std::uint32_t sequence, Replies& replies);
  /// The broadcasts (address set, IF_Clear): true if \p packet was one.
  bool executeBroadcast(const visca::Packet& packet, Replies& replies);
  void executeCommand(const visca::Packet& packet, TimePoint at, std::uint32_t sequence, Replies& replies);
  /// Runs a command; false if its parameters are illegal (then nothing moved).
  bool run(const visca::Packet& packet, TimePoint at, bool& until_rest);
  bool runPosition(const visca::Packet& packet, TimePoint at);
  bool runZoomDrive(std::uint8_t drive, TimePoint at);
  /// A CAM_Focus, CAM_Iris or CAM_AE packet (visca_lens.h).
  static bool isLensPacket(const visca::Packet& packet);
  /// config.lens_model, with the functions config.lens has.
  static SimLensConfig lensModelConfig(const ViscaEmulatorConfig& config);
  /// Runs one on the lens model: 0, or the error it answers (syntax; not executable: a manual focus command in auto
  /// focus, an iris position in automatic exposure, as Sony's cameras refuse them).
  std::uint8_t runLens(const visca::Packet& packet, TimePoint at);
  void answerInquiry(const visca::Packet& packet, TimePoint at, Replies& replies);
  /// CAM_FocusModeInq, CAM_FocusPosInq, CAM_IrisPosInq from the lens model: their data appended to \p answer; false
  /// for another packet, or one of a function the camera lacks (it answers a syntax error, as a camera without it).
  bool answerLensInquiry(const visca::Packet& packet, TimePoint at, visca::Packet& answer) const;
  visca::Packet reply(std::uint8_t kind, std::initializer_list<std::uint8_t> rest = {}) const;
  /// Sends raw VISCA replies (wrapped as replies to \p sequence over VISCA over IP).
  void sendAll(const Replies& replies, std::uint32_t sequence, std::uint16_t type = visca::IP_REPLY);

  const ViscaEmulatorConfig config_;
  std::mt19937 latency_random_{ 2023 };  ///< the port's thread only
  // Guarded by mutex_.
  visca::PacketSplitter splitter_;
  std::array<Socket, 3> sockets_{};  ///< 1 and 2 (0 unused)
  std::uint32_t last_sequence_ = 0;
  std::string reply_host_;  ///< udp: the host of the last sender, for reply_port
  ViscaEmulatorCounters counters_;
  SimLensModel lens_model_;
};

}  // namespace ptz_action_server
