#include "ptz_action_server/core/device/device_io_pool.h"

#include <pthread.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace ptz_action_server
{
namespace
{
/// The most shared slots PTZ_IO_THREADS may ask for.
constexpr std::size_t MAX_SLOTS = 64;

/// The slot whose thread this is (nullptr off the pool).
thread_local const DeviceIoPool::Slot* current_slot = nullptr;
}  // namespace

DeviceIoPool::Slot::Slot(bool dedicated_slot) : dedicated(dedicated_slot), work(boost::asio::make_work_guard(context))
{
}

DeviceIoPool::Slot::~Slot()
{
  join();
}

void DeviceIoPool::Slot::start()
{
  if (thread.joinable())
  {
    return;
  }
  thread = std::thread([this] {
    current_slot = this;
    context.run();
  });
  // "ptz_io" in top, gdb and /proc/<pid>/task/*/comm.
  pthread_setname_np(thread.native_handle(), dedicated ? "ptz_io_own" : "ptz_io");
}

void DeviceIoPool::Slot::join()
{
  if (!thread.joinable())
  {
    return;
  }
  work.reset();
  context.stop();
  thread.join();
}

DeviceIoPool::Lease::~Lease()
{
  release();
}

DeviceIoPool::Lease::Lease(Lease&& other) noexcept : pool_(other.pool_), slot_(other.slot_)
{
  other.pool_ = nullptr;
  other.slot_ = nullptr;
}

DeviceIoPool::Lease& DeviceIoPool::Lease::operator=(Lease&& other) noexcept
{
  if (this != &other)
  {
    release();
    pool_ = other.pool_;
    slot_ = other.slot_;
    other.pool_ = nullptr;
    other.slot_ = nullptr;
  }
  return *this;
}

boost::asio::io_context& DeviceIoPool::Lease::context() const
{
  return slot_->context;
}

bool DeviceIoPool::Lease::runsHere() const
{
  return slot_ != nullptr && current_slot == slot_;
}

void DeviceIoPool::Lease::release()
{
  if (pool_ != nullptr)
  {
    pool_->release(slot_);
  }
  pool_ = nullptr;
  slot_ = nullptr;
}

DeviceIoPool& DeviceIoPool::instance()
{
  // Made on first use, destroyed at exit (after every session made after it): its threads are joined then.
  static DeviceIoPool pool(sizeFromEnvironment() > 0 ? sizeFromEnvironment() : defaultSize());
  return pool;
}

std::size_t DeviceIoPool::defaultSize()
{
  const std::size_t hardware = std::thread::hardware_concurrency();
  return std::min<std::size_t>(std::max<std::size_t>(hardware, 2), 4);
}

std::size_t DeviceIoPool::sizeFromEnvironment()
{
  const char* text = std::getenv("PTZ_IO_THREADS");
  if (text == nullptr || *text == '\0')
  {
    return 0;
  }
  char* end = nullptr;
  const unsigned long size = std::strtoul(text, &end, 10);
  if (*end != '\0' || size < 1 || size > MAX_SLOTS)
  {
    return 0;  // not a count from 1 to 64: the default
  }
  return size;
}

bool DeviceIoPool::onIoThread()
{
  return current_slot != nullptr;
}

DeviceIoPool::DeviceIoPool(std::size_t size)
{
  shared_.reserve(std::max<std::size_t>(size, 1));
  for (std::size_t i = 0; i < std::max<std::size_t>(size, 1); ++i)
  {
    shared_.push_back(std::make_unique<Slot>(false));
  }
}

DeviceIoPool::~DeviceIoPool()
{
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto& slot : shared_)
  {
    slot->join();
  }
  for (auto& slot : dedicated_)
  {
    slot->join();
  }
}

DeviceIoPool::Lease DeviceIoPool::acquire(bool dedicated)
{
  std::lock_guard<std::mutex> lock(mutex_);
  Slot* slot = nullptr;
  if (dedicated)
  {
    dedicated_.push_back(std::make_unique<Slot>(true));
    slot = dedicated_.back().get();
  }
  else
  {
    // The fewest sessions; among equals the first, so a few sessions share the threads already running.
    const auto least = std::min_element(shared_.begin(), shared_.end(),
                                        [](const auto& a, const auto& b) { return a->sessions < b->sessions; });
    slot = least->get();
  }
  ++slot->sessions;
  slot->start();
  return Lease(this, slot);
}

void DeviceIoPool::release(Slot* slot)
{
  std::unique_ptr<Slot> gone;  // a dedicated slot, joined outside the lock
  {
    std::lock_guard<std::mutex> lock(mutex_);
    --slot->sessions;
    if (slot->dedicated)
    {
      const auto found = std::find_if(dedicated_.begin(), dedicated_.end(),
                                      [slot](const std::unique_ptr<Slot>& held) { return held.get() == slot; });
      gone = std::move(*found);
      dedicated_.erase(found);
    }
  }
  // Its session is gone; whatever it left queued is destroyed unrun (as with a thread per session).
}

std::size_t DeviceIoPool::runningThreads() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<std::size_t>(
      std::count_if(shared_.begin(), shared_.end(), [](const auto& slot) { return slot->thread.joinable(); }));
}

std::size_t DeviceIoPool::dedicatedThreads() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return dedicated_.size();
}

}  // namespace ptz_action_server
