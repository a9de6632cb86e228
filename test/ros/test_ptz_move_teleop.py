#!/usr/bin/env python3
"""rostest client for `ptz_move teleop`: the program runs on a pseudo-terminal against the sim node; the test types
keys into it, reads its screen, and checks what the node received and did. Waits on conditions with deadlines.
"""
import os
import pty
import select
import signal
import subprocess
import termios
import time
import unittest

import rospy
import rostest

from ptz_action_server.msg import PtzActionGoal, PtzPresetActionGoal, PtzState

from wait_until import wait_until

NAMESPACE = '/ptz'
TOLERANCE = 0.006  # rad
WAIT = 30.0
LEFT = b'\x1b[D'


class Terminal:
    """`ptz_move teleop` on a pty: keys in, screen out."""

    def __init__(self, *options):
        self.master, self.slave = pty.openpty()
        self.process = subprocess.Popen(['rosrun', 'ptz_action_server', 'ptz_move', 'teleop', '--ns', NAMESPACE] +
                                        list(options),
                                        stdin=self.slave, stdout=self.slave, stderr=self.slave, close_fds=True)
        self.screen = b''

    def read(self):
        while select.select([self.master], [], [], 0)[0]:
            try:
                chunk = os.read(self.master, 4096)
            except OSError:
                break
            if not chunk:
                break
            self.screen += chunk
        return self.screen

    def last_line(self):
        """The state line as the terminal shows it: the text after the last carriage return, escapes dropped."""
        text = self.read().decode(errors='replace')
        return text.split('\r')[-1].replace('\x1b[K', '')

    def type(self, keys):
        os.write(self.master, keys)

    def hold(self, keys, seconds):
        """A held key as a terminal repeats it: every 40 ms."""
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            self.type(keys)
            self.read()
            time.sleep(0.04)

    def raw(self):
        """True while the terminal has neither line editing nor echo (the program's raw mode)."""
        lflag = termios.tcgetattr(self.slave)[3]
        return not lflag & (termios.ICANON | termios.ECHO)

    def wait_exit(self, timeout=WAIT):
        try:
            return self.process.wait(timeout)
        except subprocess.TimeoutExpired:
            self.process.kill()
            return None

    def close(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
        os.close(self.master)
        os.close(self.slave)


class PtzMoveTeleopTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_ptz_move_teleop', anonymous=True)
        cls.state = None
        cls.velocity_goals = []
        cls.preset_goals = []
        rospy.Subscriber(NAMESPACE + '/ptz_state', PtzState, cls.on_state)
        rospy.Subscriber(NAMESPACE + '/move_ptz/velocity/goal', PtzActionGoal,
                         lambda goal: cls.velocity_goals.append(goal.goal))
        rospy.Subscriber(NAMESPACE + '/move_ptz/preset/goal', PtzPresetActionGoal,
                         lambda goal: cls.preset_goals.append(goal.goal))
        assert wait_until(lambda: cls.state is not None, 90.0), 'no ptz_state'

    @classmethod
    def on_state(cls, state):
        cls.state = state

    def start(self, *options):
        terminal = Terminal(*options)
        self.addCleanup(terminal.close)
        self.assertTrue(wait_until(lambda: 'mode idle' in terminal.last_line(), WAIT),
                        'no state line: %r' % terminal.read())
        self.assertTrue(terminal.raw())
        return terminal

    def test_keys_drive_the_camera_and_q_restores_the_terminal(self):
        terminal = self.start()
        pan = self.state.pan
        goals_before = len(self.velocity_goals)
        terminal.hold(LEFT, 1.0)
        self.assertTrue(wait_until(lambda: self.state.pan < pan - 0.1, 5.0), 'the left arrow did not pan left')
        self.assertGreater(len(self.velocity_goals), goals_before, 'no velocity goal from the left arrow')
        self.assertLess(self.velocity_goals[-1].pan, 0.0)
        self.assertLess(len(self.velocity_goals) - goals_before, 4, 'a held key repeated the goal')
        self.assertIn('velocity pan -0.50', terminal.last_line())
        # Released: the key is no longer repeated, the camera stops and the line shows it.
        self.assertTrue(wait_until(lambda: self.state.mode == PtzState.MODE_IDLE, 5.0))
        self.assertTrue(wait_until(lambda: 'mode idle' in terminal.last_line(), 5.0), terminal.last_line())
        self.assertIn('stop', terminal.last_line())

        terminal.type(b'h')
        self.assertTrue(wait_until(lambda: self.preset_goals and self.preset_goals[-1].name == 'home', 5.0))
        self.assertTrue(wait_until(lambda: self.state.mode == PtzState.MODE_IDLE and abs(self.state.pan) < TOLERANCE,
                                   WAIT), 'not home')
        self.assertTrue(wait_until(lambda: 'preset home' in terminal.last_line(), 5.0), terminal.last_line())

        terminal.type(b'q')
        self.assertEqual(terminal.wait_exit(), 0, terminal.read())
        self.assertFalse(terminal.raw(), 'the terminal was left raw')

    def test_space_stops_and_a_signal_restores_the_terminal(self):
        terminal = self.start('--key-timeout', '60')  # only space can stop it
        terminal.hold(b'+', 0.3)
        self.assertTrue(wait_until(lambda: self.state.mode == PtzState.MODE_VELOCITY, 5.0))
        terminal.type(b' ')
        self.assertTrue(wait_until(lambda: self.state.mode == PtzState.MODE_IDLE, 5.0))
        terminal.process.send_signal(signal.SIGTERM)
        self.assertEqual(terminal.wait_exit(), -signal.SIGTERM)
        self.assertFalse(terminal.raw(), 'the terminal was left raw after SIGTERM')


if __name__ == '__main__':
    rostest.rosrun('ptz_action_server', 'ptz_move_teleop', PtzMoveTeleopTest)
