#!/usr/bin/env python3
"""rostest client for focus and iris: lens_capabilities, lens_state, the cmd/ topics with their dead-man, the
set_auto and one_push services on the sim's lens, a device without a lens refusing with the reason, and an ONVIF
camera's lens through its Imaging service (onvif_camera_emulator).

It waits on conditions with deadlines, never on bare sleeps.
"""
import math
import threading
import unittest

import rospy
import rostest

from std_msgs.msg import Float64
from std_srvs.srv import SetBool, Trigger
from ptz_action_server.msg import PtzLensCapabilities, PtzLensState

from wait_until import wait_until

START_WAIT = 90.0  # s for the nodes to come up (roslaunch on a busy 2-core machine)
WAIT = 20.0


class Camera:
    """One node's lens topics and services, and the latest lens_state and lens_capabilities it published."""

    def __init__(self, namespace):
        self.lock = threading.Lock()
        self.state = None
        self.capabilities = None
        self.states = 0
        rospy.Subscriber(namespace + '/lens_state', PtzLensState, self.on_state)
        rospy.Subscriber(namespace + '/lens_capabilities', PtzLensCapabilities, self.on_capabilities)
        self.focus = rospy.Publisher(namespace + '/cmd/focus', Float64, queue_size=10)
        self.focus_position = rospy.Publisher(namespace + '/cmd/focus_position', Float64, queue_size=10)
        self.iris_position = rospy.Publisher(namespace + '/cmd/iris_position', Float64, queue_size=10)
        for service in ('focus/set_auto', 'iris/set_auto', 'focus/one_push'):
            rospy.wait_for_service(namespace + '/' + service, START_WAIT)
        self.focus_auto = rospy.ServiceProxy(namespace + '/focus/set_auto', SetBool)
        self.iris_auto = rospy.ServiceProxy(namespace + '/iris/set_auto', SetBool)
        self.one_push = rospy.ServiceProxy(namespace + '/focus/one_push', Trigger)

    def on_state(self, message):
        with self.lock:
            self.state = message
            self.states += 1

    def on_capabilities(self, message):
        with self.lock:
            self.capabilities = message

    def latest(self):
        with self.lock:
            return self.state

    def state_count(self):
        with self.lock:
            return self.states


class LensTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('lens_test')
        cls.sim = Camera('/ptz')
        cls.nolens = Camera('/nolens')
        cls.onvif = Camera('/onvif')
        for camera in (cls.sim, cls.nolens, cls.onvif):
            assert wait_until(lambda: camera.capabilities is not None and camera.latest() is not None, START_WAIT)
            for publisher in (camera.focus, camera.focus_position, camera.iris_position):
                assert wait_until(lambda: publisher.get_num_connections() > 0, START_WAIT)

    def test_capabilities_say_what_each_lens_takes(self):
        focus = self.sim.capabilities.focus
        self.assertTrue(focus.present and focus.auto_mode and focus.velocity and focus.absolute and focus.feedback)
        self.assertTrue(focus.one_push)
        self.assertTrue(self.sim.capabilities.iris.present)
        self.assertFalse(self.nolens.capabilities.focus.present)
        self.assertEqual(self.nolens.capabilities.focus.limitation, 'the simulated lens is configured without focus')

    def test_focus_stream_drives_and_its_deadman_stops_it(self):
        self.sim.focus_position.publish(Float64(0.2))  # manual, well short of the far end
        self.assertTrue(wait_until(lambda: abs(self.sim.latest().focus - 0.2) < 1e-4, WAIT))
        self.assertEqual(self.sim.latest().focus_mode, PtzLensState.MODE_MANUAL)
        start = self.sim.latest().focus
        # A stream at 20 Hz for as long as the focus has not moved far: the node keeps it running.
        rate = rospy.Rate(20)
        deadline = rospy.get_time() + WAIT
        while self.sim.latest().focus < start + 0.1 and rospy.get_time() < deadline:
            self.sim.focus.publish(Float64(1.0))
            rate.sleep()
        self.assertGreaterEqual(self.sim.latest().focus, start + 0.1)
        # The stream stops: within lens/velocity_timeout (0.5 s) the focus stops, short of the far end.
        def settled():
            before = self.sim.latest().focus
            count = self.sim.state_count()
            wait_until(lambda: self.sim.state_count() >= count + 3, WAIT)
            return self.sim.latest().focus == before
        self.assertTrue(wait_until(settled, WAIT))
        self.assertLess(self.sim.latest().focus, 1.0)

    def test_positions_modes_and_one_push(self):
        self.sim.focus_position.publish(Float64(0.25))
        self.assertTrue(wait_until(lambda: abs(self.sim.latest().focus - 0.25) < 1e-4, WAIT))
        self.assertEqual(self.sim.latest().focus_mode, PtzLensState.MODE_MANUAL)
        self.sim.iris_position.publish(Float64(0.9))
        self.assertTrue(wait_until(lambda: abs(self.sim.latest().iris - 0.9) < 1e-4, WAIT))
        answer = self.sim.iris_auto(True)
        self.assertTrue(answer.success, answer.message)
        self.assertTrue(wait_until(lambda: self.sim.latest().iris_mode == PtzLensState.MODE_AUTO, WAIT))
        self.assertTrue(self.sim.one_push().success)
        self.assertTrue(wait_until(lambda: abs(self.sim.latest().focus - 0.7) < 1e-4, WAIT))  # the sim's subject
        self.assertEqual(self.sim.latest().focus_mode, PtzLensState.MODE_MANUAL)

    def test_a_device_without_a_lens_refuses_with_the_reason(self):
        answer = self.nolens.focus_auto(True)
        self.assertFalse(answer.success)
        self.assertEqual(answer.message, 'the simulated lens is configured without focus')
        answer = self.nolens.one_push()
        self.assertFalse(answer.success)
        answer = self.nolens.iris_auto(False)
        self.assertEqual(answer.message, 'the simulated lens is configured without iris')
        self.nolens.focus.publish(Float64(0.5))
        count = self.nolens.state_count()
        self.assertTrue(wait_until(lambda: self.nolens.state_count() >= count + 3, WAIT))
        state = self.nolens.latest()
        self.assertEqual(state.focus_mode, PtzLensState.MODE_UNKNOWN)
        self.assertTrue(math.isnan(state.focus) and math.isnan(state.iris))
        self.assertEqual(state.faults, 0)

    def test_an_onvif_camera_drives_its_lens_through_the_imaging_service(self):
        capabilities = self.onvif.capabilities
        self.assertTrue(capabilities.focus.present and capabilities.focus.auto_mode and capabilities.focus.velocity)
        self.assertTrue(capabilities.focus.absolute and capabilities.focus.feedback)
        self.assertFalse(capabilities.focus.one_push)
        self.assertTrue(capabilities.iris.present and capabilities.iris.absolute and capabilities.iris.feedback)
        self.assertFalse(capabilities.iris.velocity)
        self.onvif.focus_position.publish(Float64(0.25))  # Move Absolute Position 250 of 0..1000, after MANUAL
        self.assertTrue(wait_until(lambda: abs(self.onvif.latest().focus - 0.25) < 1e-3, WAIT))
        self.assertEqual(self.onvif.latest().focus_mode, PtzLensState.MODE_MANUAL)
        self.onvif.iris_position.publish(Float64(0.5))  # Exposure MANUAL, Iris -11 dB of -22..0
        self.assertTrue(wait_until(lambda: abs(self.onvif.latest().iris - 0.5) < 1e-3, WAIT))
        self.assertEqual(self.onvif.latest().iris_mode, PtzLensState.MODE_MANUAL)
        answer = self.onvif.focus_auto(True)
        self.assertTrue(answer.success, answer.message)
        self.assertTrue(wait_until(lambda: self.onvif.latest().focus_mode == PtzLensState.MODE_AUTO, WAIT))
        answer = self.onvif.one_push()
        self.assertFalse(answer.success)
        self.assertIn('the ONVIF Imaging service has no one-push focus', answer.message)
        self.assertEqual(self.onvif.latest().faults, 0)


if __name__ == '__main__':
    rostest.rosrun('ptz_action_server', 'lens', LensTest)
