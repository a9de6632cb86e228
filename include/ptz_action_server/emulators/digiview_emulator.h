/**
 * \file
 * \brief A DigiView emulator: answers the messages of format 0.5, 1.0, 1.1 or 1.2 over TCP or UDP, angles in either
 * unit, with virtual views that slew.
 */
#pragma once

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ptz_action_server/core/transport/link.h"
#include "ptz_action_server/emulators/ports/device_port.h"
#include "ptz_action_server/emulators/emulator_faults.h"
#include "ptz_action_server/emulators/ports/received_log.h"
#include "ptz_action_server/core/digiview/digiview_codec.h"
#include "ptz_action_server/core/sim/sim_device_model.h"

namespace ptz_action_server
{
struct DigiViewEmulatorConfig
{
  std::string host = "127.0.0.1";
  std::uint16_t port = 0;              ///< 0: an ephemeral port (see port())
  LinkKind transport = LinkKind::TCP;  ///< TCP or UDP
  /// The format it speaks (0.5: 80-byte messages, 1.0 and 1.1: 88, 1.2: 96), the unit of its angles (the format's
  /// documented one unless set), and what it takes for a checksum from its clients.
  digiview::Wire wire;
  /// false: every message it sends carries a checksum byte of 0, as from a DigiView built on the published helpers,
  /// which never fill it.
  bool fill_checksum = true;
  std::vector<std::string> streams{ "main" };  ///< names of at most nameSizeOf(format) characters
  std::uint8_t layout_mode = 4;                ///< 4: four user views in a 2x2 grid
  double slew_rate = 1.0;                      ///< rad/s a view turns at
  double acceleration = 4.0;                   ///< rad/s^2
  double fov_rate = 1.0;                       ///< rad/s the field of view changes at
  double initial_fov = 1.2;                    ///< rad
};

/// A message as it reached the emulator.
struct ReceivedMessage
{
  TimePoint at;
  digiview::UnpackError error = digiview::UnpackError::NONE;
  bool unverified = false;    ///< accepted with a checksum byte of 0 (ChecksumRule::ZERO_ACCEPTED)
  digiview::Message message;  ///< valid when error is NONE
};

/**
 * \brief Behaves as DigiView does towards a PTZ client.
 *
 * Speaks one format (config.wire), cutting a TCP stream by its size. ACKNOWLEDGEMENT for accepted SETs (CAM_TARGETING
 * in directional mode, absolute or delta; CAM_OPTICS_AND_CONTROL; from 1.1 on SYSTEM_STATUS RUNNING or HALT, the only
 * SET its documentation gives it), CURRENT_PARAMETERS for GETs (SYSTEM_STATUS, VIDEO_OUTPUT, CAM_TARGETING,
 * CAM_OPTICS_AND_CONTROL), periodic CURRENT_PARAMETERS for subscriptions (0.5: GET_INTERVAL, answered by its reports
 * only; from 1.0 on a GET with interval_ms, answered at once too; minIntervalOf(format) or more subscribes, 0 cancels,
 * a request with less is ignored, or in 1.2 answered once), CHECKSUM_ERROR for a bad checksum, DATA_ERROR for data out
 * of range, UNKNOWN for types it does not know or model, FORBIDDEN for SETs while told to refuse, and QUIT closes the
 * connection. Requests about an unknown stream or camera are ignored, as the seed says. Halted (1.1 on), it reports
 * SYSTEM_STATUS HALT and goes on answering and reporting, but its views stop and SETs of a view are acknowledged and
 * not applied (nothing published says more; the emulator's choice). Every client is served at once (a session per TCP
 * connection or UDP peer). Its DevicePort owns the I/O thread; subscriptions are kept on its tick.
 */
class DigiViewEmulator : public PushEmulatorFaults
{
public:
  explicit DigiViewEmulator(const DigiViewEmulatorConfig& config);
  ~DigiViewEmulator() override;
  DigiViewEmulator(const DigiViewEmulator&) = delete;
  DigiViewEmulator& operator=(const DigiViewEmulator&) = delete;

  std::uint16_t port() const;

  // setSilent(): the subscriptions pause too.
  /// Endless: every reply is replaced by one byte fewer of the filler 'A': on a stream, a message that never ends and
  /// leaves the stream out of step; in a datagram, noise.
  void setEndless(bool endless) override;
  /// Refuse: every SET is answered FORBIDDEN.
  void setRefuse(bool refuse);
  /// Halted (SYSTEM_STATUS HALT, formats 1.1 and 1.2; a client's SET SYSTEM_STATUS does the same): the views stop
  /// where they are and SETs of a view do nothing until it runs again. Ignored in 0.5 and 1.0, which have no HALT.
  void setHalted(bool halted);
  bool halted() const
  {
    return halted_;
  }
  /// Fault hooks of every view's motion model: a stalled axis accepts every command and silently stays where it is.
  void setFaults(const SimFaults& faults);
  /// Closes every TCP connection (the client sees the connection drop).
  void dropConnections();

  /// What the device received, oldest first.
  ReceivedLog<ReceivedMessage>& received()
  {
    return received_;
  }
  const ReceivedLog<ReceivedMessage>& received() const
  {
    return received_;
  }
  /// What DigiView received, classified (digiview_emulator_classify.cpp): GETs and subscriptions, and the SETs of
  /// CAM_TARGETING that aim a view (with the yaw they aim at; DigiView has no stop: a hold aims the view where it is);
  /// the rest (the optics, the system status, what did not unpack) is other.
  std::vector<ClassifiedCommand> classify() const;
  std::size_t connections() const;

  /// The view's state: yaw, pitch (rad) and field of view (rad, in the zoom slot). Throws for an unknown view.
  PtzSample view(const std::string& stream, std::uint8_t cam_id) const;

private:
  bool faultDrop(bool on) override;                       ///< every TCP connection closed
  void setModelFaults(const SimFaults& faults) override;  ///< every view's

  struct Subscription;
  struct Session;
  using SessionPtr = std::shared_ptr<Session>;

  /// The port's handlers (I/O thread).
  void received(const std::uint8_t* bytes, std::size_t size);
  void tick();
  /// The session of the client a handler runs for (a new one for a new UDP peer).
  SessionPtr session();
  void handle(const SessionPtr& session, const std::uint8_t* bytes, std::size_t size);
  void reply(const SessionPtr& session, const digiview::Message& message);
  /// Forgets \p session; \p disconnect: closes its TCP connection too (QUIT).
  void closeSession(const SessionPtr& session, bool disconnect);
  void subscribe(const SessionPtr& session, const digiview::IntervalRequest& request);
  /// CURRENT_PARAMETERS of \p param for \p camera, or false if there is no such view / param.
  bool current(digiview::ParamType param, const digiview::CameraId& camera, digiview::Message& message);
  SimDeviceModel* model(const digiview::CameraId& camera);

  const DigiViewEmulatorConfig config_;

  std::atomic<bool> endless_{ false };
  std::atomic<bool> refuse_{ false };
  std::atomic<bool> halted_{ false };

  mutable std::mutex mutex_;  ///< guards the models and the session map (which only the I/O thread changes)
  mutable std::map<std::pair<std::string, std::uint8_t>, SimDeviceModel> models_;  ///< mutable: sampling
  ReceivedLog<ReceivedMessage> received_;
  std::map<std::string, SessionPtr> sessions_;  ///< by the client's "host:port"

  std::unique_ptr<DevicePort> port_;  ///< last: its thread starts after everything above exists
};

}  // namespace ptz_action_server
