/**
 * \file
 * \brief The PtzBackend of every device: a DeviceProtocol run by a DeviceSession.
 */
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/device/device_protocol.h"
#include "ptz_action_server/core/device/device_session.h"

namespace ptz_action_server
{
/**
 * \brief A device backend: the session does the I/O and the bookkeeping, the protocol the talking.
 *
 * Every command is queued to the session's I/O thread, where the protocol encodes it; sample() and the other
 * accessors read the session's snapshot. Adding a device means writing a DeviceProtocol (and its codec), not a
 * backend.
 */
class DeviceBackend : public PtzBackend
{
public:
  using ProtocolFactory = std::function<std::unique_ptr<DeviceProtocol>(DeviceSession&)>;

  /// Builds the session on \p link, then the protocol over it with \p make_protocol.
  DeviceBackend(const LinkConfig& link, const DeviceSessionConfig& config, const ProtocolFactory& make_protocol,
                std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  /// Stops the session (after the protocol's last words) before the protocol goes.
  ~DeviceBackend() override;

  std::string name() const override
  {
    return protocol_->name();
  }
  Capabilities capabilities() const override
  {
    return session_->capabilities();
  }
  void start() override
  {
    session_->start();
  }
  void goTo(const AxisValues& position) override;
  void goToAtSpeed(const AxisValues& position, const AxisValues& speed) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  void aimInView(const ViewTarget& target) override;
  PtzSample sample() const override
  {
    return session_->sample();
  }
  /// Queued to the I/O thread beside the commands (DeviceSession::post()): the protocol's lens().
  void lens(const LensCommand& command) override;
  LensState lensState() const override
  {
    return session_->lens().state();
  }
  std::string lastLensFault() const override
  {
    return session_->lens().lastFault();
  }
  std::string lastFault() const override
  {
    return session_->lastFault();
  }
  std::string lastLinkLoss() const override
  {
    return session_->lastLinkLoss();
  }
  std::vector<std::string> takeWarnings() override
  {
    return session_->takeWarnings();
  }
  bool setSampleListener(SampleListener listener) override
  {
    session_->setStateListener(std::move(listener));
    return true;
  }
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const DeviceSession& session() const
  {
    return *session_;
  }
  /// The protocol, for tests and tools that read its counters. Throws std::bad_cast for another protocol.
  template <class Protocol>
  const Protocol& protocol() const
  {
    return dynamic_cast<const Protocol&>(*protocol_);
  }

private:
  std::unique_ptr<DeviceSession> session_;
  std::unique_ptr<DeviceProtocol> protocol_;  ///< after session_: destroyed first, while the session's context lives
};

/// A DeviceBackend running \p Protocol (constructed from \p settings and the session) on \p link.
template <class Protocol, class Settings>
std::unique_ptr<DeviceBackend> makeDeviceBackend(const LinkConfig& link, const DeviceSessionConfig& session,
                                                 const Settings& settings, std::shared_ptr<const Clock> clock)
{
  return std::make_unique<DeviceBackend>(
      link, session, [&settings](DeviceSession& owner) { return std::make_unique<Protocol>(settings, owner); },
      std::move(clock));
}

/**
 * \brief Everything a device backend is built from: its link, its session's timing, its protocol's settings.
 *
 * The defaults are the protocol's (`Protocol::defaultLink()`, `Protocol::defaultSession()`), its settings are
 * `Protocol::Settings`: DeviceConfig<FlirProtocol> is a FLIR PTU on /dev/ttyUSB0 with a 0.25 s reply deadline.
 */
template <class Protocol>
struct DeviceConfig
{
  LinkConfig link = Protocol::defaultLink();
  DeviceSessionConfig session = Protocol::defaultSession();
  typename Protocol::Settings settings;
};

namespace detail
{
template <class Protocol, class = void>
struct HasValidate : std::false_type
{
};
template <class Protocol>
struct HasValidate<Protocol, std::void_t<decltype(Protocol::validate(std::declval<const DeviceConfig<Protocol>&>()))>>
  : std::true_type
{
};
}  // namespace detail

/// A DeviceBackend running \p Protocol as \p config says (checked first by `Protocol::validate`, where it has one).
template <class Protocol>
std::unique_ptr<DeviceBackend> makeDeviceBackend(const DeviceConfig<Protocol>& config,
                                                 std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>())
{
  if constexpr (detail::HasValidate<Protocol>::value)
  {
    Protocol::validate(config);
  }
  return makeDeviceBackend<Protocol>(config.link, config.session, config.settings, std::move(clock));
}

}  // namespace ptz_action_server
