"""The scenario harness of the system rostests: the whole chair (`wheelchair` process with
chair_sim.yaml) drives the simulator (`_motor_bus:=udp`, the CAN path); the test watches
what a rider and a carer would see (/hmi/announce, /safety/status) and the simulator's ground
truth (/sim/ground_truth, /sim/collision), which the stack itself never reads.

Waits are in wall seconds (generous: the machine is loaded), measurements in simulated time."""
import math
import threading
import time
from typing import Dict, NamedTuple

import rospkg
import rospy
import yaml
from geometry_msgs.msg import PoseStamped, PoseWithCovarianceStamped
from nav_msgs.msg import Odometry, Path
from std_msgs.msg import Bool, Empty, String
from wheelchair_msgs.msg import PlanCertificate
from wheelchair_msgs.srv import GoToPlace
from wheelchair_sim.srv import AddObstacle, SetPose


WORLDS = rospkg.RosPack().get_path("wheelchair_test") + "/worlds"


def place(name, world="flat"):
    """(x, y, yaw) of a named place of a test world."""
    with open(f"{WORLDS}/{world}.places.yaml") as f:
        for p in yaml.safe_load(f)["places"]:
            if p["name"] == name:
                return p["x"], p["y"], p["yaw"]
    raise KeyError(name)


def yaw_of(q):
    return 2.0 * math.atan2(q.z, q.w)


def angle_diff(a, b):
    return math.remainder(a - b, 2.0 * math.pi)


LOGS = ("controller", "announcements", "safety")  # the Scenario's (t, text) logs


class Mark(NamedTuple):
    """A `since` for the questions of Scenario (Scenario.mark()): the simulated time and how
    long each log was. A log is cut at that position, not at that time: the test's clock moves
    in the simulator's 5 ms steps and lags on a loaded machine, so a message received before
    the mark can carry the mark's own time. Cut by time, one leg's final 'goal_reached' (or
    'aborted') also counted as the next leg's, read right after that leg's drive began."""
    time: float
    lengths: Dict[str, int]


def time_of(since):
    """The simulated time [s] of a `since` (a Mark or a time)."""
    return since.time if isinstance(since, Mark) else since


class Scenario:
    """One rostest's view of the running chair; every callback only records."""

    def __init__(self, name):
        rospy.init_node(name)
        self.lock = threading.Lock()
        self.truth = None  # (t, x, y, yaw, v, w)
        self.truth_path = []  # (t, x, y)
        self.collided = False
        self.safety = []  # (t, text) every change
        self.announcements = []  # (t, text)
        self.localized = ""
        self.certificates = []
        self.controller = []  # (t, status) every change
        self.plans = []
        self.switch_pub = rospy.Publisher("/switch", Empty, queue_size=10)
        self.goal_pub = rospy.Publisher("/move_base_simple/goal", PoseStamped, queue_size=1)
        self.init_pub = rospy.Publisher("/initialpose", PoseWithCovarianceStamped, queue_size=1,
                                        latch=True)
        self.subs = [
            rospy.Subscriber("/sim/ground_truth", Odometry, self._on_truth, queue_size=20),
            rospy.Subscriber("/sim/collision", Bool, self._on_collision),
            rospy.Subscriber("/safety/status", String, self._append("safety")),
            rospy.Subscriber("/hmi/announce", String, self._append("announcements"), queue_size=50),
            rospy.Subscriber("/kld/localized", String, self._on_localized),
            rospy.Subscriber("/plan_certificate", PlanCertificate, self._on_certificate),
            rospy.Subscriber("/controller/status", String, self._append("controller")),
            rospy.Subscriber("/plan", Path, self._on_plan),
        ]

    # ---- recording --------------------------------------------------------------------------
    def _on_truth(self, msg):
        p = msg.pose.pose
        t = msg.header.stamp.to_sec()
        with self.lock:
            self.truth = (t, p.position.x, p.position.y, yaw_of(p.orientation),
                          msg.twist.twist.linear.x, msg.twist.twist.angular.z)
            self.truth_path.append((t, p.position.x, p.position.y))

    def _on_collision(self, msg):
        if msg.data:
            self.collided = True

    def _append(self, field):
        def record(msg):
            with self.lock:
                getattr(self, field).append((rospy.get_time(), msg.data))
        return record

    def _on_localized(self, msg):
        self.localized = msg.data

    def _on_certificate(self, msg):
        with self.lock:
            self.certificates.append(msg)

    def _on_plan(self, msg):
        with self.lock:
            self.plans.append(msg)

    # ---- waiting ------------------------------------------------------------------------------
    @staticmethod
    def wait(predicate, wall_timeout, period=0.05):
        """True once predicate() holds; False after wall_timeout wall seconds."""
        deadline = time.monotonic() + wall_timeout
        while time.monotonic() < deadline and not rospy.is_shutdown():
            if predicate():
                return True
            time.sleep(period)
        return bool(predicate())

    def sim_sleep(self, seconds, wall_timeout=60.0):
        """Sleeps `seconds` of simulated time (the simulator owns the clock)."""
        end = rospy.get_time() + seconds
        return self.wait(lambda: rospy.get_time() >= end, wall_timeout)

    def wait_ready(self, wall_timeout=60.0):
        """The simulator runs, the chair's nodes answer: clock, truth, map in the planner, HMI."""
        ok = self.wait(lambda: self.truth is not None and rospy.get_time() > 0.5, wall_timeout)
        if not ok:
            return "no /clock or /sim/ground_truth from the simulator"
        for service in ["/go_to_place", "/sim/teleport", "/planner/make_plan"]:
            try:
                rospy.wait_for_service(service, timeout=wall_timeout)
            except rospy.ROSException:
                return f"service {service} not up"
        return ""

    def initialize(self, x, y, yaw, wall_timeout=40.0):
        """rviz's 2D Pose Estimate at the true pose; waits for the localizer's "localized"."""
        msg = PoseWithCovarianceStamped()
        msg.header.frame_id = "map"
        msg.header.stamp = rospy.Time.now()
        msg.pose.pose.position.x, msg.pose.pose.position.y = x, y
        msg.pose.pose.orientation.z, msg.pose.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        msg.pose.covariance[0] = msg.pose.covariance[7] = 0.05 ** 2
        msg.pose.covariance[35] = 0.05 ** 2
        self.localized = ""
        self.init_pub.publish(msg)
        if not self.wait(lambda: self.localized == "localized", wall_timeout):
            return False
        # map -> odom needs two stamps before the planner's latest-time lookup works (a goal
        # 0.1 s after the initial pose is refused: "extrapolation into the past").
        self.sim_sleep(1.0)
        return self.localized == "localized"

    # ---- commands -----------------------------------------------------------------------------
    def go_to_place(self, name):
        """The named place through the HMI's service; returns (accepted, message)."""
        response = rospy.ServiceProxy("/go_to_place", GoToPlace)(name)
        return response.accepted, response.message

    def send_goal(self, x, y, yaw):
        goal = PoseStamped()
        goal.header.frame_id = "map"
        goal.header.stamp = rospy.Time.now()
        goal.pose.position.x, goal.pose.position.y = x, y
        goal.pose.orientation.z, goal.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        self.goal_pub.publish(goal)

    def press(self):
        self.switch_pub.publish(Empty())

    def add_obstacle(self, x, y, radius=0.15, appear_time=0.0):
        return rospy.ServiceProxy("/sim/add_obstacle", AddObstacle)(x, y, radius, appear_time)

    def teleport(self, x, y, yaw):
        return rospy.ServiceProxy("/sim/teleport", SetPose)(x, y, yaw)

    # ---- questions: `since` is a Mark (exact) or a simulated time [s] ---------------------------
    def mark(self):
        """Now, as a `since` that leaves out every message already received."""
        with self.lock:
            return Mark(rospy.get_time(), {log: len(getattr(self, log)) for log in LOGS})

    def received(self, log, since=0.0):
        """The (t, text) records of `log` (one of LOGS) received since `since`."""
        with self.lock:
            records = list(getattr(self, log))
        if isinstance(since, Mark):
            return records[since.lengths[log]:]
        return [(t, text) for t, text in records if t >= since]

    def controller_says(self, prefix, since=0.0):
        return any(s.startswith(prefix) for _, s in self.received("controller", since))

    def announced(self, text, since=0.0):
        return any(text in s for _, s in self.received("announcements", since))

    def safety_stop(self, since=0.0):
        """The first stop reason published since `since`, or ""."""
        return next((s for _, s in self.received("safety", since) if s != "safe"), "")

    def error_to(self, x, y, yaw):
        """(distance [m], heading error [rad]) of the true pose to (x, y, yaw)."""
        _, tx, ty, tyaw, _, _ = self.truth
        return math.hypot(tx - x, ty - y), abs(angle_diff(tyaw, yaw))

    def at_rest(self):
        return self.truth is not None and abs(self.truth[4]) < 0.01 and abs(self.truth[5]) < 0.02

    def travelled(self, since):
        """Path length of the true trajectory since `since`."""
        with self.lock:
            points = [(x, y) for t, x, y in self.truth_path if t >= time_of(since)]
        return sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(points, points[1:]))

    def start_driving(self, test, start, name, metres):
        """Ready, localized at `start`, on the way to place `name` and `metres` driven; returns
        the Mark of the goal. Fails `test` (a TestCase) otherwise."""
        test.assertEqual(self.wait_ready(), "")
        test.assertTrue(self.initialize(*start), "not localized: " + self.describe())
        accepted, message = self.go_to_place(name)
        test.assertTrue(accepted, message)
        t_go = self.mark()
        test.assertTrue(self.wait(lambda: self.travelled(t_go) > metres, 60.0),
                        "the chair did not start: " + self.describe(t_go))
        return t_go

    def drive_to_place(self, name, wall_timeout):
        """go_to_place + wait for the controller's goal_reached (or a stop/abort)."""
        since = self.mark()
        accepted, message = self.go_to_place(name)
        if not accepted:
            return False, message
        done = self.wait(lambda: self.controller_says("goal_reached", since) or
                         self.controller_says("aborted", since) or self.collided, wall_timeout)
        return done and self.controller_says("goal_reached", since), self.describe(since)

    def describe(self, since=0.0):
        """What happened since `since`, for failure messages."""
        c = [s for _, s in self.received("controller", since)][-6:]
        a = [s for _, s in self.received("announcements", since)][-6:]
        f = [s for _, s in self.received("safety", since)][-4:]
        pose = "none" if self.truth is None else "(%.2f, %.2f, %.2f)" % self.truth[1:4]
        return (f"controller {c}; announced {a}; safety {f}; localized '{self.localized}'; "
                f"true pose {pose}; collided {self.collided}")
