#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>

#include "ptz_action_server/SetSimFaults.h"
#include "ptz_action_server/core/sim/sim_backend.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/**
 * \brief Builds the simulated backend from ~sim/... parameters and serves ~sim/set_faults.
 *
 * Limits default to the URDF's joint limits and speeds, so the simulated device matches the model in rviz.
 */
class SimBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    SimDeviceConfig config = SimDeviceConfig::defaults();
    readAxis(params.child("pan"), context.urdf_limits.axes[PAN], config.axes[PAN]);
    readAxis(params.child("tilt"), context.urdf_limits.axes[TILT], config.axes[TILT]);

    SimAxisConfig& zoom = config.axes[ZOOM];
    const ParamReader zoom_params = params.child("zoom");
    zoom.present = zoom_params.flag("present", true);
    zoom.range.min = zoom_params.number("min", zoom.range.min, 1.0, 1000.0);
    zoom.range.max = zoom_params.number("max", zoom.range.max, zoom.range.min, 1000.0);
    // A lens slews at a constant rate: no ramp.
    zoom.motion.max_speed = zoom.motion.base_speed = zoom_params.number("rate", zoom.motion.max_speed, 1e-3, 1000.0);
    zoom.initial_position = zoom.range.min;

    SimLensConfig lens;
    lens.focus.present = params.flag("focus/present", lens.focus.present);
    lens.focus.travel_time = params.number("focus/travel_time", lens.focus.travel_time, 0.01, 600.0);
    lens.iris.present = params.flag("iris/present", lens.iris.present);
    lens.iris.travel_time = params.number("iris/travel_time", lens.iris.travel_time, 0.01, 600.0);

    auto backend = std::make_shared<SimBackend>(config, context.clock, lens);
    backend_ = backend;
    ros::NodeHandle node_handle = params.nodeHandle();
    fault_service_ = node_handle.advertiseService("set_faults", &SimBackendPlugin::setFaults, this);
    return backend;
  }

private:
  static void readAxis(const ParamReader& params, const AxisCapability& urdf, SimAxisConfig& axis)
  {
    const double default_speed = urdf.max_speed > 0.0 ? urdf.max_speed : axis.motion.max_speed;
    axis.range.min = params.number("min", urdf.range.min, -M_PI, M_PI);
    axis.range.max = params.number("max", urdf.range.max, axis.range.min, M_PI);
    axis.motion.max_speed = params.number("max_speed", default_speed, 1e-3, 100.0);
    axis.motion.acceleration = params.number("acceleration", axis.motion.acceleration, 1e-3, 1e4);
    axis.motion.base_speed = params.number("base_speed", 0.0, 0.0, axis.motion.max_speed);
    axis.resolution = params.number("resolution", axis.resolution, 0.0, 0.1);
    axis.initial_position = params.number("initial", 0.0, axis.range.min, axis.range.max);
  }

  bool setFaults(SetSimFaults::Request& request, SetSimFaults::Response& response)
  {
    const std::shared_ptr<SimBackend> backend = backend_.lock();
    if (!backend)
    {
      response.success = false;
      response.message = "the simulated backend is gone";
      return true;
    }
    if (!(request.lag >= 0.0 && request.lag <= 60.0))
    {
      response.success = false;
      response.message = "lag must be in [0, 60] s";
      return true;
    }
    SimFaults faults;
    faults.stalled = { { request.stall_pan != 0, request.stall_tilt != 0, request.stall_zoom != 0 } };
    faults.lag = request.lag;
    backend->setFaults(faults, request.dropout != 0);
    response.success = true;
    response.message = "faults set";
    const bool any =
        request.stall_pan || request.stall_tilt || request.stall_zoom || request.lag > 0.0 || request.dropout;
    ROS_LOG(any ? ros::console::levels::Warn : ros::console::levels::Debug, ROSCONSOLE_DEFAULT_NAME,
            "sim: faults set: stall pan=%d tilt=%d zoom=%d, lag %.3f s, dropout=%d", request.stall_pan,
            request.stall_tilt, request.stall_zoom, request.lag, request.dropout);
    return true;
  }

  std::weak_ptr<SimBackend> backend_;  ///< the node owns the backend; the service must not keep it alive
  ros::ServiceServer fault_service_;
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::SimBackendPlugin, ptz_action_server::BackendPlugin)
