/**
 * \file
 * \brief The misbehaviours every device emulator can be told to show, switched the same way on each (bench/soak,
 * tests): one switch here, and each emulator says how it shows the faults it has.
 */
#pragma once

#include <atomic>
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

/**
 * \brief The faults of an emulator that pushes its state (PanTilt, DigiView, the MAVLink gimbal), switched the same
 * way on each: SILENCE, ENDLESS, FLOOD and IMPOSSIBLE (the reported pan of the model setModelFaults() names). No
 * garbage mode and no slow replies: the device pushes its state, it has no request to answer late. An emulator with a
 * DROP of its own overrides faultDrop().
 */
class PushEmulatorFaults : public EmulatorFaults
{
public:
  /// Silent: reads and ignores everything, sends nothing.
  virtual void setSilent(bool silent)
  {
    silent_ = silent;
  }
  /// Endless: replies that never end, at the rate of the real ones (each emulator says how). Off again, the device
  /// answers as before.
  virtual void setEndless(bool endless) = 0;
  /// Flood: every state the device sends goes out \p copies times (1: normally), as a device that reports far faster
  /// than it should.
  void setFlood(unsigned copies)
  {
    flood_ = copies < 1 ? 1 : copies;
  }

protected:
  bool silent() const
  {
    return silent_;
  }
  /// How many times each state goes out (setFlood()).
  unsigned floodCopies() const
  {
    return flood_;
  }
  /// IMPOSSIBLE switched: \p faults for the model whose state the device reports.
  virtual void setModelFaults(const SimFaults& faults) = 0;

private:
  bool faultSilence(bool on) override;
  bool faultEndless(bool on) override;
  bool faultFlood(bool on) override;
  bool faultModel(EmulatorFault fault, const SimFaults& faults) override;

  std::atomic<bool> silent_{ false };
  std::atomic<unsigned> flood_{ 1 };
};

}  // namespace ptz_action_server
