/**
 * \file
 * \brief A PtzBackend that passes every call to another one: the base of decorators around a backend.
 */
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief Forwards every PtzBackend call to the wrapped backend; a decorator overrides only what it changes.
 *
 * Thread-safe as the wrapped backend is.
 */
class ForwardingBackend : public PtzBackend
{
public:
  /// Owns (shares) \p inner. Throws ConfigError if it is null.
  explicit ForwardingBackend(std::shared_ptr<PtzBackend> inner) : inner_(std::move(inner))
  {
    if (!inner_)
    {
      throw ConfigError("a backend wrapper needs a backend to wrap");
    }
  }

  std::string name() const override
  {
    return inner_->name();
  }
  Capabilities capabilities() const override
  {
    return inner_->capabilities();
  }
  void start() override
  {
    inner_->start();
  }
  void goTo(const AxisValues& position) override
  {
    inner_->goTo(position);
  }
  void goToAtSpeed(const AxisValues& position, const AxisValues& speed) override
  {
    inner_->goToAtSpeed(position, speed);
  }
  void moveAtVelocity(const AxisValues& velocity) override
  {
    inner_->moveAtVelocity(velocity);
  }
  void stop() override
  {
    inner_->stop();
  }
  void aimInView(const ViewTarget& target) override
  {
    inner_->aimInView(target);
  }
  PtzSample sample() const override
  {
    return inner_->sample();
  }
  std::string lastFault() const override
  {
    return inner_->lastFault();
  }
  void lens(const LensCommand& command) override
  {
    inner_->lens(command);
  }
  LensState lensState() const override
  {
    return inner_->lensState();
  }
  std::string lastLensFault() const override
  {
    return inner_->lastLensFault();
  }
  std::string lastLinkLoss() const override
  {
    return inner_->lastLinkLoss();
  }
  bool setSampleListener(SampleListener listener) override
  {
    return inner_->setSampleListener(std::move(listener));
  }
  std::vector<std::string> takeWarnings() override
  {
    return inner_->takeWarnings();
  }
  void diagnostics(std::vector<DiagnosticValue>& values) const override
  {
    inner_->diagnostics(values);
  }

protected:
  /// The wrapped backend.
  PtzBackend& inner() const
  {
    return *inner_;
  }

private:
  const std::shared_ptr<PtzBackend> inner_;
};

}  // namespace ptz_action_server
