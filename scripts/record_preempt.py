"""Records pan and tilt of /ptz/ptz_state while a goal is preempted by a second one, into a CSV file.

The first goal (pan 1.2, tilt 0.5) is preempted once the pan passes 0.4 rad by a second one (pan -0.8, tilt -0.3)
from the same client; the run ends 0.5 s after the second goal's result. Columns: t (s from the first goal), pan,
tilt (rad), mode, event (the goal sent or ended at that state, else empty).
Usage: record_preempt.py OUT.csv
"""
import csv
import sys
import threading

import actionlib
import rospy
from ptz_action_server.msg import PtzAction, PtzGoal, PtzState


def main():
    rospy.init_node("record_preempt", anonymous=True)
    rows = []
    lock = threading.Lock()
    crossed = threading.Event()
    pending_event = []
    start = [None]

    def on_state(state):
        with lock:
            if start[0] is None:
                return
            event = pending_event.pop(0) if pending_event else ""
            rows.append((rospy.get_time() - start[0], state.pan, state.tilt, state.mode, event))
            if state.pan > 0.4:
                crossed.set()

    client = actionlib.SimpleActionClient("/ptz/move_ptz/position_abs", PtzAction)
    if not client.wait_for_server(rospy.Duration(30)):
        sys.exit("no action server at /ptz/move_ptz/position_abs")
    client.send_goal_and_wait(PtzGoal(pan=0.0, tilt=0.0, zoom=1.0), rospy.Duration(30))
    rospy.Subscriber("/ptz/ptz_state", PtzState, on_state)
    rospy.sleep(0.5)  # a few states at rest before the first goal
    with lock:
        start[0] = rospy.get_time() - 0.5
        pending_event.append("goal 1 (1.2, 0.5)")
    client.send_goal(PtzGoal(pan=1.2, tilt=0.5, zoom=1.0))
    if not crossed.wait(30):
        sys.exit("the pan never passed 0.4 rad")
    with lock:
        pending_event.append("goal 2 (-0.8, -0.3) preempts")
    client.send_goal(PtzGoal(pan=-0.8, tilt=-0.3, zoom=1.0))
    client.wait_for_result(rospy.Duration(30))
    with lock:
        pending_event.append("goal 2 " + actionlib.GoalStatus.to_string(client.get_state()).lower())
    rospy.sleep(0.6)
    with open(sys.argv[1], "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["t", "pan", "tilt", "mode", "event"])
        with lock:
            for t, pan, tilt, mode, event in rows:
                writer.writerow(["%.3f" % t, "%.5f" % pan, "%.5f" % tilt, mode, event])

if __name__ == "__main__":
    main()
