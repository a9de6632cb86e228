/**
 * \file
 * \brief An action's goal status list serialized as an actionlib_msgs/GoalStatusArray straight from where its
 * entries live, without copying them into a message first.
 */
#pragma once

#include <cstdint>
#include <cstring>

#include <actionlib_msgs/GoalStatusArray.h>
#include <ros/message_traits.h>
#include <ros/serialization.h>

#include "ptz_action_server/core/goal/ended_goal_list.h"

namespace ptz_action_server
{
/**
 * \brief A GoalStatusArray on the wire (same md5sum, type and definition): the header, then the ended goals' entries
 * (serialized once, EndedGoalList), then each live goal's status from actionlib's list of StatusTrackers.
 *
 * Published in place of a GoalStatusArray; it is only read while the publisher serializes it, under the server's
 * lock.
 */
template <class Trackers>
struct StatusListMessage
{
  std_msgs::Header header;
  const EndedGoalList* ended = nullptr;
  const Trackers* live = nullptr;  ///< std::list<actionlib::StatusTracker<...>>
};

}  // namespace ptz_action_server

namespace ros
{
namespace message_traits
{
/// The trait \p Trait of GoalStatusArray, also answering for a \p Message (the status list on the wire).
template <template <class> class Trait, class Message>
struct AsGoalStatusArray : Trait<actionlib_msgs::GoalStatusArray>
{
  using Trait<actionlib_msgs::GoalStatusArray>::value;
  static const char* value(const Message&)
  {
    return Trait<actionlib_msgs::GoalStatusArray>::value();
  }
};
template <class Trackers>
struct MD5Sum<ptz_action_server::StatusListMessage<Trackers>>
  : AsGoalStatusArray<MD5Sum, ptz_action_server::StatusListMessage<Trackers>>
{
};
template <class Trackers>
struct DataType<ptz_action_server::StatusListMessage<Trackers>>
  : AsGoalStatusArray<DataType, ptz_action_server::StatusListMessage<Trackers>>
{
};
template <class Trackers>
struct Definition<ptz_action_server::StatusListMessage<Trackers>>
  : AsGoalStatusArray<Definition, ptz_action_server::StatusListMessage<Trackers>>
{
};
template <class Trackers>
struct HasHeader<ptz_action_server::StatusListMessage<Trackers>> : TrueType
{
};
}  // namespace message_traits

namespace serialization
{
template <class Trackers>
struct Serializer<ptz_action_server::StatusListMessage<Trackers>>
{
  using Message = ptz_action_server::StatusListMessage<Trackers>;

  template <typename Stream>
  static void write(Stream& stream, const Message& message)
  {
    stream.next(message.header);
    stream.next(static_cast<uint32_t>(message.ended->count() + message.live->size()));
    const auto ended = message.ended->bytes();
    if (!ended.empty())
    {
      std::memcpy(stream.advance(static_cast<uint32_t>(ended.size())), ended.data(), ended.size());
    }
    for (const auto& tracker : *message.live)
    {
      stream.next(tracker.status_);
    }
  }

  static uint32_t serializedLength(const Message& message)
  {
    uint32_t size = serializationLength(message.header) + 4 + static_cast<uint32_t>(message.ended->bytes().size());
    for (const auto& tracker : *message.live)
    {
      size += serializationLength(tracker.status_);
    }
    return size;
  }
};
}  // namespace serialization
}  // namespace ros
