/**
 * \file
 * \brief The process-wide pool of device I/O threads: every DeviceSession runs its handlers on one of a few
 * single-threaded io_contexts instead of a thread of its own.
 */
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>

namespace ptz_action_server
{
/**
 * \brief A bounded set of I/O threads shared by the device sessions of a process.
 *
 * The pool has N slots, each one io_context run by one thread: N = min(max(hardware threads, 2), 4), or the
 * environment variable PTZ_IO_THREADS (1 .. 64) read once, when the pool is first used. A slot's thread starts when
 * its first session comes; the threads then live as long as the process (they stop and are joined at exit). A session
 * takes the slot with the fewest sessions and gives it back when it goes (Lease).
 *
 * Every slot is single-threaded, so all the handlers of one session run on one thread, one at a time, in the order
 * they were queued: the protocols need no lock of their own, as with a thread per session. The other side: a handler
 * that blocks stalls every session of its slot. A link that blocks (HttpLink calls libcurl's blocking
 * curl_easy_perform()) therefore takes a dedicated slot: an io_context and a thread of its own, stopped and joined
 * when its lease goes, until HTTP becomes asynchronous.
 */
class DeviceIoPool
{
public:
  struct Slot;

  /// A session's share of the pool: its io_context for as long as the lease lives.
  class Lease
  {
  public:
    Lease() = default;
    ~Lease();
    Lease(Lease&& other) noexcept;
    Lease& operator=(Lease&& other) noexcept;
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;

    boost::asio::io_context& context() const;
    /// True if the caller runs on this lease's I/O thread.
    bool runsHere() const;

  private:
    friend class DeviceIoPool;
    Lease(DeviceIoPool* pool, Slot* slot) : pool_(pool), slot_(slot)
    {
    }
    void release();

    DeviceIoPool* pool_ = nullptr;
    Slot* slot_ = nullptr;
  };

  /// The process's pool, made on first use.
  static DeviceIoPool& instance();

  /// The least-loaded shared slot, or (\p dedicated) a slot of its own for a link whose calls block.
  Lease acquire(bool dedicated = false);

  /// The number of shared slots (the bound on shared I/O threads).
  std::size_t size() const
  {
    return shared_.size();
  }
  /// Shared I/O threads running now (dedicated ones aside).
  std::size_t runningThreads() const;
  /// Dedicated slots in use now (one thread each).
  std::size_t dedicatedThreads() const;
  /// True if the caller runs on an I/O thread of the pool (shared or dedicated). Blocking there on another
  /// session's I/O (DeviceSession::stop()) could wait for itself.
  static bool onIoThread();

  /// The default slot count for this machine, and the one PTZ_IO_THREADS asks for (0: unset or invalid).
  static std::size_t defaultSize();
  static std::size_t sizeFromEnvironment();

  /// A pool of \p size shared slots (tests make their own; the process uses instance()).
  explicit DeviceIoPool(std::size_t size);
  /// Stops and joins every thread; leftover handlers are destroyed unrun.
  ~DeviceIoPool();
  DeviceIoPool(const DeviceIoPool&) = delete;
  DeviceIoPool& operator=(const DeviceIoPool&) = delete;

private:
  void release(Slot* slot);

  mutable std::mutex mutex_;  ///< guards the session counts, the thread starts and dedicated_
  std::vector<std::unique_ptr<Slot>> shared_;
  std::vector<std::unique_ptr<Slot>> dedicated_;
};

/// One io_context and its thread.
struct DeviceIoPool::Slot
{
  explicit Slot(bool dedicated_slot);
  ~Slot();
  /// Starts the thread (once; with the pool's mutex held).
  void start();
  /// Lets run() return, stops the context and joins the thread (not from the thread itself).
  void join();

  const bool dedicated;
  boost::asio::io_context context{ 1 };  ///< concurrency hint 1: run by one thread
  boost::asio::executor_work_guard<boost::asio::io_context::executor_type> work;
  std::thread thread;
  std::size_t sessions = 0;  ///< guarded by the pool's mutex
};

}  // namespace ptz_action_server
