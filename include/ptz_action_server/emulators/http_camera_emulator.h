/**
 * \file
 * \brief What the emulated IP cameras (Axis, ONVIF) share: the motion model behind their answers, the refusal switch
 * and their faults.
 */
#pragma once

#include <memory>
#include <mutex>

#include "ptz_action_server/core/motion/field_of_view.h"
#include "ptz_action_server/core/sim/sim_device_model.h"
#include "ptz_action_server/emulators/emulator_faults.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace ptz_action_server
{
/**
 * \brief The base of an emulated IP camera: its motion model (with its lock and clock), the refusal of moves, and
 * its faults: silence, dropped connections and endless answers of its server, slow answers and impossible reports of
 * its model. No garbage mode (HTTP), no flood (the camera answers requests).
 *
 * The camera owns its HttpCameraServer, as the last of its members (the server's thread calls the camera's handler
 * until the server is gone), and hands it out through server(). Its handler locks mutex_ around the model.
 */
class HttpCameraEmulator : public EmulatorFaults
{
public:
  /// The camera's web server.
  virtual HttpCameraServer& server() = 0;
  /// The model's state now (rad, X).
  PtzSample sample() const;
  /// Refuses every move (as a camera whose PTZ control another user holds), in the camera's own words.
  void setRefuse(bool refuse);
  /// Fault hooks of the motion model: a stalled axis accepts every command and silently stays where it is; a reply
  /// delay makes every answer wait.
  void setFaults(const SimFaults& faults);

  /// A camera's lens at its wide end: 60 degrees across a 16:9 picture (about 34 degrees high).
  static FieldOfViewAngles defaultFieldOfView();
  /**
   * \brief Where a camera at \p pan, \p tilt turns to centre the point (\p x, \p y) of its picture, whose field of
   * view is \p view: x and y from -1 to 1 across it, from its centre to the right and up (1: its edge), on an ideal
   * pinhole. Pan positive to the right, tilt up (rad), as the contract and the camera's own angles.
   */
  static void centreOf(double pan, double tilt, const FieldOfViewAngles& view, double x, double y, double& new_pan,
                       double& new_tilt);

protected:
  /// The motion model of \p device, on \p clock.
  HttpCameraEmulator(const SimDeviceConfig& device, std::shared_ptr<const Clock> clock);

  /// Brings the camera's own doings up to \p now before the model is read (mutex_ held). By default nothing.
  virtual void advance(TimePoint now) const
  {
    (void)now;
  }
  /// Moves are refused (setRefuse()); mutex_ held.
  bool refusing() const
  {
    return refuse_;
  }

  const std::shared_ptr<const Clock> clock_;
  mutable std::mutex mutex_;  ///< guards the model, the refusal and the camera's own state
  mutable SimDeviceModel model_;

private:
  bool faultSilence(bool on) override;
  bool faultDrop(bool on) override;
  bool faultEndless(bool on) override;
  bool faultModel(EmulatorFault fault, const SimFaults& faults) override;

  bool refuse_ = false;
};

}  // namespace ptz_action_server
