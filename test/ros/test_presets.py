#!/usr/bin/env python3
"""rostest client for presets: save, list, delete, the preset action, and presets surviving a restart of the node.

The test runs the node as users start it (roslaunch ptz_action_server.launch, sim backend) in a child process, with
presets_file in a temporary directory, and stops and restarts it. It waits on conditions with deadlines, never on
bare sleeps.
"""
import os
import shutil
import signal
import subprocess
import tempfile
import unittest

import actionlib
import rospy
import rostest

from actionlib_msgs.msg import GoalStatus
from ptz_action_server.msg import PtzAction, PtzGoal, PtzPresetAction, PtzPresetGoal, PtzState
from ptz_action_server.srv import DeletePreset, ListPresets, SavePreset

from wait_until import wait_until

NAMESPACE = '/ptz'
TOLERANCE = 0.006  # rad: the node's 0.005 plus float32 rounding
ZOOM_TOLERANCE = 0.06
START_WAIT = 90.0  # s for the node to come up (roslaunch on a busy 2-core machine)
GOAL_WAIT = 30.0
HOME = (0.1, -0.05, 1.0)  # ~home/pan, ~home/tilt; zoom: the sim's lowest


class Node:
    """The node under test, started by roslaunch in a child process, and clients for its presets."""

    def __init__(self, presets_file):
        self.process = subprocess.Popen(
            ['roslaunch', 'ptz_action_server', 'ptz_action_server.launch', 'output:=log',
             'presets_file:=' + presets_file])
        prefix = NAMESPACE + '/move_ptz/'
        self.position = actionlib.SimpleActionClient(prefix + 'position_abs', PtzAction)
        self.preset = actionlib.SimpleActionClient(prefix + 'preset', PtzPresetAction)
        try:
            for client in (self.position, self.preset):
                if not client.wait_for_server(rospy.Duration(START_WAIT)):
                    raise RuntimeError('the node did not come up within %.0f s' % START_WAIT)
            for service in ('save_preset', 'delete_preset', 'list_presets'):
                rospy.wait_for_service(prefix + service, START_WAIT)
        except Exception:
            self.stop()  # leave no roslaunch behind
            raise
        self.save = rospy.ServiceProxy(prefix + 'save_preset', SavePreset)
        self.delete = rospy.ServiceProxy(prefix + 'delete_preset', DeletePreset)
        self.list = rospy.ServiceProxy(prefix + 'list_presets', ListPresets)

    def stop(self):
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
            try:
                self.process.wait(timeout=60)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()


class PresetsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('presets_test', anonymous=True)
        cls.directory = tempfile.mkdtemp(prefix='ptz_presets_test_')
        cls.presets_file = os.path.join(cls.directory, 'presets.yaml')
        cls.state = None
        rospy.Subscriber(NAMESPACE + '/ptz_state', PtzState, cls.on_state, queue_size=10)
        # home's pan and tilt from parameters (the launch file leaves them alone), its zoom by default.
        rospy.set_param(NAMESPACE + '/ptz_action_server/home/pan', HOME[0])
        rospy.set_param(NAMESPACE + '/ptz_action_server/home/tilt', HOME[1])
        cls.node = Node(cls.presets_file)

    @classmethod
    def tearDownClass(cls):
        cls.node.stop()
        shutil.rmtree(cls.directory, ignore_errors=True)

    @classmethod
    def on_state(cls, message):
        cls.state = message

    def restart(self):
        PresetsTest.node.stop()
        PresetsTest.node = Node(self.presets_file)

    def assert_state_near(self, pan, tilt, zoom):
        near = lambda: self.state is not None and abs(self.state.pan - pan) < TOLERANCE and \
            abs(self.state.tilt - tilt) < TOLERANCE and abs(self.state.zoom - zoom) < ZOOM_TOLERANCE
        self.assertTrue(wait_until(near, 5.0), 'state %s, expected %.3f %.3f %.2f' % (self.state, pan, tilt, zoom))

    def move_to(self, pan, tilt, zoom):
        client = self.node.position
        client.send_goal(PtzGoal(pan=pan, tilt=tilt, zoom=zoom))
        self.assertTrue(client.wait_for_result(rospy.Duration(GOAL_WAIT)))
        self.assertEqual(client.get_state(), GoalStatus.SUCCEEDED, client.get_goal_status_text())
        self.assert_state_near(pan, tilt, zoom)

    def go_to_preset(self, name):
        """Sends a preset goal and returns its final state and text."""
        client = self.node.preset
        client.send_goal(PtzPresetGoal(name=name))
        self.assertTrue(client.wait_for_result(rospy.Duration(GOAL_WAIT)))
        return client.get_state(), client.get_goal_status_text()

    def listed(self):
        answer = self.node.list()
        return {name: (pan, tilt, zoom) for name, pan, tilt, zoom in
                zip(answer.names, answer.pan, answer.tilt, answer.zoom)}, answer

    def test_saved_preset_is_reached_after_a_restart(self):
        self.move_to(0.5, -0.3, 3.0)
        answer = self.node.save('door')
        self.assertTrue(answer.success, answer.message)
        presets, _ = self.listed()
        self.assertIn('door', presets)
        for value, expected in zip(presets['door'], (0.5, -0.3, 3.0)):
            self.assertAlmostEqual(value, expected, delta=ZOOM_TOLERANCE)
        self.move_to(-0.4, 0.2, 1.0)

        self.restart()
        presets, answer = self.listed()
        self.assertEqual(answer.message, '')
        self.assertEqual(answer.names[0], 'home')
        self.assertIn('door', presets)
        state, text = self.go_to_preset('door')
        self.assertEqual(state, GoalStatus.SUCCEEDED, text)
        self.assert_state_near(*presets['door'])
        self.assertEqual(os.listdir(self.directory), ['presets.yaml'])  # no temporary file left

    def test_home_is_predefined(self):
        self.move_to(0.3, 0.3, 2.0)
        presets, _ = self.listed()
        self.assertEqual(presets['home'], HOME)
        state, text = self.go_to_preset('home')
        self.assertEqual(state, GoalStatus.SUCCEEDED, text)
        self.assert_state_near(*HOME)
        for answer in (self.node.save('home'), self.node.delete('home')):
            self.assertFalse(answer.success)
            self.assertIn('predefined', answer.message)

    def test_unknown_preset_is_rejected_with_the_reason(self):
        state, text = self.go_to_preset('nowhere')
        self.assertEqual(state, GoalStatus.REJECTED, text)
        self.assertIn("no preset named 'nowhere'", text)

    def test_delete(self):
        self.assertTrue(self.node.save('gate').success)
        answer = self.node.delete('gate')
        self.assertTrue(answer.success, answer.message)
        self.assertNotIn('gate', self.listed()[0])
        answer = self.node.delete('gate')
        self.assertFalse(answer.success)
        self.assertIn("no preset named 'gate'", answer.message)
        state, text = self.go_to_preset('gate')
        self.assertEqual(state, GoalStatus.REJECTED, text)

    def test_bad_names_are_refused(self):
        for name in ('', ' gate', 'x' * 65, 'new\nline'):
            answer = self.node.save(name)
            self.assertFalse(answer.success, repr(name))
            self.assertNotEqual(answer.message, '')
        self.assertEqual(list(self.listed()[0])[0], 'home')
        self.assertFalse(set(self.listed()[0]) & {'', ' gate', 'x' * 65, 'new\nline'})

    def test_preset_goal_is_preempted_and_cancelled(self):
        self.move_to(-1.5, 0.8, 12.0)
        self.assertTrue(self.node.save('far').success)
        self.move_to(0.0, 0.0, 1.0)

        # A position goal preempts the preset goal on its way.
        feedback = []
        self.node.preset.send_goal(PtzPresetGoal(name='far'), feedback_cb=feedback.append)
        self.assertTrue(wait_until(lambda: feedback, GOAL_WAIT))
        self.node.position.send_goal(PtzGoal(pan=0.2, tilt=0.1, zoom=1.0))
        self.assertTrue(self.node.preset.wait_for_result(rospy.Duration(GOAL_WAIT)))
        self.assertEqual(self.node.preset.get_state(), GoalStatus.PREEMPTED, self.node.preset.get_goal_status_text())
        self.assertTrue(self.node.position.wait_for_result(rospy.Duration(GOAL_WAIT)))
        self.assertEqual(self.node.position.get_state(), GoalStatus.SUCCEEDED)

        # A cancel stops it too.
        feedback = []
        self.node.preset.send_goal(PtzPresetGoal(name='far'), feedback_cb=feedback.append)
        self.assertTrue(wait_until(lambda: feedback, GOAL_WAIT))
        self.node.preset.cancel_goal()
        self.assertTrue(self.node.preset.wait_for_result(rospy.Duration(GOAL_WAIT)))
        self.assertEqual(self.node.preset.get_state(), GoalStatus.PREEMPTED, self.node.preset.get_goal_status_text())

    def test_zz_unreadable_file_is_reported_and_kept(self):
        # Runs last (unittest orders by name): it leaves the node with a broken file.
        self.node.stop()
        broken = 'presets: {door: {pan: 0.1, tilt: [}\n'
        with open(self.presets_file, 'w') as file:
            file.write(broken)
        PresetsTest.node = Node(self.presets_file)
        presets, answer = self.listed()
        self.assertEqual(list(presets), ['home'])
        self.assertIn(self.presets_file, answer.message)
        answer = self.node.save('gate')
        self.assertFalse(answer.success)
        self.assertIn('read-only', answer.message)
        state, text = self.go_to_preset('home')
        self.assertEqual(state, GoalStatus.SUCCEEDED, text)
        with open(self.presets_file) as file:
            self.assertEqual(file.read(), broken)


if __name__ == '__main__':
    rostest.rosrun('ptz_action_server', 'presets', PresetsTest)
