"""The paper's Table 2 protocol against a running chair + simulator (table2_stack.py).

For each start/goal pair: teleport the simulated chair to the start, give the localizer the
start as its initial pose, send the goal, wait for the controller's `goal_reached` (or
`aborted`, a collision, a timeout), recording the reference path (/plan), the localizer's
estimate (/kld_pose) and the truth (/sim/ground_truth). Metrics: table2_metrics.py.
Used by the rostest node (table2_test.py) and by tools/report.py.
"""
import math
import os
import threading
import time

import actionlib
import rospy
import yaml
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped, PoseWithCovarianceStamped
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
from nav_msgs.msg import Odometry, Path
from actionlib_msgs.msg import GoalID, GoalStatusArray
from std_msgs.msg import Bool, String
from wheelchair_msgs.msg import SafetyStatus
from wheelchair_msgs.srv import GoToPlace
from wheelchair_sim.srv import EnableLaser, SetPose

import table2_metrics as metrics

HERE = os.path.dirname(os.path.abspath(__file__))
WORLDS = os.path.join(HERE, "..", "worlds")


def yaw_of(q):
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def load_places(path=os.path.join(HERE, "flat_pairs.yaml")):
    """{name: (x, y, yaw)} of the world's named places (the rider's destinations)."""
    with open(path) as f:
        spec = yaml.safe_load(f)
    with open(os.path.join(WORLDS, spec["places"])) as f:
        return {p["name"]: (p["x"], p["y"], p["yaw"]) for p in yaml.safe_load(f)["places"]}


def load_pairs(path=os.path.join(HERE, "flat_pairs.yaml")):
    """The pairs with every end resolved to (x, y, yaw) from the world's named places."""
    with open(path) as f:
        spec = yaml.safe_load(f)
    with open(os.path.join(WORLDS, spec["places"])) as f:
        places = {p["name"]: (p["x"], p["y"], p["yaw"]) for p in yaml.safe_load(f)["places"]}

    def pose(end):
        if isinstance(end, str):
            return tuple(places[end])
        if isinstance(end, dict):  # a place's position with another heading
            x, y, yaw = places[end["place"]]
            return (x, y, float(end.get("yaw", yaw)))
        return tuple(float(v) for v in end)

    pairs = []
    for i, p in enumerate(spec["pairs"]):
        pairs.append({"index": i + 1, "name": p["name"], "via": p.get("via", ""),
                      "start": pose(p["start"]), "goal": pose(p["goal"])})
    return spec["world"], pairs


def describe(stop):
    """A SafetyStatus in words (None: no stop)."""
    return "no stop" if stop is None else "%s (%s)" % (stop.sentence, stop.detail)


ACTIVE = ("aligning", "tracking", "rotating_to_goal")


def terminal_statuses(status):
    """The controller's (t, text) `goal_reached` / `aborted...` that follow its first active
    state (aligning, tracking, rotating) since the goal: an abort still pending from the previous
    pose (the teleport) is not this run's outcome."""
    first_active = next((i for i, (_, s) in enumerate(status) if s.startswith(ACTIVE)), None)
    if first_active is None:
        return []
    return [(t, s) for t, s in status[first_active:] if s.startswith(("goal_reached", "aborted"))]


class Table2Runner:
    """Talks to the chair. rospy.init_node must have been called (with use_sim_time set)."""

    def __init__(self, status_topic="/controller/status", wall_scale=1.0):
        self.lock = threading.Lock()
        self.wall_scale = wall_scale  # multiplies every wall-clock timeout (loaded machines)
        self.plan = None
        self.plan_count = 0
        self.status = []  # (sim t, text) since the goal
        self.truth, self.estimates = [], []
        self.collided = False
        self.recording = False
        rospy.Subscriber("/plan", Path, self._on_plan, queue_size=2)
        rospy.Subscriber("/kld_pose", PoseWithCovarianceStamped, self._on_estimate, queue_size=50)
        rospy.Subscriber("/sim/ground_truth", Odometry, self._on_truth, queue_size=200)
        rospy.Subscriber(status_topic, String, self._on_status, queue_size=20)
        rospy.Subscriber("/sim/collision", Bool, self._on_collision, queue_size=5)
        self.init_pub = rospy.Publisher("/initialpose", PoseWithCovarianceStamped, queue_size=1,
                                        latch=True)
        # The navigator owns every drive: goals through its move_base action (as rviz and
        # move_base scripts give them); a bring-up without it (chair_table2.yaml): the planner
        # host's /move_base_simple/goal.
        self.move_base = actionlib.SimpleActionClient("/move_base", MoveBaseAction)
        self.plan_pub = rospy.Publisher("/plan", Path, queue_size=1)
        self.goal_pub = rospy.Publisher("/move_base_simple/goal", PoseStamped, queue_size=1)
        self.last_truth = None
        self.check_processes = lambda: None  # raises when the chair or simulator died
        # The supervisor's stop latches until the rider's own command (a destination through
        # the HMI): a run that ended in one would otherwise end every later run too.
        self.safety = None  # the supervisor's last SafetyStatus
        self.navigate_goals = []  # GoalStatus of the navigator's `navigate` action (the HMI's)
        self.releases = []  # (before run index, the stop released)
        self.places = load_places()
        rospy.Subscriber("/safety/status", SafetyStatus, self._on_safety, queue_size=5)
        rospy.Subscriber("/navigate/status", GoalStatusArray, self._on_navigate_status,
                         queue_size=5)
        self.navigate_cancel = rospy.Publisher("/navigate/cancel", GoalID, queue_size=1)

    # -- callbacks --------------------------------------------------------------------------
    def _on_plan(self, msg):
        with self.lock:
            self.plan = [(p.pose.position.x, p.pose.position.y, yaw_of(p.pose.orientation))
                         for p in msg.poses]
            self.plan_count += 1

    def _on_estimate(self, msg):
        p = msg.pose.pose
        sample = (msg.header.stamp.to_sec(), p.position.x, p.position.y, yaw_of(p.orientation))
        with self.lock:
            if self.recording:
                self.estimates.append(sample)

    def _on_truth(self, msg):
        p = msg.pose.pose
        sample = (msg.header.stamp.to_sec(), p.position.x, p.position.y, yaw_of(p.orientation),
                  math.hypot(msg.twist.twist.linear.x, msg.twist.twist.linear.y),
                  msg.twist.twist.angular.z)
        with self.lock:
            self.last_truth = sample
            if self.recording:
                self.truth.append(sample)

    def _on_status(self, msg):
        with self.lock:
            self.status.append((rospy.Time.now().to_sec(), msg.data))

    def _on_safety(self, msg):
        with self.lock:
            self.safety = msg

    def _on_navigate_status(self, msg):
        with self.lock:
            self.navigate_goals = list(msg.status_list)

    def _on_collision(self, msg):
        with self.lock:
            if self.recording and msg.data:
                self.collided = True

    # -- helpers ----------------------------------------------------------------------------
    def wait_for(self, what, predicate, wall_timeout):
        deadline = time.time() + wall_timeout * self.wall_scale
        while not rospy.is_shutdown() and time.time() < deadline:
            self.check_processes()
            with self.lock:
                if predicate():
                    return
            time.sleep(0.02)
        raise RuntimeError("timed out after %.0f s wall waiting for %s" %
                           (wall_timeout * self.wall_scale, what))

    def sim_sleep(self, seconds, wall_timeout=60.0):
        end = rospy.Time.now().to_sec() + seconds
        self.wait_for("%.1f s of simulated time" % seconds,
                      lambda: rospy.Time.now().to_sec() >= end, wall_timeout)

    def wait_ready(self, wall_timeout=120.0):
        """Simulator, localizer, planner and controller up."""
        self.wait_for("/sim/ground_truth", lambda: self.last_truth is not None, wall_timeout)
        rospy.wait_for_service("/sim/teleport", timeout=wall_timeout * self.wall_scale)
        self.wait_for("the controller's status", lambda: bool(self.status), wall_timeout)
        self.teleport = rospy.ServiceProxy("/sim/teleport", SetPose)
        self.navigator = self.move_base.wait_for_server(rospy.Duration(10.0 * self.wall_scale))

    def _stamped_pose(self, pose):
        msg = PoseWithCovarianceStamped()
        msg.header.frame_id = "map"
        msg.header.stamp = rospy.Time.now()
        msg.pose.pose.position.x, msg.pose.pose.position.y = pose[0], pose[1]
        msg.pose.pose.orientation.z = math.sin(pose[2] / 2)
        msg.pose.pose.orientation.w = math.cos(pose[2] / 2)
        return msg

    def put_at_start(self, start):
        """Chair at rest at the start, localizer initialized there."""
        self.wait_for("the chair at rest", lambda: self.last_truth[4] < 0.01 and
                      abs(self.last_truth[5]) < 0.01, 60.0)
        answer = self.teleport(*start)
        if not answer.success:
            raise RuntimeError("teleport to %s refused: %s" % (start, answer.message))
        self.wait_for("the truth at the start", lambda: math.hypot(
            self.last_truth[1] - start[0], self.last_truth[2] - start[1]) < 0.01, 30.0)
        msg = self._stamped_pose(start)
        msg.pose.covariance[0] = msg.pose.covariance[7] = 0.03 ** 2
        msg.pose.covariance[35] = 0.03 ** 2
        self.init_pub.publish(msg)
        self.sim_sleep(1.5)  # scans into the freshly initialized filter

    def latched_stop(self):
        """The supervisor's stop that holds until the rider's command (None when it allows
        motion or waits for its first data)."""
        with self.lock:
            s = self.safety
        if s is None or not s.stop or s.reason == SafetyStatus.NO_DATA:
            return None
        return s

    def latch_stop_by_laser_dropout(self, wall_timeout=30.0):
        """A stop the supervisor latches (the simulator's laser off until it does, then on
        again: the cause is gone, the latch holds). Returns the latched SafetyStatus."""
        laser = rospy.ServiceProxy("/sim/enable_laser", EnableLaser)
        if not laser(False).success:
            raise RuntimeError("the simulator refused to switch the laser off")
        try:
            # (wait_for holds self.lock while it asks: the status read directly)
            self.wait_for("the supervisor's stop for the silent laser", lambda: self.safety
                          is not None and self.safety.stop
                          and self.safety.reason != SafetyStatus.NO_DATA, wall_timeout)
        finally:
            laser(True)
        self.sim_sleep(1.0)  # scans again: only the latch holds the stop
        return self.latched_stop()

    def release_by_rider(self, wall_timeout=30.0):
        """Releases a latched stop the way the rider does: a destination through the HMI (its
        go_to_place service; the HMI is the only release of the supervisor's and the base
        driver's latch), here the named place nearest the chair; that drive is canceled as soon
        as the navigator has it and the chair is let come to rest. Returns the stop's text, or
        None when nothing was latched."""
        stop = self.latched_stop()
        if stop is None:
            return None
        text = "%s (%s)" % (stop.sentence, stop.detail)
        with self.lock:
            _, x, y = self.last_truth[:3]
            seen = {g.goal_id.id for g in self.navigate_goals}
        place = min(self.places, key=lambda n: math.hypot(self.places[n][0] - x,
                                                           self.places[n][1] - y))
        rospy.wait_for_service("/go_to_place", timeout=wall_timeout * self.wall_scale)
        answer = rospy.ServiceProxy("/go_to_place", GoToPlace)(place)
        if not answer.accepted:
            raise RuntimeError("the HMI refused the rider's release (go to %s): %s" %
                               (place, answer.message))
        try:
            self.wait_for("the HMI's drive at the navigator", lambda: any(
                g.goal_id.id not in seen for g in self.navigate_goals), wall_timeout)
        finally:
            self.navigate_cancel.publish(GoalID())  # every navigate goal: the HMI's drive ends
        # (wait_for holds self.lock while it asks) a stop whose cause holds on latches again:
        # this run then fails on its own
        try:
            self.wait_for("the supervisor's release", lambda: not self.safety.stop
                          or self.safety.reason == SafetyStatus.NO_DATA, 10.0)
        except RuntimeError:
            pass
        self.sim_sleep(1.0)
        return text

    def run_pair(self, pair, sim_timeout=None):
        """Drives one pair; returns the per-run record (dict, JSON-ready). A stop the
        supervisor latched in an earlier run is first released by the rider (release_by_rider):
        it failed that run; this run starts as a rider's next drive does."""
        record = {"index": pair["index"], "name": pair["name"], "via": pair["via"],
                  "start": list(pair["start"]), "goal": list(pair["goal"])}
        wall0 = time.time()
        self.put_at_start(pair["start"])  # localized at the start: a lost pose is no cause
        released = self.release_by_rider()
        if released:
            record["released_before_run"] = released
            self.releases.append((pair["index"], released))
        with self.lock:
            self.truth, self.estimates, self.status = [], [], []
            self.collided = False
            plans_before = self.plan_count
            self.recording = True
        goal = self._stamped_pose(pair["goal"])
        goal_msg = PoseStamped(header=goal.header, pose=goal.pose.pose)
        t_goal = rospy.Time.now().to_sec()
        if self.navigator:
            self.move_base.send_goal(MoveBaseGoal(target_pose=goal_msg))
        else:
            self.goal_pub.publish(goal_msg)
        try:
            self.wait_for("a plan", lambda: self.plan_count > plans_before, 60.0)
            with self.lock:
                plan = list(self.plan)
            if not plan:
                raise RuntimeError("the planner sent an empty plan (no path)")
            length = sum(math.hypot(plan[i + 1][0] - plan[i][0], plan[i + 1][1] - plan[i][1])
                         for i in range(len(plan) - 1))
            limit = sim_timeout or 40.0 + 4.0 * length
            t_end = rospy.Time.now().to_sec() + limit

            def finished():
                return (bool(terminal_statuses(self.status)) and self.navigator_done()
                        or self.collided or rospy.Time.now().to_sec() > t_end)

            # wall: the simulated limit at a fifth of real time, at least
            self.wait_for("goal reached", finished, 5.0 * limit + 60.0)
            self.sim_sleep(1.0)  # braked: the final pose is the one the rider stays at
        finally:
            with self.lock:
                self.recording = False
        with self.lock:
            status, truth, estimates = list(self.status), list(self.truth), list(self.estimates)
            collided = self.collided
        navigator = self.navigator_outcome()
        if not terminal_statuses(status) or terminal_statuses(status)[0][1] != "goal_reached":
            self.stop_chair()
        record.update(self.evaluate(pair, plan, status, truth, estimates, t_goal, collided))
        if navigator:
            record["navigator"] = navigator
        record.update({"collision": collided, "path_length_m": length,
                       "wall_time_s": time.time() - wall0})
        return record

    def navigator_done(self):
        """The navigator's result has come (always true without a navigator)."""
        return not self.navigator or self.move_base.get_state() not in (
            GoalStatus.PENDING, GoalStatus.ACTIVE, GoalStatus.PREEMPTING, GoalStatus.RECALLING)

    def navigator_outcome(self):
        """The move_base action's end: {"status": "SUCCEEDED"..., "text": the rider's sentence}
        (None without a navigator)."""
        if not self.navigator:
            return None
        state = self.move_base.get_state()
        names = {v: k for k, v in vars(GoalStatus).items() if k.isupper() and isinstance(v, int)}
        return {"status": names.get(state, str(state)),
                "text": self.move_base.get_goal_status_text()}

    def stop_chair(self):
        """After a failed run: the navigator's drive canceled (a controlled stop), or without a
        navigator an empty plan, which the controller answers with a controlled stop
        (nav_msgs/Path convention of the planner host), so nothing moves at the next
        teleport."""
        if self.navigator:
            self.move_base.cancel_all_goals()
            self.sim_sleep(2.0)
            return
        empty = Path()
        empty.header.frame_id = "map"
        empty.header.stamp = rospy.Time.now()
        self.plan_pub.publish(empty)
        self.sim_sleep(2.0)

    @staticmethod
    def evaluate(pair, plan, status, truth, estimates, t_goal, collided=False):
        terminal = terminal_statuses(status)
        ends = [t for t, _ in terminal]
        outcome = [s for _, s in terminal]
        t_end = ends[0] if ends else (truth[-1][0] if truth else t_goal)
        tracking = [t for t, s in status if s.startswith("tracking")]
        t_start = tracking[0] if tracking else t_goal
        path_xy = [(p[0], p[1]) for p in plan]
        truth_w = [(s[1], s[2]) for s in metrics.in_window(truth, t_start, t_end)]
        est_w = [(s[1], s[2]) for s in metrics.in_window(estimates, t_start, t_end)]
        final = truth[-1][1:4] if truth else (float("nan"),) * 3
        pos_err, yaw_err = metrics.goal_error(final, pair["goal"])
        return {
            "outcome": outcome[0] if outcome else ("collision" if collided else "timeout"),
            "status_sequence": [s for _, s in status],
            "sim_duration_s": t_end - t_goal,
            "mse_rc_cm2": metrics.mse_cm2(est_w, path_xy) if est_w else float("nan"),
            "mse_re_cm2": metrics.mse_cm2(truth_w, path_xy) if truth_w else float("nan"),
            "samples_estimate": len(est_w), "samples_truth": len(truth_w),
            "final_pose": list(final), "goal_position_error_m": pos_err,
            "goal_heading_error_deg": math.degrees(yaw_err),
            "plan": [list(p) for p in plan],
            "truth": [list(s[:4]) for s in truth],
            "estimate": [list(s) for s in estimates],
            "window": [t_start, t_end],
        }


def summarize(records):
    """Mean and std of MSErc / MSEre over the runs (the paper's bottom rows)."""
    out = {}
    for key in ("mse_rc_cm2", "mse_re_cm2"):
        mean, std = metrics.mean_std([r[key] for r in records])
        out[key] = {"mean": mean, "std": std}
    return out
