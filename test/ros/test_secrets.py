#!/usr/bin/env python3
"""rostest: the IP backends (axis, onvif) never print a secret taken from credentials_file.

For each backend the test makes a fresh random password, writes it only to a credentials file (never a parameter),
and starts the backend's emulator with it (the emulator appends every Digest nonce, response and cnonce and every
WS-Security Nonce and PasswordDigest it receives to a file). It then runs the node as users start it (roslaunch
ptz_action_server.launch, output on screen) through start-up, a goal, a link broken mid-goal (the emulator falls
silent), recovery, and a second start with a wrong password, and captures everything the node writes: roslaunch's
stdout and stderr (the node's own), every /rosout and /diagnostics message, the goals' result texts, and
`rosparam get /`. None of the passwords and none of the values the emulator recorded may appear in any of it.
"""
import os
import secrets
import shutil
import signal
import subprocess
import tempfile
import unittest

import actionlib
import rospy
import rostest

from actionlib_msgs.msg import GoalStatus
from diagnostic_msgs.msg import DiagnosticArray
from ptz_action_server.msg import PtzAction, PtzGoal
from rosgraph_msgs.msg import Log

from wait_until import wait_until

NAMESPACE = '/ptz'
START_WAIT = 90.0  # s for the node to come up (roslaunch on a busy 2-core machine)
GOAL_WAIT = 30.0
USER = 'operator'


def read(path):
    with open(path, errors='replace') as file:
        return file.read()


def stop(process):
    if process.poll() is None:
        process.send_signal(signal.SIGINT)
        try:
            process.wait(timeout=60)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


class SecretsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('secrets_test', anonymous=True)
        cls.seen = []  # every text the node published on /rosout and /diagnostics
        rospy.Subscriber('/rosout', Log, cls.on_log, queue_size=1000)
        rospy.Subscriber('/rosout_agg', Log, cls.on_log, queue_size=1000)
        rospy.Subscriber('/diagnostics', DiagnosticArray, cls.on_diagnostics, queue_size=100)

    @classmethod
    def on_log(cls, message):
        cls.seen.append('rosout %s: %s' % (message.name, message.msg))

    @classmethod
    def on_diagnostics(cls, message):
        for status in message.status:
            cls.seen.append('diagnostics %s [%s]: %s' % (status.name, status.hardware_id, status.message))
            cls.seen.extend('diagnostics %s: %s' % (pair.key, pair.value) for pair in status.values)

    def setUp(self):
        self.directory = tempfile.mkdtemp(prefix='ptz_secrets_test_')
        self.texts = {}  # where -> what the node wrote there
        self.processes = []

    def tearDown(self):
        for process in reversed(self.processes):
            stop(process)
        shutil.rmtree(self.directory, ignore_errors=True)

    def path(self, name):
        return os.path.join(self.directory, name)

    def credentials(self, name, password):
        path = self.path(name)
        with open(path, 'w') as file:
            file.write('username: %s\npassword: "%s"\n' % (USER, password))
        return path

    def start_emulator(self, program, args, password):
        self.emulator_output = self.path('emulator.out')
        self.secrets_file = self.path('secrets_seen')
        with open(self.emulator_output, 'w') as output:
            process = subprocess.Popen(
                ['rosrun', 'ptz_action_server', program, '--host', '127.0.0.1', '--port', '0', '--user', USER,
                 '--password', password, '--secrets-file', self.secrets_file] + args,
                stdout=output, stderr=subprocess.STDOUT)
        self.processes.append(process)
        self.emulator = process
        port = []

        def listening():
            for line in read(self.emulator_output).splitlines():
                if ': listening on http://127.0.0.1:' in line:
                    port.append(int(line.split('127.0.0.1:')[1].split()[0]))
                    return True
            return False
        self.assertTrue(wait_until(listening, 30.0), read(self.emulator_output))
        return port[0]

    def start_node(self, backend, port, credentials_file, name):
        """roslaunch of the node, its stdout and stderr to files named after \\p name."""
        out = open(self.path(name + '.out'), 'w')
        err = open(self.path(name + '.err'), 'w')
        process = subprocess.Popen(
            ['roslaunch', 'ptz_action_server', 'ptz_action_server.launch', 'backend:=' + backend,
             'port:=%d' % port, 'credentials_file:=' + credentials_file, 'output:=screen'],
            stdout=out, stderr=err)
        out.close()
        err.close()
        self.processes.append(process)
        return process

    def output(self, name):
        return read(self.path(name + '.out')) + read(self.path(name + '.err'))

    def stop_node(self, process, name):
        self.texts['rosparam get / (' + name + ')'] = subprocess.run(
            ['rosparam', 'get', '/'], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
            universal_newlines=True, timeout=60).stdout
        stop(process)
        self.texts[name + ' stdout'] = read(self.path(name + '.out'))
        self.texts[name + ' stderr'] = read(self.path(name + '.err'))

    def goal(self, client, pan, tilt, feedback_cb=None):
        client.send_goal(PtzGoal(pan=pan, tilt=tilt, zoom=1.0), feedback_cb=feedback_cb)
        self.assertTrue(client.wait_for_result(rospy.Duration(GOAL_WAIT)))
        text = client.get_goal_status_text()
        self.texts.setdefault('result texts', '')
        self.texts['result texts'] += '%s %s\n' % (client.get_state(), text)
        return client.get_state(), text

    def run_backend(self, backend, program, emulator_args):
        password = 'pw' + secrets.token_hex(16)
        wrong_password = 'pw' + secrets.token_hex(16)
        port = self.start_emulator(program, emulator_args, password)
        del SecretsTest.seen[:]

        # Start-up, a goal, a link broken mid-goal, recovery.
        node = self.start_node(backend, port, self.credentials('right.yaml', password), 'right')
        client = actionlib.SimpleActionClient(NAMESPACE + '/move_ptz/position_abs', PtzAction)
        self.assertTrue(client.wait_for_server(rospy.Duration(START_WAIT)), self.output('right'))
        state, text = self.goal(client, 0.5, 0.2)
        self.assertEqual(state, GoalStatus.SUCCEEDED, text)
        moving = []
        client.send_goal(PtzGoal(pan=-2.5, tilt=0.0, zoom=1.0), feedback_cb=moving.append)
        self.assertTrue(wait_until(lambda: moving, GOAL_WAIT))
        self.emulator.send_signal(signal.SIGUSR1)  # silent
        self.assertTrue(client.wait_for_result(rospy.Duration(GOAL_WAIT)))
        text = client.get_goal_status_text()
        self.texts['result texts'] += 'broken link: %s\n' % text
        self.assertEqual(client.get_state(), GoalStatus.ABORTED, text)
        self.assertIn('link lost', text)
        self.emulator.send_signal(signal.SIGUSR1)  # answers again
        recovered = lambda: self.goal(client, 0.1, 0.1)[0] == GoalStatus.SUCCEEDED
        self.assertTrue(wait_until(recovered, 60.0, step=0.5), self.texts['result texts'])
        self.stop_node(node, 'right')

        # A wrong password: start-up fails with a reason that names the user and no secret.
        node = self.start_node(backend, port, self.credentials('wrong.yaml', wrong_password), 'wrong')
        refused = lambda: 'refused the credentials of user \'%s\'' % USER in self.output('wrong')
        self.assertTrue(wait_until(refused, START_WAIT), self.output('wrong'))
        self.stop_node(node, 'wrong')

        self.texts['rosout and diagnostics'] = '\n'.join(SecretsTest.seen)
        self.assertTrue(any('ptz_action_server' in text for text in SecretsTest.seen), 'nothing on /rosout')
        self.assertTrue(any(text.startswith('diagnostics') for text in SecretsTest.seen), 'no diagnostics')
        seen_by_camera = [line for line in read(self.secrets_file).split('\n') if len(line) >= 8]
        # Many requests each carried fresh values: the search below has something to find.
        self.assertGreater(len(set(seen_by_camera)), 20, read(self.secrets_file))
        for secret in [password, wrong_password] + sorted(set(seen_by_camera)):
            for where, text in self.texts.items():
                at = text.find(secret)
                self.assertEqual(at, -1, 'a secret in %s: ...%s...' % (where, text[max(0, at - 60):at + 60]))

    def test_axis(self):
        self.run_backend('axis', 'axis_camera_emulator', [])

    def test_onvif(self):
        # WS-Security in every message, and HTTP Digest around it, as some cameras demand.
        self.run_backend('onvif', 'onvif_camera_emulator', ['--auth', 'digest'])


if __name__ == '__main__':
    rostest.rosrun('ptz_action_server', 'secrets', SecretsTest)
