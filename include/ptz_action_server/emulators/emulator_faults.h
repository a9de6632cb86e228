/**
 * \file
 * \brief The misbehaviours every device emulator can be told to show, switched the same way on each (bench/soak,
 * tests): one switch here, and each emulator says how it shows the faults it has.
 */
#pragma once

#include <mutex>

#include "ptz_action_server/core/sim/sim_device_model.h"

namespace ptz_action_server
{
/// A misbehaviour an emulator shows on demand (see EmulatorFaults::setFault()).
enum class EmulatorFault
{
  SILENCE,     ///< reads everything, answers nothing
  DROP,        ///< the link drops: a TCP connection closed, a pseudo-terminal unplugged (replugged when off), or
               ///< half the UDP replies lost
  GARBAGE,     ///< a share of the bytes sent replaced by random ones
  ENDLESS,     ///< replies that never end (filler bytes that neither end nor start a message)
  FLOOD,       ///< every state sent FAULT_FLOOD_COPIES times
  SLOW,        ///< every reply FAULT_SLOW_REPLY late (request/reply protocols)
  IMPOSSIBLE,  ///< the reported pan FAULT_IMPOSSIBLE_OFFSET off: outside the device's limits
};
inline constexpr EmulatorFault ALL_EMULATOR_FAULTS[] = { EmulatorFault::SILENCE,   EmulatorFault::DROP,
                                                         EmulatorFault::GARBAGE,   EmulatorFault::ENDLESS,
                                                         EmulatorFault::FLOOD,     EmulatorFault::SLOW,
                                                         EmulatorFault::IMPOSSIBLE };
/// "silence", "drop", ...
const char* toString(EmulatorFault fault);

/// The faults' sizes.
constexpr unsigned FAULT_FLOOD_COPIES = 100;
constexpr double FAULT_GARBLE_RATIO = 0.2;
constexpr double FAULT_DROP_RATIO = 0.5;
constexpr double FAULT_SLOW_REPLY = 0.08;  ///< s: under the serial reply margin (100 ms) and half any state timeout
constexpr double FAULT_IMPOSSIBLE_OFFSET = 10.0;  ///< rad added to the reported pan

/**
 * \brief The fault switch of an emulator. An emulator derives from it and overrides the hooks of the faults it has;
 * the others stay false ("no such mode"). SLOW and IMPOSSIBLE are SimFaults of its motion model.
 */
class EmulatorFaults
{
public:
  virtual ~EmulatorFaults() = default;

  /// Turns \p fault on or off; false, changing nothing, where the emulator has no such mode. Any thread.
  bool setFault(EmulatorFault fault, bool on);

protected:
  virtual bool faultSilence(bool /*on*/)
  {
    return false;
  }
  virtual bool faultDrop(bool /*on*/)
  {
    return false;
  }
  virtual bool faultGarbage(bool /*on*/)
  {
    return false;
  }
  virtual bool faultEndless(bool /*on*/)
  {
    return false;
  }
  virtual bool faultFlood(bool /*on*/)
  {
    return false;
  }
  /// SLOW or IMPOSSIBLE (\p fault) switched: \p faults is the model's whole set with it. False: no such mode.
  virtual bool faultModel(EmulatorFault /*fault*/, const SimFaults& /*faults*/)
  {
    return false;
  }

private:
  std::mutex mutex_;  ///< one switch at a time
  SimFaults model_faults_;
};

}  // namespace ptz_action_server
