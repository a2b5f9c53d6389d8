"""The rider (and the carer) of a running chair, as one ROS node: gives a pose estimate, a goal
(a pose, a named place through the HMI, or one-switch presses on the HMI's scanning) and waits
for its outcome, while recording what a rider and a carer would see (/hmi/announce, the typed
/safety/status and /localization/status, the controller's /controller/status) and the
simulator's ground truth (/sim/ground_truth, /sim/collision), which the stack itself never
reads. Used by the system rostests, the demo and bench/system.

Waits are in wall seconds (generous: the machine is loaded), measurements in simulated time."""
import math
import subprocess
import threading
import time
from typing import Dict, NamedTuple

import rospy
from geometry_msgs.msg import PoseStamped, PoseWithCovarianceStamped
from nav_msgs.msg import Odometry, Path
from std_msgs.msg import Bool, Empty, String
from wheelchair_msgs.msg import LocalizationStatus, PlanCertificate, SafetyStatus
from wheelchair_msgs.srv import GoToPlace

LOGS = ("controller", "announcements", "safety")  # the Rider's (t, record) logs
READY_SERVICES = ("/go_to_place", "/sim/teleport", "/planner/make_plan")


class RiderError(RuntimeError):
    """What the rider waited for did not happen; the message says what it saw."""


def call(name, service_type, *args, wall_timeout=20.0):
    """Calls service `name` and returns its response; raises RiderError when it is not up or
    does not answer within `wall_timeout` wall seconds (a rospy call alone can wait for ever,
    and a test killed by its time limit reports nothing of what it saw)."""
    try:
        rospy.wait_for_service(name, timeout=wall_timeout)
    except rospy.ROSException:
        raise RiderError(f"service {name} is not up after {wall_timeout:.0f} s") from None
    result = {}

    def run():
        try:
            result["response"] = rospy.ServiceProxy(name, service_type)(*args)
        except Exception as error:  # raised again in the caller's thread
            result["error"] = error

    worker = threading.Thread(target=run, daemon=True)
    worker.start()
    worker.join(wall_timeout)
    if worker.is_alive():
        raise RiderError(f"service {name} did not answer within {wall_timeout:.0f} s")
    if "error" in result:
        raise result["error"]
    return result["response"]


def yaw_of(q):
    return 2.0 * math.atan2(q.z, q.w)


def angle_diff(a, b):
    return math.remainder(a - b, 2.0 * math.pi)


def _orientation(msg, yaw):
    msg.orientation.z, msg.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)


def describe_stop(status):
    """A SafetyStatus for messages: "<sentence> (<detail>)"."""
    return f"{status.sentence} ({status.detail})" if status.detail else status.sentence


def point_ahead(plan, x, y, distance):
    """The point `distance` [m] along the plan (nav_msgs/Path) from its vertex nearest to (x, y),
    or None if the plan is shorter."""
    points = [(p.pose.position.x, p.pose.position.y) for p in plan.poses]
    i = min(range(len(points)), key=lambda k: math.hypot(points[k][0] - x, points[k][1] - y))
    walked = 0.0
    for a, b in zip(points[i:], points[i + 1:]):
        step = math.hypot(b[0] - a[0], b[1] - a[1])
        if walked + step >= distance:
            f = (distance - walked) / step
            return a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])
        walked += step
    return None


class Mark(NamedTuple):
    """A `since` for the questions of Rider (Rider.mark()): the simulated time and how long
    each log was. A log is cut at that position, not at that time: the test's clock moves in
    the simulator's 5 ms steps and lags on a loaded machine, so a message received before the
    mark can carry the mark's own time. Cut by time, one leg's final 'goal_reached' (or
    'aborted') also counted as the next leg's, read right after that leg's drive began."""
    time: float
    lengths: Dict[str, int]


def time_of(since):
    """The simulated time [s] of a `since` (a Mark or a time)."""
    return since.time if isinstance(since, Mark) else since


class Rider:
    """One view of the running chair; every callback only records. `name`: rospy.init_node
    with it (None: this process already is a node)."""

    def __init__(self, name=None):
        if name is not None:
            rospy.init_node(name)
        self.lock = threading.Lock()
        self.truth = None  # (t, x, y, yaw, v, w)
        self.truth_path = []  # (t, x, y)
        self.collided = False
        self.safety = []  # (t, SafetyStatus) every change
        self.announcements = []  # (t, text)
        self.localization = None  # the localizer's last LocalizationStatus
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
            rospy.Subscriber("/safety/status", SafetyStatus, self._on_safety, queue_size=20),
            rospy.Subscriber("/hmi/announce", String, self._on_announcement, queue_size=50),
            rospy.Subscriber("/localization/status", LocalizationStatus, self._on_localization),
            rospy.Subscriber("/plan_certificate", PlanCertificate, self._on_certificate),
            rospy.Subscriber("/controller/status", String, self._on_controller),
            rospy.Subscriber("/plan", Path, self._on_plan),
        ]

    # ---- recording --------------------------------------------------------------------------
    def record(self, log, value):
        """Appends (now, value) to `log` (one of LOGS): what every subscriber does."""
        with self.lock:
            getattr(self, log).append((rospy.get_time(), value))

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

    def _on_safety(self, msg):
        self.record("safety", msg)

    def _on_announcement(self, msg):
        self.record("announcements", msg.data)

    def _on_controller(self, msg):
        self.record("controller", msg.data)

    def _on_localization(self, msg):
        self.localization = msg

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

    def wait_ready(self, wall_timeout=60.0, services=READY_SERVICES):
        """The simulator runs, the chair's nodes answer: clock, truth, map in the planner, HMI.
        Returns "" or what is missing."""
        ok = self.wait(lambda: self.truth is not None and rospy.get_time() > 0.5, wall_timeout)
        if not ok:
            return "no /clock or /sim/ground_truth from the simulator"
        for service in services:
            try:
                rospy.wait_for_service(service, timeout=wall_timeout)
            except rospy.ROSException:
                return f"service {service} not up"
        return ""

    def localized(self):
        return self.localization is not None and self.localization.localized

    def _wait_localized(self, wall_timeout, settle):
        if not self.wait(self.localized, wall_timeout):
            return False
        # map -> odom needs two stamps before the planner's latest-time lookup works (a goal
        # 0.1 s after the initial pose is refused: "extrapolation into the past").
        self.sim_sleep(settle)
        return self.localized()

    # ---- commands -----------------------------------------------------------------------------
    def initialize(self, x, y, yaw, wall_timeout=40.0, std=0.05, settle=1.0):
        """rviz's 2D Pose Estimate at (x, y, yaw) with std-dev `std` (m and rad); waits for the
        localizer's `localized` (a fresh verdict, not one from before the estimate)."""
        msg = PoseWithCovarianceStamped()
        msg.header.frame_id = "map"
        msg.header.stamp = rospy.Time.now()
        msg.pose.pose.position.x, msg.pose.pose.position.y = x, y
        _orientation(msg.pose.pose, yaw)
        msg.pose.covariance[0] = msg.pose.covariance[7] = std ** 2
        msg.pose.covariance[35] = std ** 2
        self.localization = None
        self.init_pub.publish(msg)
        return self._wait_localized(wall_timeout, settle)

    def global_localization(self, wall_timeout=60.0, settle=1.0):
        """The localizer's global_localization service (particles over the whole map); waits
        for `localized`. (std_srvs has no Python bindings on Debian unless python3-std-srvs is
        installed: through rosservice.)"""
        self.localization = None
        subprocess.run(["rosservice", "call", "/global_localization"], check=True,
                       capture_output=True, timeout=30)
        return self._wait_localized(wall_timeout, settle)

    def go_to_place(self, name):
        """The named place through the HMI's service; returns (accepted, message)."""
        response = call("/go_to_place", GoToPlace, name)
        return response.accepted, response.message

    def send_goal(self, x, y, yaw):
        goal = PoseStamped()
        goal.header.frame_id = "map"
        goal.header.stamp = rospy.Time.now()
        goal.pose.position.x, goal.pose.position.y = x, y
        _orientation(goal.pose, yaw)
        self.goal_pub.publish(goal)

    def press(self):
        self.switch_pub.publish(Empty())

    def choose_by_switch(self, name, room, sim_timeout=90.0, quiet_timeout=30.0,
                         check=lambda: None):
        """Chooses place `name` of `room` with one switch, like the rider: presses when its
        room, then the place is highlighted on /hmi/announce, then confirms. Returns (presses,
        scan steps) once the HMI says "Going to <name>". Raises RiderError when the HMI does not
        listen, goes quiet for `quiet_timeout` wall seconds or never offers the place within
        `sim_timeout` simulated seconds; `check()` may raise too (e.g. a process died)."""
        if not self.wait(lambda: self.switch_pub.get_num_connections() > 0, quiet_timeout):
            raise RiderError("the HMI does not listen to /switch")
        presses, steps, seen = 0, 0, len(self.announcements)
        deadline = rospy.get_time() + sim_timeout
        while True:
            check()
            if not self.wait(lambda: len(self.announcements) > seen, quiet_timeout, period=0.02):
                raise RiderError(f"{name}: the scanner went quiet: " + self.describe())
            with self.lock:
                new = [text for _, text in self.announcements[seen:]]
                seen = len(self.announcements)
            for text in new:
                steps += text.endswith("?") and not text.startswith("Go to")  # a highlight
                if text.startswith("Going to " + name):
                    return presses, steps
                if (text.startswith("Go to " + name) or text.endswith(room + "?")
                        or text.endswith(name + "?")):
                    self.press()
                    presses += 1
            if rospy.get_time() > deadline:
                raise RiderError(f"the scanner never offered {name} ({presses} presses)")

    def add_obstacle(self, x, y, radius=0.15, appear_time=0.0):
        from wheelchair_sim.srv import AddObstacle

        return call("/sim/add_obstacle", AddObstacle, x, y, radius, appear_time)

    def stops_for_person(self, test, person, radius, front_offset=0.30, rest_wall_timeout=60.0):
        """A person (a disc of `radius` at `person` = (x, y)) appears now; fails `test` unless
        the supervisor stops the chair for it (OBSTACLE, "in the way") and it comes to rest
        without touching them (the simulator's contact check). Returns (mark, stop, gap): the
        Mark of the appearance, the SafetyStatus, the gap [m] left between the chair's front
        (`front_offset` ahead of the axle, chair.yaml's footprint) and the person."""
        t_person = self.mark()
        test.assertTrue(self.add_obstacle(person[0], person[1], radius, 0.0).success)
        test.assertTrue(self.wait(lambda: self.first_stop(t_person), 30.0),
                        "no safety stop: " + self.describe(t_person))
        _, stop = self.first_stop(t_person)
        test.assertEqual(stop.reason, SafetyStatus.OBSTACLE, describe_stop(stop))
        test.assertIn("in the way", stop.sentence)
        test.assertTrue(self.wait(self.at_rest, rest_wall_timeout),
                        "still moving: " + self.describe(t_person))
        self.sim_sleep(1.0)
        test.assertFalse(self.collided, "the chair touched the person: " + self.describe(t_person))
        _, fx, fy, fyaw, _, _ = self.truth
        front = (fx + front_offset * math.cos(fyaw), fy + front_offset * math.sin(fyaw))
        return t_person, stop, math.hypot(person[0] - front[0], person[1] - front[1]) - radius

    def teleport(self, x, y, yaw):
        from wheelchair_sim.srv import SetPose

        return call("/sim/teleport", SetPose, x, y, yaw)

    # ---- questions: `since` is a Mark (exact) or a simulated time [s] ---------------------------
    def mark(self):
        """Now, as a `since` that leaves out every message already received."""
        with self.lock:
            return Mark(rospy.get_time(), {log: len(getattr(self, log)) for log in LOGS})

    def received(self, log, since=0.0):
        """The (t, record) entries of `log` (one of LOGS) received since `since`."""
        with self.lock:
            records = list(getattr(self, log))
        if isinstance(since, Mark):
            return records[since.lengths[log]:]
        return [(t, value) for t, value in records if t >= since]

    def controller_says(self, prefix, since=0.0):
        return any(s.startswith(prefix) for _, s in self.received("controller", since))

    def announced(self, text, since=0.0):
        return any(text in s for _, s in self.received("announcements", since))

    def first_stop(self, since=0.0):
        """(t, SafetyStatus) of the first safety stop published since `since`, or None."""
        return next(((t, s) for t, s in self.received("safety", since) if s.stop), None)

    def stops(self, since=0.0):
        """Every safety stop since `since`, as text (describe_stop)."""
        return [describe_stop(s) for _, s in self.received("safety", since) if s.stop]

    def drive_outcome(self, since):
        """"goal_reached" (the controller's), "collided" or "aborted" (the controller's) since
        `since`, in this order, or ""."""
        if self.controller_says("goal_reached", since):
            return "goal_reached"
        if self.collided:
            return "collided"
        return "aborted" if self.controller_says("aborted", since) else ""

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
        done = self.wait(lambda: self.drive_outcome(since), wall_timeout)
        return done and self.drive_outcome(since) == "goal_reached", self.describe(since)

    def describe(self, since=0.0):
        """What happened since `since`, for failure messages."""
        c = [s for _, s in self.received("controller", since)][-6:]
        a = [s for _, s in self.received("announcements", since)][-6:]
        f = [describe_stop(s) if s.stop else "safe" for _, s in self.received("safety", since)][-4:]
        loc = self.localization
        localized = "none" if loc is None else f"{loc.localized} ({loc.sentence}; {loc.detail})"
        pose = "none" if self.truth is None else "(%.2f, %.2f, %.2f)" % self.truth[1:4]
        return (f"controller {c}; announced {a}; safety {f}; localized {localized}; "
                f"true pose {pose}; collided {self.collided}")
