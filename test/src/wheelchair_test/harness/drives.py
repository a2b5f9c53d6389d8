"""A client of the navigator, as rviz, a script or the HMI is: goals through its actions
(`navigate`: a pose or a named place, with the rider's reasons; `move_base`: move_base_msgs),
cancel, and everything it says, recorded: every result message of either action by goal id (so a
test can count them: exactly one per drive), the states on /navigator/state. Used with a Rider
(the simulator's truth, the HMI's announcements) by the navigation rostests and
bench/navigation. Waits are in wall seconds."""
import math
import threading
import time

import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped
from move_base_msgs.msg import MoveBaseAction, MoveBaseActionResult, MoveBaseGoal
from wheelchair_msgs.msg import (NavigateAction, NavigateActionResult, NavigateGoal,
                                 NavigateResult, NavigatorState)

TERMINAL = (GoalStatus.SUCCEEDED, GoalStatus.ABORTED, GoalStatus.REJECTED, GoalStatus.PREEMPTED,
            GoalStatus.RECALLED)


def _trigger_service():
    """std_srvs/Trigger as a rospy service class (Debian ships no Python std_srvs, so neither
    this process nor rosservice can load it): request and response generated from their
    definitions, the service's md5 as std_srvs defines it."""
    from genpy.dynamic import generate_dynamic

    request = generate_dynamic("std_srvs/TriggerRequest", "")["std_srvs/TriggerRequest"]
    response = generate_dynamic("std_srvs/TriggerResponse", "bool success\nstring message")[
        "std_srvs/TriggerResponse"]
    return type("Trigger", (), {"_type": "std_srvs/Trigger",
                                "_md5sum": "937c9679a518e3a18d831e57125ea522",
                                "_request_class": request, "_response_class": response})


def clear_obstacles():
    """The simulator's /sim/clear_obstacles: every unmapped obstacle gone at once."""
    return rospy.ServiceProxy("/sim/clear_obstacles", _trigger_service())()


def check_arrived(test, rider, drive, name, since):
    """Asserts (unittest `test`) that `drive` reached place `name`: the action SUCCEEDED with
    REACHED, the chair at rest within 15 cm and 0.2 rad of it (the simulator's truth), exactly
    one result message, no contact since `since`."""
    from .worlds import place

    told = drive.describe() + "; " + rider.describe(since)
    test.assertEqual(drive.status(), GoalStatus.SUCCEEDED, told)
    test.assertEqual(drive.result().reason, NavigateResult.REACHED, told)
    test.assertTrue(rider.wait(rider.at_rest, 20.0))
    distance, heading = rider.error_to(*place(name))
    test.assertLess(distance, 0.15, rider.describe(since))
    test.assertLess(heading, 0.2, rider.describe(since))
    rider.sim_sleep(1.0)
    test.assertEqual(len(drive.result_messages()), 1, drive.result_messages())
    test.assertFalse(rider.collided, "contact: " + rider.describe(since))


def reason_name(reason):
    """NavigateResult's constant name of `reason` ("BLOCKED")."""
    for name in dir(NavigateResult):
        if name.isupper() and getattr(NavigateResult, name) == reason:
            return name
    return str(reason)


def target(x, y, yaw, frame="map"):
    pose = PoseStamped()
    pose.header.frame_id = frame
    pose.header.stamp = rospy.Time.now()
    pose.pose.position.x, pose.pose.position.y = x, y
    pose.pose.orientation.z, pose.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return pose


class Drives:
    """The navigator's two action clients and what it says. Construct after rospy.init_node."""

    def __init__(self):
        self.lock = threading.Lock()
        self.results = {}  # goal id -> [(sim t, status, result)], every result message
        self.states = []  # (sim t, NavigatorState) every message
        self.navigate = actionlib.SimpleActionClient("/navigate", NavigateAction)
        self.move_base = actionlib.SimpleActionClient("/move_base", MoveBaseAction)
        self.subs = [
            rospy.Subscriber("/navigate/result", NavigateActionResult, self._on_result,
                             queue_size=20),
            rospy.Subscriber("/move_base/result", MoveBaseActionResult, self._on_result,
                             queue_size=20),
            rospy.Subscriber("/navigator/state", NavigatorState, self._on_state, queue_size=50),
        ]

    def _on_result(self, msg):
        with self.lock:
            self.results.setdefault(msg.status.goal_id.id, []).append(
                (rospy.get_time(), msg.status.status, msg.result))

    def _on_state(self, msg):
        with self.lock:
            self.states.append((rospy.get_time(), msg))

    def wait_servers(self, wall_timeout=60.0):
        return (self.navigate.wait_for_server(rospy.Duration(wall_timeout))
                and self.move_base.wait_for_server(rospy.Duration(wall_timeout)))

    # ---- goals --------------------------------------------------------------------------------
    def go(self, place=None, pose=None):
        """A goal of `navigate`: a named place or (x, y, yaw). Returns the Drive."""
        goal = NavigateGoal()
        if place:
            goal.place = place
        else:
            goal.target_pose = target(*pose)
        return Drive(self, self.navigate, goal)

    def go_move_base(self, x, y, yaw):
        """A goal of `move_base`, as rviz or a move_base script gives it. Returns the Drive."""
        return Drive(self, self.move_base, MoveBaseGoal(target_pose=target(x, y, yaw)))

    # ---- questions ----------------------------------------------------------------------------
    def states_since(self, t):
        with self.lock:
            return [s for ts, s in self.states if ts >= t]

    def was_in(self, state, t):
        """Whether the navigator was in `state` (NavigatorState.WAITING...) since sim time t."""
        return any(s.state == state for s in self.states_since(t))

    def sentences_since(self, t):
        out = []
        for s in self.states_since(t):
            if s.sentence and (not out or out[-1] != s.sentence):
                out.append(s.sentence)
        return out


class Drive:
    """One goal: its id, its end (the action client's), every result message seen for it."""

    def __init__(self, drives, client, goal):
        self.drives = drives
        self.client = client
        self.sent = rospy.get_time()
        self.id = None
        client.send_goal(goal)
        # SimpleActionClient keeps the goal id in its goal handle.
        self.id = client.gh.comm_state_machine.action_goal.goal_id.id

    def done(self):
        """Ended, and its result received: the goal's status can say REJECTED before the
        result message arrives (get_result() is None until then)."""
        return (self.client.get_state() in TERMINAL
                and self.client.simple_state == actionlib.SimpleGoalState.DONE)

    def wait(self, wall_timeout):
        """True once the drive ended within `wall_timeout` wall seconds."""
        deadline = time.monotonic() + wall_timeout
        while time.monotonic() < deadline and not rospy.is_shutdown():
            if self.done():
                return True
            time.sleep(0.05)
        return self.done()

    def cancel(self):
        self.client.cancel_goal()

    def status(self):
        return self.client.get_state()

    def result(self):
        return self.client.get_result()

    def result_messages(self):
        """Every result message of either action that names this goal."""
        with self.drives.lock:
            return list(self.drives.results.get(self.id, []))

    def describe(self):
        r = self.result()
        told = self.drives.sentences_since(self.sent)[-6:]
        if r is None or not hasattr(r, "reason"):
            return f"status {self.status()}; navigator said {told}"
        return (f"status {self.status()}, {reason_name(r.reason)}: '{r.sentence}' [{r.detail}]; "
                f"navigator said {told}")


def layer_occupied_near(grid, point, radius=0.4):
    """Whether an OccupancyGrid (the live obstacle layer) has an occupied cell (>= 50) within
    `radius` of `point` (x, y), sampled on a 17 x 17 lattice; None while no layer was seen."""
    if grid is None:
        return None
    info = grid.info
    for dy in range(-8, 9):
        for dx in range(-8, 9):
            x, y = point[0] + dx * radius / 8, point[1] + dy * radius / 8
            i = int((x - info.origin.position.x) / info.resolution)
            j = int((y - info.origin.position.y) / info.resolution)
            if 0 <= i < info.width and 0 <= j < info.height and grid.data[j * info.width + i] >= 50:
                return True
    return False
