#include "ptz_action_server/emulators/emulator_faults.h"

namespace ptz_action_server
{
const char* toString(EmulatorFault fault)
{
  switch (fault)
  {
    case EmulatorFault::SILENCE:
      return "silence";
    case EmulatorFault::DROP:
      return "drop";
    case EmulatorFault::GARBAGE:
      return "garbage";
    case EmulatorFault::ENDLESS:
      return "endless";
    case EmulatorFault::FLOOD:
      return "flood";
    case EmulatorFault::SLOW:
      return "slow";
    case EmulatorFault::IMPOSSIBLE:
      return "impossible";
  }
  return "?";
}

bool EmulatorFaults::setFault(EmulatorFault fault, bool on)
{
  std::lock_guard<std::mutex> lock(mutex_);
  switch (fault)
  {
    case EmulatorFault::SILENCE:
      return faultSilence(on);
    case EmulatorFault::DROP:
      return faultDrop(on);
    case EmulatorFault::GARBAGE:
      return faultGarbage(on);
    case EmulatorFault::ENDLESS:
      return faultEndless(on);
    case EmulatorFault::FLOOD:
      return faultFlood(on);
    case EmulatorFault::SLOW:
    case EmulatorFault::IMPOSSIBLE: {
      SimFaults faults = model_faults_;
      if (fault == EmulatorFault::SLOW)
      {
        faults.reply_delay = on ? FAULT_SLOW_REPLY : 0.0;
      }
      else
      {
        faults.report_offset[PAN] = on ? FAULT_IMPOSSIBLE_OFFSET : 0.0;
      }
      if (!faultModel(fault, faults))
      {
        return false;
      }
      model_faults_ = faults;
      return true;
    }
  }
  return false;
}

bool PushEmulatorFaults::faultSilence(bool on)
{
  setSilent(on);
  return true;
}

bool PushEmulatorFaults::faultEndless(bool on)
{
  setEndless(on);
  return true;
}

bool PushEmulatorFaults::faultFlood(bool on)
{
  setFlood(on ? FAULT_FLOOD_COPIES : 1);
  return true;
}

bool PushEmulatorFaults::faultModel(EmulatorFault fault, const SimFaults& faults)
{
  if (fault != EmulatorFault::IMPOSSIBLE)
  {
    return false;
  }
  setModelFaults(faults);
  return true;
}

}  // namespace ptz_action_server
