#!/usr/bin/env python3
"""rostest: old launches still work. The node started as users started it before the plugins were renamed says
once, for the plugin and for each old parameter, what the new spelling is, names itself by today's plugin, and still
reaches the device (on a port only an old name gives) and moves it:
- roslaunch ptz_action_server.launch backend:=pantilt_udp, a YAML of the old names device_host and device_port under
  ~pantilt_udp/;
- roslaunch ptz_action_server.launch backend:=serial protocol:=flir host:=... port:=NUMBER
  (launch/deprecated_names.launch turns the number into ~serial/tcp_port), a YAML as config/serial.yaml was: the
  device path in port whatever the transport, transaction_deadline, the FLIR settings under ~serial/flir/.
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
from ptz_action_server.msg import PtzAction, PtzCapabilities, PtzGoal

NAMESPACE = '/ptz'
START_WAIT = 90.0  # s for the node to come up (roslaunch on a busy 2-core machine)
GOAL_WAIT = 30.0
PANTILT_UDP_YAML = """
pantilt_udp:
  device_host: 127.0.0.1
  device_port: %d
  local_host: 127.0.0.1
  format: seed
"""
SERIAL_YAML = """
serial:
  protocol: flir
  transport: serial
  port: /dev/ttyUSB0
  baud: 9600
  tcp_port: 4000
  transaction_deadline: 2.0
  flir:
    pan_speed: 1.5
    tilt_speed: 1.0
"""


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

    def check_old_launch(self, yaml, arguments, backend, expected):
        """Starts the node with roslaunch ARGUMENTS and YAML, moves it, then checks its name and warnings."""
        config = os.path.join(self.directory, 'old.yaml')
        with open(config, 'w') as file:
            file.write(yaml)
        with open(os.path.join(self.directory, 'node.out'), 'w') as out:
            self.node = subprocess.Popen(
                ['roslaunch', 'ptz_action_server', 'ptz_action_server.launch', 'config:=' + config,
                 'output:=screen'] + arguments, stdout=out, stderr=subprocess.STDOUT)
        client = actionlib.SimpleActionClient(NAMESPACE + '/move_ptz/position_abs', PtzAction)
        self.assertTrue(client.wait_for_server(rospy.Duration(START_WAIT)), self.output())
        capabilities = rospy.wait_for_message(NAMESPACE + '/capabilities', PtzCapabilities, timeout=START_WAIT)
        self.assertEqual(capabilities.backend, backend)
        client.send_goal(PtzGoal(pan=0.4, tilt=0.2, zoom=1.0))
        self.assertTrue(client.wait_for_result(rospy.Duration(GOAL_WAIT)), self.output())
        self.assertEqual(client.get_state(), GoalStatus.SUCCEEDED, client.get_goal_status_text())
        output = self.output()
        for line in expected:
            self.assertEqual(output.count(line), 1, 'expected once: %s\n%s' % (line, output))
        self.assertEqual(output.count(' is deprecated: '), len(expected), output)

    def test_pantilt_udp_with_device_host_and_device_port(self):
        self.check_old_launch(
            PANTILT_UDP_YAML % rospy.get_param('~pantilt_port'), ['backend:=pantilt_udp'], 'pantilt', [
                "backend 'pantilt_udp' is deprecated: use backend 'pantilt'",
                "parameter /ptz/ptz_action_server/pantilt_udp/device_host is deprecated: use ~pantilt/host",
                "parameter /ptz/ptz_action_server/pantilt_udp/device_port is deprecated: use ~pantilt/port",
            ])

    def test_serial_with_protocol_flir_over_tcp(self):
        self.check_old_launch(
            SERIAL_YAML,
            ['backend:=serial', 'protocol:=flir', 'host:=127.0.0.1', 'port:=%d' % rospy.get_param('~flir_port')],
            'flir', [
                "backend 'serial' (/ptz/ptz_action_server/serial/protocol: flir) is deprecated: use backend 'flir'",
                "parameter /ptz/ptz_action_server/serial/tcp_port is deprecated: use ~flir/port",
                "parameter /ptz/ptz_action_server/serial/transaction_deadline is deprecated: use ~flir/state_timeout",
            ])


if __name__ == '__main__':
    rospy.init_node('deprecated_names_test', anonymous=True)
    rostest.rosrun('ptz_action_server', 'deprecated_names', DeprecatedNamesTest)
