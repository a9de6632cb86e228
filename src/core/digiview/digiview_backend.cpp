#include "ptz_action_server/core/digiview/digiview_backend.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <boost/asio/connect.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/write.hpp>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
using boost::asio::ip::tcp;
using boost::asio::ip::udp;
using namespace digiview;

constexpr double NARROWEST_FOV = 0.1;  ///< rad, DigiView's smallest field of view
constexpr std::uint32_t STATE_INTERVAL_MS = MIN_INTERVAL_MS;
constexpr std::size_t MAX_OUTSTANDING = 64;
constexpr double ZOOM_RATE = 2.0;   ///< X/s of velocity goals on zoom
constexpr double QUIT_GRACE = 0.5;  ///< s the destructor waits for QUIT to go out

std::chrono::steady_clock::duration seconds(double value)
{
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(value));
}

bool sameCamera(const CameraId& a, const CameraId& b)
{
  return a.stream_name == b.stream_name && a.cam_id == b.cam_id;
}
}  // namespace

DigiViewBackend::DigiViewBackend(const DigiViewConfig& config, std::shared_ptr<const Clock> clock)
  : config_(config)
  , clock_(std::move(clock))
  , tcp_(context_)
  , udp_(context_)
  , reconnect_timer_(context_)
  , velocity_timer_(context_)
  , link_timer_(context_)
  , motion_(config.settle_window)
{
}

DigiViewBackend::~DigiViewBackend()
{
  if (!thread_.joinable())
  {
    return;
  }
  // Say goodbye: cancel the subscriptions and send QUIT, then close once they are out (or after a grace time).
  boost::asio::post(context_, [this] {
    reconnect_timer_.cancel();
    velocity_timer_.cancel();
    link_timer_.cancel();
    if (connected_)
    {
      for (ParamType param : { ParamType::CAM_TARGETING, ParamType::CAM_OPTICS_AND_CONTROL })
      {
        send(packInterval(IntervalRequest{ param, camera(), 0 }));
      }
      send(packBare(MessageType::QUIT, ParamType::SYSTEM_STATUS));
    }
    quitting_ = true;
    if (write_queue_.empty())
    {
      context_.stop();
      return;
    }
    // The last write's completion stops the loop; this is the fallback if DigiView never takes the bytes.
    link_timer_.expires_after(seconds(QUIT_GRACE));
    link_timer_.async_wait([this](const boost::system::error_code& error) {
      if (!error)
      {
        context_.stop();
      }
    });
  });
  thread_.join();
}

double DigiViewBackend::zoomMax() const
{
  return config_.zoom_max > 0.0 ? config_.zoom_max : config_.fov_wide / NARROWEST_FOV;
}

Capabilities DigiViewBackend::capabilities() const
{
  Capabilities capabilities;
  capabilities.axes[PAN] = AxisCapability{ true, { -M_PI, M_PI }, config_.slew_rate, config_.acceleration };
  capabilities.axes[TILT] =
      AxisCapability{ true, { -M_PI / 2.0, M_PI / 2.0 }, config_.slew_rate, config_.acceleration };
  capabilities.axes[ZOOM] = AxisCapability{ true, { 1.0, zoomMax() }, ZOOM_RATE, 0.0 };
  return capabilities;
}

CameraId DigiViewBackend::camera() const
{
  return CameraId{ config_.stream_name, config_.cam_id };
}

void DigiViewBackend::start()
{
  thread_ = std::thread([this] {
    auto work = boost::asio::make_work_guard(context_);
    context_.run();
  });
  boost::asio::post(context_, [this] {
    connect();
    superviseLink();
  });
  std::unique_lock<std::mutex> lock(mutex_);
  const bool ready = described_.wait_for(lock, seconds(config_.startup_timeout), [this] {
    return !startup_problem_.empty() || (stream_described_ && state_seen_);
  });
  if (!ready || !startup_problem_.empty())
  {
    const std::string reason = !startup_problem_.empty() ? startup_problem_ :
                               !last_error_.empty()      ? last_error_ :
                               counters_.connections > 0 ? "no VIDEO_OUTPUT or CAM_TARGETING for that view" :
                                                           "not connected";
    throw BackendError(
        formatText("DigiView at %s:%u (%s), view '%s' camera %u is not available within %.1f s: %s",
                   config_.host.c_str(), config_.port, config_.transport == DigiViewTransport::TCP ? "tcp" : "udp",
                   config_.stream_name.c_str(), config_.cam_id, config_.startup_timeout, reason.c_str()));
  }
}

void DigiViewBackend::connect()
{
  boost::system::error_code error;
  const auto address = boost::asio::ip::make_address(config_.host, error);
  if (error)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    startup_problem_ = "host must be an IP address: " + error.message();
    described_.notify_all();
    return;
  }
  if (config_.transport == DigiViewTransport::UDP)
  {
    udp_.open(udp::v4(), error);
    if (!error)
    {
      udp_.connect(udp::endpoint(address, config_.port), error);  // only this peer's datagrams are taken
    }
    if (error)
    {
      onDisconnected("udp: " + error.message());
      return;
    }
    onConnected();
    return;
  }
  tcp_.async_connect(tcp::endpoint(address, config_.port), [this](const boost::system::error_code& connect_error) {
    if (connect_error == boost::asio::error::operation_aborted)
    {
      return;
    }
    if (connect_error)
    {
      onDisconnected("connect: " + connect_error.message());
      return;
    }
    tcp_.set_option(tcp::no_delay(true));
    onConnected();
  });
}

void DigiViewBackend::onConnected()
{
  connected_ = true;
  backoff_ = 0.0;
  read_size_ = 0;
  outstanding_sets_.clear();
  hold_on_state_ = ever_connected_;  // after a reconnection the view is held where it is: no old goal goes on
  ever_connected_ = true;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++counters_.connections;
  }
  send(packGet(ParamType::VIDEO_OUTPUT, camera()));
  send(packGet(ParamType::SYSTEM_STATUS, camera()));
  for (ParamType param : { ParamType::CAM_TARGETING, ParamType::CAM_OPTICS_AND_CONTROL })
  {
    send(packGet(param, camera()));
    send(packInterval(IntervalRequest{ param, camera(), STATE_INTERVAL_MS }));
  }
  startRead();
}

void DigiViewBackend::onDisconnected(const std::string& reason)
{
  const bool was_connected = connected_;
  connected_ = false;
  write_queue_.clear();
  outstanding_sets_.clear();
  velocity_timer_.cancel();
  boost::system::error_code ignored;
  tcp_.close(ignored);
  udp_.close(ignored);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    last_error_ = reason;
    if (was_connected && link_was_up_)
    {
      link_was_up_ = false;
      ++counters_.link_losses;
    }
  }
  backoff_ = backoff_ <= 0.0 ? config_.reconnect_min : std::min(backoff_ * 2.0, config_.reconnect_max);
  reconnect_timer_.expires_after(seconds(backoff_));
  reconnect_timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error)
    {
      connect();
    }
  });
}

void DigiViewBackend::startRead()
{
  auto on_read = [this](const boost::system::error_code& error, std::size_t size) {
    if (error == boost::asio::error::operation_aborted || !connected_)
    {
      return;
    }
    if (error)
    {
      if (config_.transport == DigiViewTransport::UDP && error == boost::asio::error::connection_refused)
      {
        startRead();  // an ICMP error from an earlier datagram: DigiView is not up yet
        return;
      }
      onDisconnected("read: " + error.message());
      return;
    }
    if (config_.transport == DigiViewTransport::UDP)
    {
      handle(read_buffer_.data(), size);  // one message per datagram
    }
    else
    {
      // A stream: cut it into 80-byte messages.
      read_size_ += size;
      std::size_t offset = 0;
      while (read_size_ - offset >= MESSAGE_SIZE)
      {
        handle(read_buffer_.data() + offset, MESSAGE_SIZE);
        offset += MESSAGE_SIZE;
      }
      std::copy(read_buffer_.begin() + offset, read_buffer_.begin() + read_size_, read_buffer_.begin());
      read_size_ -= offset;
    }
    if (connected_)
    {
      startRead();
    }
  };
  if (config_.transport == DigiViewTransport::UDP)
  {
    udp_.async_receive(boost::asio::buffer(read_buffer_), on_read);
  }
  else
  {
    tcp_.async_read_some(boost::asio::buffer(read_buffer_.data() + read_size_, read_buffer_.size() - read_size_),
                         on_read);
  }
}

void DigiViewBackend::handle(const std::uint8_t* bytes, std::size_t size)
{
  Message message;
  const UnpackError error = Message::unpack(bytes, size, message);
  const TimePoint now = clock_->now();
  std::unique_lock<std::mutex> lock(mutex_);
  ++counters_.messages;
  if (error != UnpackError::NONE)
  {
    ++counters_.bad[static_cast<std::size_t>(error)];
    return;
  }
  switch (message.message_type)
  {
    case MessageType::CURRENT_PARAMETERS: {
      if (message.param_type == ParamType::VIDEO_OUTPUT)
      {
        VideoOutput output;
        if (unpackVideoOutput(message, output) == UnpackError::NONE && output.stream_name == config_.stream_name)
        {
          num_user_views_ = output.num_user_views;
          stream_described_ = true;
          if (config_.cam_id >= num_user_views_)
          {
            startup_problem_ = formatText("stream '%s' has %u user view(s), so cam_id %u does not exist",
                                          config_.stream_name.c_str(), num_user_views_, config_.cam_id);
          }
          described_.notify_all();
        }
        return;
      }
      if (message.param_type == ParamType::SYSTEM_STATUS)
      {
        SystemStatus status;
        if (unpackSystemStatus(message, status) == UnpackError::NONE)
        {
          system_status_ = status.status;
        }
        return;
      }
      bool ours = false;
      if (message.param_type == ParamType::CAM_TARGETING)
      {
        CamTargeting targeting;
        ours = unpackTargeting(message, targeting) == UnpackError::NONE && sameCamera(targeting.camera, camera());
        if (ours)
        {
          reported_[PAN] = targeting.yaw;
          reported_[TILT] = targeting.pitch;
        }
      }
      else if (message.param_type == ParamType::CAM_OPTICS_AND_CONTROL)
      {
        CamOpticsAndControl optics;
        ours = unpackOptics(message, optics) == UnpackError::NONE && sameCamera(optics.camera, camera()) &&
               optics.fov > 0.0;
        if (ours)
        {
          reported_[ZOOM] = config_.fov_wide / optics.fov;
        }
      }
      if (!ours)
      {
        return;
      }
      const bool recovered = state_seen_ && !linkUpLocked(now);
      ++counters_.states;
      last_state_at_ = now;
      link_was_up_ = true;
      motion_.add(now, reported_);
      const bool first = !state_seen_ && message.param_type == ParamType::CAM_TARGETING;
      state_seen_ = state_seen_ || message.param_type == ParamType::CAM_TARGETING;
      if (first)
      {
        described_.notify_all();
      }
      if ((recovered || hold_on_state_) && message.param_type == ParamType::CAM_TARGETING)
      {
        // Back after a loss: whatever DigiView still does belongs to a goal that has ended. Hold the view.
        hold_on_state_ = false;
        const AxisValues hold = reported_;
        lock.unlock();
        velocity_timer_.cancel();
        sendTargets(hold[PAN], hold[TILT], hold[ZOOM]);
      }
      return;
    }
    case MessageType::ACKNOWLEDGEMENT:
    case MessageType::CHECKSUM_ERROR:
    case MessageType::DATA_ERROR:
    case MessageType::FORBIDDEN:
    case MessageType::UNKNOWN: {
      const auto set = std::find(outstanding_sets_.begin(), outstanding_sets_.end(), message.param_type);
      const bool answers_a_set = set != outstanding_sets_.end();
      if (answers_a_set)
      {
        outstanding_sets_.erase(set);
      }
      if (message.message_type == MessageType::ACKNOWLEDGEMENT)
      {
        ++counters_.acknowledged;
        return;
      }
      ++counters_.refused;
      const std::string reason =
          formatText("DigiView refused %s %s: %s (%s)", answers_a_set ? "SET" : "a request for",
                     toString(message.param_type), toString(message.message_type), describeError(message.message_type));
      last_error_ = reason;
      if (answers_a_set)
      {
        ++fault_count_;
        last_fault_ = reason;
      }
      return;
    }
    case MessageType::QUIT:
      lock.unlock();
      onDisconnected("DigiView sent QUIT");
      return;
    default:
      return;
  }
}

void DigiViewBackend::send(const Message& message)
{
  if (!connected_)
  {
    return;
  }
  Message stamped = message;
  stamped.timestamp = static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
  if (message.message_type == MessageType::SET_PARAMETERS)
  {
    if (outstanding_sets_.size() >= MAX_OUTSTANDING)
    {
      outstanding_sets_.pop_front();  // never answered: forget the oldest
    }
    outstanding_sets_.push_back(message.param_type);
  }
  write_queue_.push_back(stamped.pack());
  if (write_queue_.size() == 1)
  {
    startWrite();
  }
}

void DigiViewBackend::startWrite()
{
  auto on_written = [this](const boost::system::error_code& error, std::size_t) {
    if (error == boost::asio::error::operation_aborted || !connected_)
    {
      return;
    }
    if (error && !(config_.transport == DigiViewTransport::UDP && error == boost::asio::error::connection_refused))
    {
      onDisconnected("write: " + error.message());
      return;
    }
    write_queue_.pop_front();
    if (!write_queue_.empty())
    {
      startWrite();
    }
    else if (quitting_)
    {
      context_.stop();
    }
  };
  const digiview::Bytes& bytes = write_queue_.front();
  if (config_.transport == DigiViewTransport::UDP)
  {
    udp_.async_send(boost::asio::buffer(bytes), on_written);
  }
  else
  {
    boost::asio::async_write(tcp_, boost::asio::buffer(bytes), on_written);
  }
}

void DigiViewBackend::sendTargets(double pan, double tilt, double zoom)
{
  CamTargeting targeting;
  targeting.camera = camera();
  targeting.targeting_mode = 0;  // directional
  targeting.yaw = pan;
  targeting.pitch = tilt;
  targeting.lock_flags = config_.lock_flags;
  send(packTargeting(MessageType::SET_PARAMETERS, targeting));
  CamOpticsAndControl optics;
  optics.camera = camera();
  optics.fov = config_.fov_wide / std::clamp(zoom, 1.0, zoomMax());
  optics.crop_mode = config_.crop_mode;
  send(packOptics(MessageType::SET_PARAMETERS, optics));
}

void DigiViewBackend::goTo(const AxisValues& position)
{
  boost::asio::post(context_, [this, position] {
    velocity_timer_.cancel();
    sendTargets(position[PAN], position[TILT], position[ZOOM]);
  });
}

void DigiViewBackend::moveAtVelocity(const AxisValues& velocity)
{
  if (std::all_of(velocity.begin(), velocity.end(), [](double value) { return value == 0.0; }))
  {
    stop();
    return;
  }
  boost::asio::post(context_, [this, velocity] {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      velocity_origin_ = reported_;
    }
    velocity_ = velocity;
    velocity_started_ = clock_->now();
    velocity_timer_.cancel();
    velocityTick();
  });
}

void DigiViewBackend::velocityTick()
{
  // DigiView has no velocity command: the target moves on from where the view was, at the asked rate.
  const double elapsed = secondsBetween(velocity_started_, clock_->now());
  const Capabilities limits = capabilities();
  AxisValues target{};
  for (Axis axis : ALL_AXES)
  {
    const AxisRange& range = limits.axes[axis].range;
    target[axis] = std::clamp(velocity_origin_[axis] + velocity_[axis] * elapsed, range.min, range.max);
  }
  sendTargets(target[PAN], target[TILT], target[ZOOM]);
  velocity_timer_.expires_after(seconds(config_.velocity_period));
  velocity_timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error)
    {
      velocityTick();
    }
  });
}

void DigiViewBackend::stop()
{
  boost::asio::post(context_, [this] {
    velocity_timer_.cancel();
    // Hold where the view would come to rest: where it is, plus its braking distance if the turn decelerates.
    PtzSample now;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      now.position = reported_;
      motion_.fill(now);
    }
    AxisValues hold = now.position;
    if (config_.acceleration > 0.0)
    {
      for (Axis axis : { PAN, TILT })
      {
        hold[axis] += now.velocity[axis] * std::abs(now.velocity[axis]) / (2.0 * config_.acceleration);
      }
    }
    sendTargets(hold[PAN], hold[TILT], hold[ZOOM]);
  });
}

PtzSample DigiViewBackend::sample() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  PtzSample sample;
  const TimePoint now = clock_->now();
  sample.stamp = now;
  sample.link_up = linkUpLocked(now);
  sample.position = reported_;
  motion_.fill(sample);
  sample.fault_count = fault_count_;
  return sample;
}

std::string DigiViewBackend::lastFault() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return last_fault_;
}

DigiViewCounters DigiViewBackend::counters() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return counters_;
}

void DigiViewBackend::diagnostics(std::vector<DiagnosticValue>& values) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  values.emplace_back("DigiView", formatText("%s:%u (%s)", config_.host.c_str(), config_.port,
                                             config_.transport == DigiViewTransport::TCP ? "tcp" : "udp"));
  values.emplace_back(
      "view", formatText("stream '%s' camera %u of %u", config_.stream_name.c_str(), config_.cam_id, num_user_views_));
  values.emplace_back("system status", std::to_string(system_status_));
  values.emplace_back("connections", std::to_string(counters_.connections));
  values.emplace_back("link losses", std::to_string(counters_.link_losses));
  values.emplace_back("states", std::to_string(counters_.states));
  values.emplace_back("acknowledged", std::to_string(counters_.acknowledged));
  values.emplace_back("refused", std::to_string(counters_.refused));
  for (std::size_t index = 1; index < counters_.bad.size(); ++index)
  {
    values.emplace_back(std::string("dropped: ") + toString(static_cast<UnpackError>(index)),
                        std::to_string(counters_.bad[index]));
  }
  values.emplace_back("last error", last_error_);
}

void DigiViewBackend::superviseLink()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (link_was_up_ && !linkUpLocked(clock_->now()))
    {
      link_was_up_ = false;
      ++counters_.link_losses;
    }
  }
  link_timer_.expires_after(seconds(config_.state_timeout / 2.0));
  link_timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error)
    {
      superviseLink();
    }
  });
}

bool DigiViewBackend::linkUpLocked(TimePoint now) const
{
  return state_seen_ && secondsBetween(last_state_at_, now) <= config_.state_timeout;
}

}  // namespace ptz_action_server
