/**
 * \file
 * \brief The transports under every device protocol: a serial port, a TCP connection or a UDP peer, behind one
 * interface with reconnection and backoff, a write queue and counters.
 *
 * The model is ur_client_library's comm layer and industrial_core's simple_message connections: the protocol never
 * sees a socket, only bytes in, bytes out, "up" and "down". A Link is the connection (open, reopen with backoff,
 * losses and their reasons); a ByteLink carries bytes over it (serial, TCP, UDP); the HTTP link carries requests and
 * answers instead (HttpChannel, http_channel.h).
 */
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/counter.h"

namespace ptz_action_server
{
class ByteLink;
class HttpChannel;

enum class LinkKind
{
  SERIAL,  ///< a serial port (8N1), a byte stream
  TCP,     ///< a TCP connection to the device, a byte stream
  UDP,     ///< datagrams to and from one peer
  HTTP,    ///< HTTP requests to one server (libcurl): one keep-alive connection, a request at a time (HttpLink)
};

/// How an HTTP link authenticates.
enum class HttpAuth
{
  DIGEST,  ///< RFC 7616 Digest (MD5, qop=auth); the nonce is reused, so a request costs one round trip
  BASIC,   ///< RFC 7617 Basic (old or configured cameras); use it over TLS
  AUTO,    ///< whatever the first challenge offers (Digest before Basic); then only that
  NONE,    ///< no credentials
};

/// The HTTP side of a LinkConfig (kind HTTP). The password is never printed.
struct HttpLinkConfig
{
  bool tls = false;  ///< https instead of http (never falls back to http)
  /// tls: check the camera's certificate (against the system's CAs, ca_file, or the pinned fingerprint); false
  /// takes an explicit tls_verify: false, and the session warns once.
  bool verify_peer = true;
  std::string ca_file;      ///< tls: PEM file of the CA(s) (or the self-signed certificate) to trust instead
  std::string fingerprint;  ///< tls: the pinned SHA-256 of the camera's certificate, 64 lower-case hex digits
  HttpAuth auth = HttpAuth::DIGEST;
  std::string username;
  std::string password;          ///< never in logs, messages or diagnostics
  double request_timeout = 1.0;  ///< s a request may take from start to the last byte of its answer
};

/// "serial", "tcp", "udp".
const char* toString(LinkKind kind);

/// Where the device is and how to reach it.
struct LinkConfig
{
  LinkKind kind = LinkKind::SERIAL;
  std::string path;                    ///< serial: e.g. /dev/ttyUSB0, or a udev / emulator symlink
  unsigned baud = 9600;                ///< serial: standard rates only (a pseudo-terminal accepts no others)
  double identity_check = 0.25;        ///< serial: s between checks that the path still names the open device
  std::string host = "127.0.0.1";      ///< tcp, udp: the device's address or name
  std::uint16_t port = 0;              ///< tcp, udp: the device's port
  std::string local_host = "0.0.0.0";  ///< udp: the address the device's datagrams arrive at
  std::uint16_t local_port = 0;        ///< udp: 0 = any free port
  double connect_timeout = 3.0;        ///< tcp: s a connection attempt may take
  double reconnect_min = 0.05;         ///< s before the first reopen attempt
  double reconnect_max = 2.0;          ///< s between attempts, at most (the wait doubles up to it)
  HttpLinkConfig http;                 ///< http: scheme, credentials, request deadline

  /// Seconds \p bytes take on the wire: 10 bits a byte (8N1) on a serial port, 0 on a network.
  double wireTime(std::size_t bytes) const;
  /// "/dev/ttyUSB0 at 9600 baud", "tcp 192.168.1.20:4000", "udp 127.0.0.1:5000", "http://10.0.0.7:80" (never the
  /// credentials).
  std::string describe() const;
};

/// What a link counts for diagnostics. Bumped on the I/O thread, readable from any thread.
struct LinkCounters
{
  Counter opens;              ///< successful opens (and reopens)
  Counter open_failures;      ///< failed attempts
  Counter disconnects;        ///< an open link that closed: unplugged, reset, read or write failure
  Counter bytes_in;           ///< received (datagram links: of the peer's datagrams)
  Counter bytes_out;          ///< written
  Counter writes_dropped;     ///< writes while the link was down
  Counter write_failures;     ///< datagrams the kernel refused (stream links disconnect instead)
  Counter foreign_datagrams;  ///< udp: datagrams from anyone but the peer, dropped
};

/**
 * \brief A connection to one device, kept open with backoff, driven by its owner's io_context.
 *
 * Everything but the accessors marked "any thread" runs on the I/O thread that runs the io_context, and so do the
 * Listener's callbacks. What the connection carries is its kind's: bytes (bytes(), a ByteLink) or HTTP requests
 * (http(), an HttpChannel).
 */
class Link
{
public:
  /// Called on the I/O thread.
  class Listener
  {
  public:
    virtual ~Listener() = default;
    /// The link is open (again): whatever the device knew of this client may be gone.
    virtual void onLinkUp() = 0;
    /// Bytes from the device. On a datagram link, exactly one datagram from the peer.
    virtual void onLinkBytes(const std::uint8_t* data, std::size_t size) = 0;
    /// The open link closed; a reopen is scheduled. \p reason names the link ("connection to 10.0.0.5:4000 closed").
    virtual void onLinkDown(const std::string& reason) = 0;
  };

  /// The link \p config describes. Throws ConfigError for a config it cannot serve.
  static std::unique_ptr<Link> create(boost::asio::io_context& context, const LinkConfig& config, Listener& listener);

  virtual ~Link() = default;
  Link(const Link&) = delete;
  Link& operator=(const Link&) = delete;

  /// Opens now, and reopens with backoff after every failure or loss until close().
  void open();
  /// Closes for good: no reopen, no callback.
  void close();
  /// Closes because the protocol gave up on this connection (it reopens after the backoff).
  void disconnect(const std::string& reason);
  /// Runs \p done once every queued write has gone out (at once if none is queued, or if the link is down).
  void whenWritten(std::function<void()> done);

  /// The link as a carrier of bytes (serial, TCP, UDP), or nullptr (HTTP).
  virtual ByteLink* bytes()
  {
    return nullptr;
  }
  /// The link as a carrier of HTTP requests, or nullptr.
  virtual HttpChannel* http()
  {
    return nullptr;
  }
  /// The last loss will repeat on every reopen (a certificate refused): waiting for the device is pointless. I/O
  /// thread.
  virtual bool refusedForGood() const
  {
    return false;
  }

  bool isOpen() const
  {
    return open_;
  }
  /// True for UDP: every onLinkBytes() is one whole datagram.
  bool carriesDatagrams() const
  {
    return config_.kind == LinkKind::UDP;
  }
  /// Any thread.
  const LinkConfig& config() const
  {
    return config_;
  }
  /// Any thread.
  const LinkCounters& counters() const
  {
    return counters_;
  }
  /// Why the link last closed or failed to open ("" if it never did). Any thread.
  std::string lastError() const;
  /// The link, its opens, failures, losses and traffic, for a backend's diagnostics. Any thread.
  virtual void diagnostics(std::vector<DiagnosticValue>& values) const;

protected:
  Link(boost::asio::io_context& context, const LinkConfig& config, Listener& listener);

  /// Starts opening; ends (now or later) in opened() or openFailed(). The handle is closed when it is called.
  virtual void startOpen() = 0;
  /// Cancels whatever is under way and closes the handle. Never calls back.
  virtual void closeHandle() = 0;
  /// The link opened, the listener has heard of it, and it is still open on the same connection: start reading.
  virtual void afterOpened()
  {
  }
  /// The link closed: drop what was queued for it.
  virtual void dropQueued()
  {
  }
  /// Something is queued for the device: whenWritten() waits for runWhenWritten().
  virtual bool writesPending() const
  {
    return false;
  }

  /// The handle is open. \p proven: it has carried traffic, so the reopen backoff starts afresh (an HTTP link opens
  /// before its first request and proves itself with a reply: see provenAlive()).
  void opened(bool proven = true);
  /// The peer answered: the next reopen after a loss waits reconnect_min again.
  void provenAlive()
  {
    backoff_ = 0.0;
  }
  void openFailed(const std::string& reason);
  /// The open link broke: closes it, tells the listener and schedules a reopen.
  void lost(const std::string& reason);
  /// Runs the whenWritten() callbacks (everything queued has gone out, or was dropped).
  void runWhenWritten();
  Listener& listener()
  {
    return listener_;
  }

  /// Identifies the current connection: completions of an earlier one compare unequal and are ignored.
  std::uint64_t connection() const
  {
    return connection_;
  }

  boost::asio::io_context& context_;
  const LinkConfig config_;
  LinkCounters counters_;

private:
  void scheduleReopen();
  void setLastError(const std::string& reason);

  Listener& listener_;
  boost::asio::steady_timer reopen_timer_;
  bool open_ = false;
  bool closed_ = true;  ///< close() was called, or open() never was: no reopen
  std::uint64_t connection_ = 0;
  double backoff_ = 0.0;
  std::vector<std::function<void()>> when_written_;

  mutable std::mutex error_mutex_;  ///< guards last_error_, read from any thread
  std::string last_error_;
};

/**
 * \brief A link that carries bytes: a serial port, a TCP connection, a UDP peer.
 *
 * Writes are queued and go out in order; while the link is down they are dropped (and counted), because commands
 * meant for a device that was not there must not reach it late.
 */
class ByteLink : public Link
{
public:
  /// Queues bytes for the device; dropped (and counted) while the link is down.
  void write(const std::uint8_t* data, std::size_t size);
  void write(const std::string& bytes);

  ByteLink* bytes() override
  {
    return this;
  }

protected:
  using Link::Link;

  /// Starts one read; its completion calls received() or lost().
  virtual void startRead() = 0;
  /// Starts writing \p bytes (the queue's front, which stays alive until written); completion calls written().
  virtual void startWrite(const std::vector<std::uint8_t>& bytes) = 0;

  void received(const std::uint8_t* data, std::size_t size);
  void written(std::size_t size);

  void afterOpened() override
  {
    startRead();
  }
  void dropQueued() override
  {
    write_queue_.clear();
  }
  bool writesPending() const override
  {
    return !write_queue_.empty();
  }

private:
  std::deque<std::vector<std::uint8_t>> write_queue_;
};

}  // namespace ptz_action_server
