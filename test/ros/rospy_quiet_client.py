#!/usr/bin/python3
"""rospy's SimpleActionClient against the node: immediate goals must end without the client logging
"Got a transition callback on a goal handle that we're not tracking" (ros/actionlib#206), and none may lose its
result. The node holds status changes for ~status_hold after each goal (without it, most such goals trip the race
on this machine and their clients wait for a result that came before they listened)."""
import logging
import math
import sys
import threading
import unittest

import actionlib
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus

from ptz_action_server.msg import PtzAction, PtzGoal

GOALS = 150
NOT_TRACKING = "not tracking"


class ErrorCounter(logging.Handler):
    """Counts the error records rospy logs (rospy.logerr goes to the 'rosout' logger)."""

    def __init__(self):
        super().__init__(level=logging.ERROR)
        self.lock = threading.Lock()
        self.messages = []

    def emit(self, record):
        with self.lock:
            self.messages.append(record.getMessage())

    def count(self, text):
        with self.lock:
            return sum(1 for message in self.messages if text in message)


def run_immediate_goals(namespace, result_timeout):
    """Sends GOALS immediate goals the way a new user would: zero-length moves and NaN goals, each followed by
    wait_for_result. Returns (rospy errors about untracked goal handles, goals whose result never came, wrong ends)."""
    counter = ErrorCounter()
    logging.getLogger("rosout").addHandler(counter)
    client = actionlib.SimpleActionClient(namespace + "/move_ptz/position_abs", PtzAction)
    if not client.wait_for_server(rospy.Duration(60.0)):
        raise AssertionError("no action server in " + namespace)
    lost = 0
    wrong = []
    try:
        for index in range(GOALS):
            nan_goal = index % 2 == 1
            goal = PtzGoal(pan=math.nan if nan_goal else 0.0, tilt=0.0, zoom=1.0)
            client.send_goal(goal)
            if not client.wait_for_result(rospy.Duration(result_timeout)):
                lost += 1
                continue
            expected = GoalStatus.REJECTED if nan_goal else GoalStatus.SUCCEEDED
            if client.get_state() != expected:
                wrong.append((index, client.get_state(), client.get_goal_status_text()))
    finally:
        logging.getLogger("rosout").removeHandler(counter)
    return counter.count(NOT_TRACKING), lost, wrong


class QuietRospyClientTest(unittest.TestCase):
    def test_immediate_goals_are_quiet_and_never_lose_a_result(self):
        errors_on, lost_on, wrong_on = run_immediate_goals("/ptz", result_timeout=20.0)
        print("default status_hold: %d of %d immediate goals logged 'not tracking', %d results lost"
              % (errors_on, GOALS, lost_on))
        sys.stdout.flush()
        self.assertEqual(lost_on, 0, "goals whose result never reached the client")
        self.assertEqual(wrong_on, [], "goals that ended otherwise than expected")
        self.assertEqual(errors_on, 0, "rospy logged 'not tracking' with the status hold on")


if __name__ == "__main__":
    rospy.init_node("rospy_quiet_client")
    rostest.rosrun("ptz_action_server", "rospy_quiet_client", QuietRospyClientTest, sys.argv)
