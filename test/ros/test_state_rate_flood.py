#!/usr/bin/env python3
"""rostest client for state_rate_flood.test: a device flooding at 100x its rate leaves ptz_state at 10 Hz.

The rate is judged on the node's clocks, not on this process's arrival times: joint_states leaves on the same 10 Hz
tick as ptz_state, stamped with the sample the tick publishes (under a flood, a sample a fraction of a millisecond
old), and the node's own diagnostics measure the ptz_state rate it publishes. That the flood was taken in, and
coalesced rather than queued, shows in the backend's diagnostics: its "state reports" counter grows far faster
than ptz_state. Waits on conditions with deadlines, never on bare sleeps.
"""
import threading
import unittest

import rospy
import rostest

from diagnostic_msgs.msg import DiagnosticArray
from ptz_action_server.msg import PtzState
from sensor_msgs.msg import JointState

from wait_until import wait_until

RATE = 10.0
TOLERANCE = 0.02  # 10 Hz +- 2 %
WINDOW = 10.0  # s of stamps the rate is taken over
NORMAL_REPORTS = 20.0  # params frames a second without the flood (--state-period 0.05)
START_WAIT = 60.0  # s for the node and its first flooded states (a busy 2-core machine)


class StateRateFloodTest(unittest.TestCase):
    def setUp(self):
        self.lock = threading.Lock()
        self.joint_stamps = []
        self.states = 0
        self.reports = []  # (diagnostics stamp in s, "state reports" count)
        self.node_rates = []  # the node's own measured ptz_state rate, Hz
        rospy.Subscriber('/ptz/joint_states', JointState, self.on_joint_state, queue_size=100)
        rospy.Subscriber('/ptz/ptz_state', PtzState, self.on_state, queue_size=100)
        rospy.Subscriber('/diagnostics', DiagnosticArray, self.on_diagnostics, queue_size=100)

    def on_joint_state(self, message):
        with self.lock:
            self.joint_stamps.append(message.header.stamp.to_sec())

    def on_state(self, _):
        with self.lock:
            self.states += 1

    def on_diagnostics(self, message):
        for status in message.status:
            values = {item.key: item.value for item in status.values}
            with self.lock:
                if 'state reports' in values:
                    self.reports.append((message.header.stamp.to_sec(), int(values['state reports'])))
                if status.name.endswith('ptz_state rate') and 'Actual frequency (Hz)' in values:
                    self.node_rates.append(float(values['Actual frequency (Hz)']))

    def flooded(self):
        """The backend has taken in at least 10x its normal state rate since the first report seen."""
        with self.lock:
            if len(self.reports) < 2 or self.reports[-1][0] <= self.reports[0][0]:
                return False
            (start, first), (end, last) = self.reports[0], self.reports[-1]
            return (last - first) / (end - start) >= 10 * NORMAL_REPORTS

    def test_ptz_state_stays_10_hz_and_the_flood_is_coalesced(self):
        self.assertTrue(wait_until(lambda: self.states > 0, START_WAIT), 'no ptz_state')
        self.assertTrue(wait_until(self.flooded, START_WAIT), 'the flood never reached the backend: %s' %
                        self.reports[-3:])
        # A window of the node's ticks, from now on (past start-up and the first flooded seconds).
        with self.lock:
            del self.joint_stamps[:]
            self.states = 0
            del self.node_rates[:]
            self.reports = self.reports[-1:]
        self.assertTrue(wait_until(lambda: len(self.joint_stamps) >= 2 and
                                   self.joint_stamps[-1] - self.joint_stamps[0] >= WINDOW, 4 * WINDOW),
                        'joint_states stopped: %d in the window' % len(self.joint_stamps))
        self.assertTrue(wait_until(lambda: len(self.reports) >= 2 and len(self.node_rates) >= 1, 3 * WINDOW),
                        'no diagnostics during the window')
        with self.lock:
            stamps = list(self.joint_stamps)
            states = self.states
            reports = list(self.reports)
            node_rates = list(self.node_rates)

        rate = (len(stamps) - 1) / (stamps[-1] - stamps[0])
        rospy.loginfo('joint_states: %d stamps over %.3f s: %.3f Hz; ptz_state: %d messages; node-measured ptz_state '
                      'rates %s', len(stamps), stamps[-1] - stamps[0], rate, states, node_rates)
        self.assertAlmostEqual(rate, RATE, delta=RATE * TOLERANCE,
                               msg='the 10 Hz tick ran at %.3f Hz under the flood' % rate)
        # ptz_state leaves on that tick: as many arrived as joint_states (one or two at the window's edges aside).
        self.assertLessEqual(abs(states - len(stamps)), 3, 'ptz_state %d vs joint_states %d' % (states, len(stamps)))
        last_rate = node_rates[-1]
        self.assertAlmostEqual(last_rate, RATE, delta=RATE * TOLERANCE,
                               msg='the node measured ptz_state at %.3f Hz under the flood' % last_rate)

        (start, first), (end, last) = reports[0], reports[-1]
        report_rate = (last - first) / (end - start)
        rospy.loginfo('state reports taken in: %.0f /s, %.0f per ptz_state message', report_rate, report_rate / rate)
        self.assertGreaterEqual(report_rate, 10 * NORMAL_REPORTS,
                                'the backend took in %.0f states/s: the flood did not reach it' % report_rate)


if __name__ == '__main__':
    rospy.init_node('test_state_rate_flood')
    rostest.rosrun('ptz_action_server', 'ptz_state_rate_flood', StateRateFloodTest)
