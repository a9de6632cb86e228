#!/usr/bin/env python3
"""rostest: an old launch still works. The node started as users started it before the plugins were renamed
(roslaunch ptz_action_server.launch backend:=pantilt_udp, a YAML of the old names device_host and device_port under
~pantilt_udp/) says once, for the plugin and for each old parameter, what the new spelling is, and still reaches the
device (a port only the old name device_port gives) and moves it.
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
from ptz_action_server.msg import PtzAction, PtzGoal

NAMESPACE = '/ptz'
START_WAIT = 90.0  # s for the node to come up (roslaunch on a busy 2-core machine)
GOAL_WAIT = 30.0
OLD_YAML = """
pantilt_udp:
  device_host: 127.0.0.1
  device_port: %d
  local_host: 127.0.0.1
  format: seed
"""
EXPECTED = [
    "backend 'pantilt_udp' is deprecated: use backend 'pantilt'",
    "parameter /ptz/ptz_action_server/pantilt_udp/device_host is deprecated: use ~pantilt/host",
    "parameter /ptz/ptz_action_server/pantilt_udp/device_port is deprecated: use ~pantilt/port",
]


class DeprecatedNamesTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.mkdtemp(prefix='ptz_deprecated_names_')
        self.node = None

    def tearDown(self):
        if self.node is not None and self.node.poll() is None:
            self.node.send_signal(signal.SIGINT)
            try:
                self.node.wait(timeout=60)
            except subprocess.TimeoutExpired:
                self.node.kill()
                self.node.wait()
        shutil.rmtree(self.directory, ignore_errors=True)

    def output(self):
        with open(os.path.join(self.directory, 'node.out'), errors='replace') as file:
            return file.read()

    def test_old_plugin_and_parameter_names_warn_once_and_still_drive_the_device(self):
        rospy.init_node('deprecated_names_test', anonymous=True)
        config = os.path.join(self.directory, 'old.yaml')
        with open(config, 'w') as file:
            file.write(OLD_YAML % rospy.get_param('~device_port'))
        with open(os.path.join(self.directory, 'node.out'), 'w') as out:
            self.node = subprocess.Popen(
                ['roslaunch', 'ptz_action_server', 'ptz_action_server.launch', 'backend:=pantilt_udp',
                 'config:=' + config, 'output:=screen'], stdout=out, stderr=subprocess.STDOUT)
        client = actionlib.SimpleActionClient(NAMESPACE + '/move_ptz/position_abs', PtzAction)
        self.assertTrue(client.wait_for_server(rospy.Duration(START_WAIT)), self.output())
        client.send_goal(PtzGoal(pan=0.4, tilt=0.2, zoom=1.0))
        self.assertTrue(client.wait_for_result(rospy.Duration(GOAL_WAIT)), self.output())
        self.assertEqual(client.get_state(), GoalStatus.SUCCEEDED, client.get_goal_status_text())
        output = self.output()
        for line in EXPECTED:
            self.assertEqual(output.count(line), 1, 'expected once: %s\n%s' % (line, output))


if __name__ == '__main__':
    rostest.rosrun('ptz_action_server', 'deprecated_names', DeprecatedNamesTest)
