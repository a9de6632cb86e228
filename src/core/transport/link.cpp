#include "ptz_action_server/core/transport/link.h"

#include <algorithm>

#include "links.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
const char* toString(LinkKind kind)
{
  switch (kind)
  {
    case LinkKind::SERIAL:
      return "serial";
    case LinkKind::TCP:
      return "tcp";
    case LinkKind::UDP:
      return "udp";
    case LinkKind::HTTP:
      return "http";
  }
  return "?";
}

double LinkConfig::wireTime(std::size_t bytes) const
{
  return kind == LinkKind::SERIAL && baud > 0 ? bytes * 10.0 / baud : 0.0;
}

std::string LinkConfig::describe() const
{
  if (kind == LinkKind::SERIAL)
  {
    return path + " at " + std::to_string(baud) + " baud";
  }
  if (kind == LinkKind::HTTP)
  {
    return std::string(http.tls ? "https://" : "http://") + host + ":" + std::to_string(port);
  }
  return std::string(toString(kind)) + " " + host + ":" + std::to_string(port);
}

std::unique_ptr<Link> Link::create(boost::asio::io_context& context, const LinkConfig& config, Listener& listener)
{
  switch (config.kind)
  {
    case LinkKind::SERIAL:
      return makeSerialLink(context, config, listener);
    case LinkKind::TCP:
      return makeTcpLink(context, config, listener);
    case LinkKind::UDP:
      return makeUdpLink(context, config, listener);
    case LinkKind::HTTP:
      return makeHttpLink(context, config, listener);
  }
  throw ConfigError("unknown link kind");
}

Link::Link(boost::asio::io_context& context, const LinkConfig& config, Listener& listener)
  : context_(context), config_(config), listener_(listener), reopen_timer_(context)
{
}

void Link::open()
{
  closed_ = false;
  ++connection_;
  startOpen();
}

void Link::close()
{
  closed_ = true;
  reopen_timer_.cancel();
  ++connection_;
  closeHandle();
  open_ = false;
  dropQueued();
  runWhenWritten();
}

void ByteLink::write(const std::string& bytes)
{
  write(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

void ByteLink::write(const std::uint8_t* data, std::size_t size)
{
  if (size == 0)
  {
    return;
  }
  if (!isOpen())
  {
    ++counters_.writes_dropped;
    return;
  }
  write_queue_.emplace_back(data, data + size);
  if (write_queue_.size() == 1)
  {
    startWrite(write_queue_.front());
  }
}

void Link::disconnect(const std::string& reason)
{
  lost(reason);
}

void Link::whenWritten(std::function<void()> done)
{
  when_written_.push_back(std::move(done));
  if (!writesPending())
  {
    runWhenWritten();
  }
}

std::string Link::lastError() const
{
  std::lock_guard<std::mutex> lock(error_mutex_);
  return last_error_;
}

void Link::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.emplace_back("link", config_.describe());
  addCounts(values, { { "link opens", counters_.opens },
                      { "link open failures", counters_.open_failures },
                      { "link disconnects", counters_.disconnects },
                      { "bytes in", counters_.bytes_in },
                      { "bytes out", counters_.bytes_out },
                      { "writes dropped while down", counters_.writes_dropped } });
  if (carriesDatagrams())
  {
    addCounts(values, { { "datagrams refused by the kernel", counters_.write_failures },
                        { "dropped: datagrams from another sender", counters_.foreign_datagrams } });
  }
  values.emplace_back("last link error", lastError());
}

void Link::opened(bool proven)
{
  open_ = true;
  if (proven)
  {
    backoff_ = 0.0;
  }
  ++counters_.opens;
  const std::uint64_t connection = connection_;
  listener_.onLinkUp();
  if (open_ && connection == connection_)
  {
    afterOpened();
  }
}

void Link::openFailed(const std::string& reason)
{
  ++connection_;  // late completions of this attempt are ignored
  ++counters_.open_failures;
  setLastError(reason);
  closeHandle();
  scheduleReopen();
}

void ByteLink::received(const std::uint8_t* data, std::size_t size)
{
  counters_.bytes_in += size;
  const std::uint64_t connection = this->connection();
  listener().onLinkBytes(data, size);
  // The listener may have closed this connection (a protocol-level failure): then the next read belongs to the next.
  if (isOpen() && connection == this->connection())
  {
    startRead();
  }
}

void ByteLink::written(std::size_t size)
{
  counters_.bytes_out += size;
  if (!write_queue_.empty())
  {
    write_queue_.pop_front();
  }
  if (!write_queue_.empty())
  {
    startWrite(write_queue_.front());
  }
  else
  {
    runWhenWritten();
  }
}

void Link::lost(const std::string& reason)
{
  if (!open_)
  {
    return;
  }
  open_ = false;
  ++connection_;
  closeHandle();
  dropQueued();
  ++counters_.disconnects;
  setLastError(reason);
  listener_.onLinkDown(reason);
  runWhenWritten();
  scheduleReopen();
}

void Link::scheduleReopen()
{
  if (closed_)
  {
    return;
  }
  backoff_ = backoff_ <= 0.0 ? config_.reconnect_min : std::min(backoff_ * 2.0, config_.reconnect_max);
  reopen_timer_.expires_after(toDuration(backoff_));
  reopen_timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error && !closed_)
    {
      ++connection_;
      startOpen();
    }
  });
}

void Link::setLastError(const std::string& reason)
{
  std::lock_guard<std::mutex> lock(error_mutex_);
  last_error_ = reason;
}

void Link::runWhenWritten()
{
  std::vector<std::function<void()>> callbacks;
  callbacks.swap(when_written_);
  for (const std::function<void()>& callback : callbacks)
  {
    callback();
  }
}

}  // namespace ptz_action_server
