/**
 * \file
 * \brief One object of a kind per process, shared by whoever holds it: the cameras of a nodelet manager share their
 * timer thread, service thread and tf publishers this way.
 */
#pragma once

#include <memory>
#include <mutex>

namespace ptz_action_server
{
/// The process's one \p T, made by the first caller, kept while a caller holds it, made again after the last let go.
/// Call it from one source file per \p T (its static shared()), so that one library holds the instance.
template <class T>
std::shared_ptr<T> processShared()
{
  static std::mutex mutex;
  static std::weak_ptr<T> instance;
  std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<T> shared = instance.lock();
  if (!shared)
  {
    shared = std::make_shared<T>();
    instance = shared;
  }
  return shared;
}

}  // namespace ptz_action_server
