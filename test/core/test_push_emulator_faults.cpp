/**
 * \file
 * \brief The fault switch of the emulators that push their state (PanTilt, DigiView, the MAVLink gimbal), as bench/soak
 * drives it: which faults each takes, and the model's fault (IMPOSSIBLE) on the state it reports.
 */
#include <gtest/gtest.h>

#include <ostream>
#include <set>

#include "ptz_action_server/emulators/digiview_emulator.h"
#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"
#include "ptz_action_server/emulators/pantilt_emulator.h"

namespace ptz_action_server
{
/// gtest prints a fault by its name ("drop").
void PrintTo(EmulatorFault fault, std::ostream* out)
{
  *out << toString(fault);
}
}  // namespace ptz_action_server

using namespace ptz_action_server;

namespace
{
using Faults = std::set<EmulatorFault>;

/// The faults \p emulator takes: each switched on, then off again.
Faults faultsTaken(EmulatorFaults& emulator)
{
  Faults taken;
  for (EmulatorFault fault : ALL_EMULATOR_FAULTS)
  {
    if (emulator.setFault(fault, true))
    {
      taken.insert(fault);
      EXPECT_TRUE(emulator.setFault(fault, false)) << toString(fault);
    }
  }
  return taken;
}

/// IMPOSSIBLE puts the reported pan FAULT_IMPOSSIBLE_OFFSET off, SLOW is refused and leaves it so, and off again the
/// pan is the model's. \p pan: the pan the emulator reports now (its model starts at 0).
template <class ReportedPan>
void expectImpossiblePan(EmulatorFaults& emulator, const ReportedPan& pan)
{
  EXPECT_NEAR(pan(), 0.0, 1e-9);
  ASSERT_TRUE(emulator.setFault(EmulatorFault::IMPOSSIBLE, true));
  EXPECT_NEAR(pan(), FAULT_IMPOSSIBLE_OFFSET, 1e-9);
  EXPECT_FALSE(emulator.setFault(EmulatorFault::SLOW, true)) << "a device that pushes its state has no slow replies";
  EXPECT_NEAR(pan(), FAULT_IMPOSSIBLE_OFFSET, 1e-9);
  ASSERT_TRUE(emulator.setFault(EmulatorFault::IMPOSSIBLE, false));
  EXPECT_NEAR(pan(), 0.0, 1e-9);
}
}  // namespace

TEST(PushEmulatorFaults, EachEmulatorTakesTheFaultsItHas)
{
  PanTiltEmulator pan_tilt{ PanTiltEmulatorConfig() };
  EXPECT_EQ(faultsTaken(pan_tilt), (Faults{ EmulatorFault::SILENCE, EmulatorFault::DROP, EmulatorFault::ENDLESS,
                                            EmulatorFault::FLOOD, EmulatorFault::IMPOSSIBLE }));
  DigiViewEmulator digiview{ DigiViewEmulatorConfig() };
  EXPECT_EQ(faultsTaken(digiview), (Faults{ EmulatorFault::SILENCE, EmulatorFault::DROP, EmulatorFault::ENDLESS,
                                            EmulatorFault::FLOOD, EmulatorFault::IMPOSSIBLE }));
  MavlinkGimbalEmulator gimbal{ MavlinkGimbalEmulatorConfig() };
  EXPECT_EQ(faultsTaken(gimbal),
            (Faults{ EmulatorFault::SILENCE, EmulatorFault::ENDLESS, EmulatorFault::FLOOD, EmulatorFault::IMPOSSIBLE }))
      << "UDP has no connection to drop";
}

TEST(PushEmulatorFaults, ImpossibleOffsetsTheReportedPanOfTheModel)
{
  PanTiltEmulator pan_tilt{ PanTiltEmulatorConfig() };
  expectImpossiblePan(pan_tilt, [&] { return pan_tilt.panTilt().sample().position[PAN]; });
  DigiViewEmulator digiview{ DigiViewEmulatorConfig() };
  expectImpossiblePan(digiview, [&] { return digiview.view("main", 0).position[PAN]; });
  MavlinkGimbalEmulator gimbal{ MavlinkGimbalEmulatorConfig() };
  expectImpossiblePan(gimbal, [&] { return gimbal.gimbal(0).position[PAN]; });
}
