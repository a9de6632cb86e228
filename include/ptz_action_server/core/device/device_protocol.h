/**
 * \file
 * \brief What a device protocol supplies to the shared device session: a codec and the few decisions only it can
 * make (what to send on connect, how to read what arrives, how to encode goals, what to poll).
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief One device protocol (FLIR, Pelco-D, PanTilt, DigiView, ...) over a DeviceSession.
 *
 * A protocol is built with the session it talks through (see DeviceBackend) and keeps a reference to it. Everything
 * but name(), deviceName(), capabilities() and diagnostics() runs on the session's I/O thread, one call at a time, so
 * a protocol needs no lock for its own state; what diagnostics() reads from other threads is either immutable
 * (settings) or a Counter.
 *
 * The session owns everything protocols have in common: the I/O thread, the link and its reconnection, the state
 * snapshot and motion estimate, link supervision by deadline, the start-up wait and recovery after a loss. A
 * protocol reports what it hears through DeviceSession::reportState(), reportAlive(), reportFault() and ready().
 */
class DeviceProtocol
{
public:
  virtual ~DeviceProtocol() = default;

  /// Names the backend and its protocol in messages and diagnostics: its plugin's name, as backend:= gives it ("flir").
  virtual std::string name() const = 0;
  /// The device, for messages: "a FLIR PTU", "DigiView view 'main' camera 0".
  virtual std::string deviceName() const = 0;
  /// What the protocol knows of the device from its settings. Called once, before the session starts; a protocol
  /// that learns more from the device publishes it with DeviceSession::setCapabilities().
  virtual Capabilities capabilities() const = 0;

  /// The link is open (again): what to send first. Whatever the device knew of this client may be gone.
  virtual void onConnected() = 0;
  /// Bytes from the device (on a datagram link: one whole datagram).
  virtual void onReceived(const std::uint8_t* data, std::size_t size) = 0;
  /// The link closed; nothing can be sent until onConnected().
  virtual void onDisconnected()
  {
  }
  /// Every poll period while the link is open: ask for state, resend what must be refreshed.
  virtual void poll()
  {
  }

  /// The node's commands (see PtzBackend); each supersedes the previous one.
  virtual void goTo(const AxisValues& position) = 0;
  /// goTo() at \p speed per axis (rad/s, X/s; 0: the device's own), on a protocol that takes a speed with its
  /// absolute move (its capabilities().speed says which axes); by default the speed is not the device's business.
  virtual void goToAtSpeed(const AxisValues& position, const AxisValues& speed)
  {
    (void)speed;
    goTo(position);
  }
  virtual void moveAtVelocity(const AxisValues& velocity) = 0;
  virtual void stop() = 0;
  /// Focus and iris (see PtzBackend::lens(); the node checked it against capabilities().lens). Not a node command:
  /// it leaves DeviceSession::currentCommand() as it was, and its refusals go to DeviceSession::lens(), never to the
  /// goal's faults. By default ignored (a device without a lens).
  virtual void lens(const LensCommand& command)
  {
    (void)command;
  }
  /// A point of the device's own picture (PtzBackend::aimInView()), for protocols whose capabilities say they can.
  virtual void aimInView(const ViewTarget& target)
  {
    (void)target;
  }
  /// The device answers again after a loss: whatever it still does belongs to a goal that has ended. Keep it
  /// where it is (by default, stop()).
  virtual void hold()
  {
    stop();
  }
  /// The session is closing: a last word to the device, if the protocol has one.
  virtual void shutdown()
  {
  }
  /// The session closes for good (after shutdown()'s words are out or the grace time is over; the link is closed):
  /// cancel every timer of the protocol. The I/O thread is shared with other sessions, so from here on no handler of
  /// the protocol may start anything new (check DeviceSession::closing() in timer handlers that re-arm).
  virtual void onClosing()
  {
  }

  /// Settings and counters for the node's diagnostics. Any thread.
  virtual void diagnostics(std::vector<DiagnosticValue>& values) const
  {
    (void)values;
  }
};

}  // namespace ptz_action_server
