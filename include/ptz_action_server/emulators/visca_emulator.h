/**
 * \file
 * \brief A VISCA camera emulator on a pseudo-terminal, a TCP server or a UDP socket (raw or with Sony's VISCA over IP
 * header), over the simulated motion model.
 */
#pragma once

#include <array>
#include <vector>

#include "ptz_action_server/core/visca/visca_codec.h"
#include "ptz_action_server/core/visca/visca_model.h"
#include "ptz_action_server/core/visca/visca_protocol.h"
#include "ptz_action_server/emulators/line_emulator.h"

namespace ptz_action_server
{
struct ViscaEmulatorConfig
{
  DevicePortConfig port;                     ///< pty (RS-232), tcp or udp (tick_period: how often completions go out)
  ViscaFraming framing = ViscaFraming::RAW;  ///< sony_ip: udp only
  std::uint8_t address = 1;
  visca::ViscaModel model;  ///< units, ranges, speeds; the motion model follows them
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
};

/**
 * \brief Speaks VISCA as a Sony-style camera: the address set and IF_Clear broadcasts; two command sockets (ACK, then
 * completion when a position is reached, at once for drives and stops; a third command while both run: buffer full);
 * a pan-tilt (or zoom) command replaces the pan-tilt (zoom) command still running, which completes then; cancel
 * (`8x 2y FF`: command cancelled, the axes decelerate; an idle socket: no socket); the position and zoom inquiries;
 * out-of-range positions, unknown packets or bad speed bytes: syntax error. Over VISCA over IP it checks sequence
 * numbers (each above the last, until a reset) and answers `0F 01` otherwise.
 */
class ViscaEmulator : public LineEmulator<ReceivedPacket>
{
public:
  explicit ViscaEmulator(const ViscaEmulatorConfig& config);
  ~ViscaEmulator() override;

  ViscaEmulatorCounters counters() const;
  visca::SplitterCounters splitterCounters() const;
  /// As if another controller had used the camera up to \p sequence: the next lower number is a sequence error.
  void skipSequence(std::uint32_t sequence);

private:
  enum class Group
  {
    PAN_TILT,
    ZOOM,
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
  void onBytes(const std::uint8_t* data, std::size_t size, TimePoint arrived_at);
  void onDatagram(const std::uint8_t* data, std::size_t size, TimePoint at, Replies& replies);
  void onTick();
  /// Executes a packet; appends the replies (raw VISCA) to \p replies.
  void execute(const visca::Packet& packet, TimePoint at, std::uint32_t sequence, Replies& replies);
  void executeCommand(const visca::Packet& packet, TimePoint at, std::uint32_t sequence, Replies& replies);
  /// Runs a command; false if its parameters are illegal (then nothing moved).
  bool run(const visca::Packet& packet, TimePoint at, bool& until_rest);
  void answerInquiry(const visca::Packet& packet, TimePoint at, Replies& replies);
  visca::Packet reply(std::uint8_t kind, std::initializer_list<std::uint8_t> rest = {}) const;
  /// Sends raw VISCA replies (wrapped as replies to \p sequence over VISCA over IP).
  void sendAll(const Replies& replies, std::uint32_t sequence, std::uint16_t type = visca::IP_REPLY);

  const ViscaEmulatorConfig config_;
  // Guarded by mutex_.
  visca::PacketSplitter splitter_;
  std::array<Socket, 3> sockets_{};  ///< 1 and 2 (0 unused)
  std::uint32_t last_sequence_ = 0;
  ViscaEmulatorCounters counters_;
};

}  // namespace ptz_action_server
