#!/usr/bin/env python3
"""The headless demo of `./wheelchair demo` (the workspace must be sourced).

Starts its own ROS master on a free port and, with `rosrun` only (no roslaunch), the simulator
(on the CAN motor bus) and the whole chair in one process (`rosrun wheelchair_bringup
wheelchair`); initializes the localizer (rviz's 2D Pose Estimate, or --global), chooses the
destination like a one-switch rider (scripted /switch presses on the HMI's group scanning),
drives there, renders rviz off-screen and writes into --out:
  overview.png, chair.png   rviz snapshots: map, particles, plan, true trajectory; close-up
  report.md                 what happened: presses, scan steps, time, final error, figures
  tf_tree.txt               the tf tree as seen by a listener
  logs/                     one log per process (+ ROS's own logs in logs/ros)
  summary.txt               the paragraph printed at the end
Exit 0 when the chair reached its goal; otherwise non-zero and one line naming the step that
failed and why. The demo is a list of steps (STEPS below).
"""
import argparse
import math
import os
import pathlib
import shutil
import signal
import socket
import subprocess
import sys
import time

import rosgraph
import rospy
import tf2_ros
import yaml
from geometry_msgs.msg import PoseWithCovarianceStamped
from nav_msgs.msg import OccupancyGrid, Odometry
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Bool, Empty, String
from tf2_msgs.msg import TFMessage

ROOT = pathlib.Path(__file__).resolve().parent.parent
STARTUP_TIMEOUT = 40.0  # [s] for a node to show its first output (loaded machine)
CAN_PORTS = (47190, 47191)  # UDP ports of the demo's CAN bus (driver, motors): not the tests'
DRIVE_TIMEOUT = 90.0  # [wall s] for the drive to the destination


class DemoError(Exception):
    """A step failed; the message says why, for the user."""


class Demo:
    """The processes the demo started and what the steps found out."""
    def __init__(self, args):
        self.args = args
        self.out = pathlib.Path(args.out).resolve()
        self.logs = self.out / "logs"
        self.processes = []  # (name, Popen), in start order
        self.facts = {}  # step results used by later steps and by the summary
        self.node = None  # rospy is initialized once the master is up
        self.tf_buffer = None

    # ---- processes -------------------------------------------------------------------------
    def start(self, name, command):
        """Starts `command` in its own process group, output to logs/<name>.log."""
        log = open(self.logs / f"{name}.log", "wb")
        process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                   start_new_session=True, cwd=self.out)
        log.close()
        self.processes.append((name, process))
        return process

    def check_alive(self, name, process):
        if process.poll() is not None:
            raise DemoError(f"{name} exited with code {process.returncode}: "
                            f"{self.log_tail(name) or '(no output)'} (log: logs/{name}.log)")

    def log_tail(self, name, lines=3):
        text = (self.logs / f"{name}.log").read_text(errors="replace").strip().splitlines()
        return " | ".join(line.strip() for line in text[-lines:])

    def rosrun(self, name, package, executable, *arguments):
        """`rosrun package executable arguments`, after checking that it exists."""
        found = subprocess.run(["rosrun", "--prefix", "echo", package, executable], capture_output=True,
                               text=True)
        if found.returncode != 0:
            reason = (found.stdout + found.stderr).strip().splitlines()
            raise DemoError(f"`rosrun {package} {executable}` is not available "
                            f"({reason[-1] if reason else 'not built'}); build the workspace "
                            f"(./wheelchair build)")
        return self.start(name, ["rosrun", package, executable, *arguments])

    def stop_all(self):
        """SIGTERM to every process group we started, newest first; SIGKILL after 10 s."""
        for name, process in reversed(self.processes):
            if process.poll() is None:
                try:
                    os.killpg(process.pid, signal.SIGTERM)
                except ProcessLookupError:
                    pass
        deadline = time.monotonic() + 10.0
        for name, process in reversed(self.processes):
            try:
                process.wait(max(0.1, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                print(f"[demo] {name} ignored SIGTERM; killing it", file=sys.stderr)
                try:
                    os.killpg(process.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                process.wait()

    # ---- waiting ---------------------------------------------------------------------------
    def wait_for(self, what, condition, process_names=(), timeout=STARTUP_TIMEOUT):
        """Polls `condition()` until true; fails early if one of the named processes died."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            for name, process in self.processes:
                if name in process_names:
                    self.check_alive(name, process)
            result = condition()
            if result:
                return result
            time.sleep(0.1)
        raise DemoError(f"timed out after {timeout:.0f} s waiting for {what}")

    def lookup(self, parent, child):

        try:
            return self.tf_buffer.lookup_transform(parent, child, rospy.Time(0))
        except Exception:  # tf2 raises several types; all mean "not yet"
            return None


# ---- steps ------------------------------------------------------------------------------------
def free_port():
    with socket.socket() as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


def start_master(demo):
    """rosmaster on a free port + rosout; this process becomes a node with a tf listener."""
    port = free_port()
    uri = f"http://localhost:{port}"
    os.environ["ROS_MASTER_URI"] = uri
    demo.start("rosmaster", ["rosmaster", "--core", "-p", str(port)])
    demo.wait_for(f"the ROS master at {uri}", rosgraph.is_master_online, ["rosmaster"])
    demo.rosrun("rosout", "rosout", "rosout", "__name:=rosout")
    rospy.set_param("/use_sim_time", True)  # the simulator owns time (/clock)
    rospy.init_node("wheelchair_demo", disable_signals=True)
    demo.tf_buffer = tf2_ros.Buffer()
    demo.node = tf2_ros.TransformListener(demo.tf_buffer)
    return f"a ROS master at {uri} with rosout"


def start_simulator(demo):
    """The closed-loop simulator behind the CAN motor bus: the paper's model, the SICK laser on
    the world's ground truth, /clock at real-time speed."""
    place = demo_pose(demo, demo.args.place)
    demo.facts["start"] = place
    world = ROOT / "test" / "worlds" / f"{demo.args.world}.yaml"
    demo.rosrun("simulator", "wheelchair_sim", "simulator", f"_world:={world}", f"_initial_x:={place['x']}",
                f"_initial_y:={place['y']}", f"_initial_yaw:={place['yaw']}", "_speed:=0.5",
                "_motor_bus:=udp", f"_udp_local_port:={CAN_PORTS[1]}", f"_udp_remote_port:={CAN_PORTS[0]}")
    scans = []
    subscriber = rospy.Subscriber("/scan", LaserScan, scans.append, queue_size=1)
    scan = demo.wait_for("a laser scan on /scan", lambda: scans[-1] if scans else None, ["simulator"])
    subscriber.unregister()
    return (f"the simulator in {world.name} with a {len(scan.ranges)}-beam laser over "
            f"{math.degrees(scan.angle_max - scan.angle_min):.0f} deg, motors on CAN-over-UDP")


def start_chair(demo):
    """The whole chair in one process: map server, description, localizer, planner, controller,
    base driver (CAN to the simulator), safety supervisor, HMI (chair_sim.yaml)."""
    world = ROOT / "test" / "worlds" / f"{demo.args.world}"
    demo.rosrun("wheelchair", "wheelchair_bringup", "wheelchair",
                f"_base_driver/udp_local_port:={CAN_PORTS[0]}", f"_base_driver/udp_remote_port:={CAN_PORTS[1]}",
                f"_map_server/map_file:={world}.yaml", f"_hmi/places_file:={world}.places.yaml",
                f"_hmi/scan_interval:={demo.args.scan_interval}")
    received = []
    subscriber = rospy.Subscriber("/map", OccupancyGrid, received.append, queue_size=1)
    grid = demo.wait_for("a map on /map", lambda: received[-1] if received else None, ["wheelchair"])
    subscriber.unregister()
    demo.facts["map"] = grid
    demo.wait_for("tf odom -> base_link from the base driver", lambda: demo.lookup("odom", "base_link"),
                  ["wheelchair"])
    demo.wait_for("tf base_link -> laser", lambda: demo.lookup("base_link", "laser"), ["wheelchair"])
    for service in ("/go_to_place", "/planner/make_plan", "/global_localization"):
        demo.wait_for(f"service {service}", lambda: service_up(service), ["wheelchair"])
    demo.watch = Watch()
    info = grid.info
    return (f"the chair (one process: map server, description, KLD localizer, harmonic planner, "
            f"controller, base driver, supervisor, HMI) with a {info.width * info.resolution:.1f} m x "
            f"{info.height * info.resolution:.1f} m map")


def service_up(name):
    try:
        rospy.wait_for_service(name, timeout=0.1)
        return True
    except rospy.ROSException:
        return False


class Watch:
    """What the demo records while it runs: truth, announcements, controller and safety."""
    def __init__(self):
        self.truth = []  # (t, x, y, yaw)
        self.announcements = []  # (t, text)
        self.controller = []
        self.safety = []
        self.localized = ""
        self.collided = False

        def append(field):
            return lambda msg: getattr(self, field).append((rospy.get_time(), msg.data))

        def on_truth(msg):
            p = msg.pose.pose
            self.truth.append((msg.header.stamp.to_sec(), p.position.x, p.position.y,
                               2 * math.atan2(p.orientation.z, p.orientation.w)))

        self.subscribers = [
            rospy.Subscriber("/sim/ground_truth", Odometry, on_truth, queue_size=50),
            rospy.Subscriber("/hmi/announce", String, append("announcements"), queue_size=50),
            rospy.Subscriber("/controller/status", String, append("controller"), queue_size=20),
            rospy.Subscriber("/safety/status", String, append("safety"), queue_size=20),
            rospy.Subscriber("/kld/localized", String, lambda m: setattr(self, "localized", m.data)),
            rospy.Subscriber("/sim/collision", Bool,
                             lambda m: setattr(self, "collided", self.collided or m.data)),
        ]

    def said(self, field, prefix, since):
        return any(t >= since and text.startswith(prefix) for t, text in getattr(self, field))


def initialize(demo):
    """Localization: rviz's 2D Pose Estimate at the start (default) or global localization."""
    place, watch = demo.facts["start"], demo.watch
    if demo.args.global_localization:
        # std_srvs has no Python bindings on Debian unless python3-std-srvs is installed
        subprocess.run(["rosservice", "call", "/global_localization"], check=True, capture_output=True,
                       timeout=30)
        how = "global localization (particles over the whole map)"
    else:
        msg = PoseWithCovarianceStamped()
        msg.header.frame_id = "map"
        msg.header.stamp = rospy.Time.now()
        msg.pose.pose.position.x, msg.pose.pose.position.y = place["x"], place["y"]
        msg.pose.pose.orientation.z = math.sin(place["yaw"] / 2)
        msg.pose.pose.orientation.w = math.cos(place["yaw"] / 2)
        msg.pose.covariance[0] = msg.pose.covariance[7] = 0.1 ** 2
        msg.pose.covariance[35] = 0.1 ** 2
        publisher = rospy.Publisher("/initialpose", PoseWithCovarianceStamped, queue_size=1, latch=True)
        demo.facts["initialpose_publisher"] = publisher  # keep it (latched) alive
        publisher.publish(msg)
        how = f"an initial pose at '{place['name']}' (10 cm, 6 deg std)"
    demo.wait_for("the localizer to report 'localized'", lambda: watch.localized == "localized",
                  ["wheelchair"], timeout=60.0)
    time.sleep(1.5)  # two map -> odom stamps before a goal: the planner looks up the latest pose
    demo.facts["localized_how"] = how
    return f"localized from {how}"


def choose_destination(demo):
    """The one-switch rider: presses /switch when the destination's room, then the place is
    announced, then confirms; counts presses and scan steps."""
    goal, watch = demo_pose(demo, demo.args.goal), demo.watch
    demo.facts["goal"] = goal
    switch = rospy.Publisher("/switch", Empty, queue_size=5)
    demo.wait_for("the HMI to listen to /switch", lambda: switch.get_num_connections() > 0, ["wheelchair"])
    presses, steps, seen = 0, 0, len(watch.announcements)
    deadline = time.monotonic() + 60.0
    while not watch.said("announcements", "Going to " + goal["name"], 0.0):
        demo.check_alive("wheelchair", dict(demo.processes)["wheelchair"])
        if time.monotonic() > deadline:
            raise DemoError(f"the scanner never offered {goal['name']} ({presses} presses)")
        fresh = watch.announcements[seen:]
        seen += len(fresh)
        for _, text in fresh:
            highlight = text.endswith("?") and not text.startswith("Go to")
            steps += highlight
            if (text.startswith("Go to " + goal["name"]) or text.endswith(goal["room"] + "?")
                    or text.endswith(goal["name"] + "?")):
                switch.publish(Empty())
                presses += 1
        time.sleep(0.02)
    demo.facts["presses"], demo.facts["steps"] = presses, steps
    demo.facts["go_time"] = rospy.get_time()
    return (f"'{goal['name']}' ({goal['room']}) chosen with {presses} switch presses after "
            f"{steps} scan steps")


def drive(demo):
    """The chair plans and drives; ends at the controller's goal_reached (or a stop)."""
    watch, goal, since = demo.watch, demo.facts["goal"], demo.facts["go_time"]
    ended = demo.wait_for(f"the drive to {goal['name']}", lambda: (
        watch.said("controller", "goal_reached", since) or watch.said("controller", "aborted", since)
        or watch.collided), ["wheelchair", "simulator"], timeout=DRIVE_TIMEOUT)
    time.sleep(1.0)  # come to rest
    t, x, y, yaw = watch.truth[-1]
    error = math.hypot(x - goal["x"], y - goal["y"])
    heading = abs(math.degrees(math.remainder(yaw - goal["yaw"], 2 * math.pi)))
    # Judged by the simulator's truth (the controller may abort a few mm off its own tolerance).
    reached = error <= 0.15 and heading <= 10.0 and not watch.collided
    points = [(px, py) for tt, px, py, _ in watch.truth if tt >= since]
    length = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(points, points[1:]))
    demo.facts.update(reached=reached, error=error, heading=heading, length=length,
                      drive_time=t - since, end=(x, y, yaw), ended=ended)
    stops = [text for tt, text in watch.safety if tt >= since and text != "safe"]
    demo.facts["stops"] = stops
    verdict = "reached" if reached else "NOT reached"
    text = (f"{goal['name']} {verdict}: {length:.2f} m driven in {t - since:.1f} s (simulated), final "
            f"error {error * 100:.1f} cm and {heading:.1f} deg")
    if not reached:
        last = [s for tt, s in watch.controller if tt >= since][-1:]
        raise DemoError(f"{text}; controller {last}, safety stops {stops[:2]}, collided {watch.collided}")
    return text


def demo_pose(demo, name):
    """A named place of the world: {name, room, x, y, yaw}."""
    places = ROOT / "test" / "worlds" / f"{demo.args.world}.places.yaml"
    listed = yaml.safe_load(places.read_text())["places"]
    for place in listed:
        if place["name"] == name:
            return place
    raise DemoError(f"no place named '{name}' in {places} (there are: "
                    f"{', '.join(p['name'] for p in listed)})")


def snapshot(demo, name, view):
    started = time.monotonic()
    command = ["rosrun", "wheelchair_bringup", "snapshot", "--out", str(demo.out / f"{name}.png"),
               "--seconds", str(demo.args.snapshot_seconds), "--view", ",".join(f"{v:.3f}" for v in view),
               "--log", str(demo.logs / f"rviz_{name}.log")]
    process = demo.start(f"snapshot_{name}", command)  # stopped with the rest if we are interrupted
    try:
        code = process.wait(demo.args.snapshot_seconds + 120)
    except subprocess.TimeoutExpired:
        raise DemoError(f"snapshot {name}.png did not finish (log: logs/snapshot_{name}.log)") from None
    if code != 0:
        raise DemoError(f"snapshot {name}.png failed: {demo.log_tail(f'snapshot_{name}', 1)}")
    demo.facts.setdefault("snapshot_seconds", []).append(time.monotonic() - started)
    return f"{name}.png"


RENDER_AREA = (900, 700)  # [px] rviz's render area in a 1280 x 800 screen with the Displays panel


def take_snapshots(demo):
    """rviz off-screen: the whole map (particles, plan, true trajectory), and the chair at its goal."""
    info = demo.facts["map"].info
    width, height = info.width * info.resolution, info.height * info.resolution
    fit = 0.95 * min(RENDER_AREA[0] / width, RENDER_AREA[1] / height)
    overview = (info.origin.position.x + width / 2, info.origin.position.y + height / 2, fit)
    x, y, _ = demo.facts["end"]
    names = [snapshot(demo, "overview", overview), snapshot(demo, "chair", (x, y, 150.0))]
    seconds = demo.facts["snapshot_seconds"]
    return f"rviz snapshots {' and '.join(names)} ({sum(seconds) / len(seconds):.0f} s each)"


def write_report(demo):
    """report.md: the run in a few lines and the snapshots."""
    f, start, goal = demo.facts, demo.facts["start"], demo.facts["goal"]
    lines = [
        f"# Demo: {start['name']} -> {goal['name']} in `{demo.args.world}`",
        "",
        f"- Localization: {f['localized_how']}",
        f"- Destination chosen with one switch (group scanning, {demo.args.scan_interval:.1f} s per "
        f"highlight): {f['presses']} presses, {f['steps']} scan steps",
        f"- Drive: {f['length']:.2f} m in {f['drive_time']:.1f} s simulated time; "
        f"{'reached' if f['reached'] else 'NOT reached'}",
        f"- Final error (simulator truth vs the place): {f['error'] * 100:.1f} cm, {f['heading']:.1f} deg",
        f"- Safety stops during the drive: {', '.join(f['stops']) if f['stops'] else 'none'}",
        f"- Collision: {'yes' if demo.watch.collided else 'no'}",
        "",
        "![overview](overview.png)",
        "",
        "![chair at the goal](chair.png)",
        "",
    ]
    (demo.out / "report.md").write_text("\n".join(lines))
    return "report.md"


def frames_with_two_parents(listen=2.0):
    """{child: {(parent, publisher)}} for every frame that more than one parent claims on /tf or
    /tf_static (a tf2 listener silently keeps whichever came last)."""
    edges = {}

    def record(message):
        who = message._connection_header.get("callerid", "?")
        for t in message.transforms:
            edges.setdefault(t.child_frame_id.lstrip("/"), set()).add((t.header.frame_id.lstrip("/"), who))

    subscribers = [rospy.Subscriber(topic, TFMessage, record, queue_size=100) for topic in ("/tf", "/tf_static")]
    time.sleep(listen)  # static transforms are latched: they all arrive at once
    for subscriber in subscribers:
        subscriber.unregister()
    return {child: parents for child, parents in edges.items() if len({p for p, _ in parents}) > 1}


def dump_tf_tree(demo):
    """tf_tree.txt: every frame under its parent, with the transform and who broadcasts it."""
    frames = yaml.safe_load(demo.tf_buffer.all_frames_as_yaml()) or {}
    children = {}
    for frame, data in frames.items():
        children.setdefault(data["parent"], []).append(frame)
    roots = sorted(set(children) - set(frames))
    lines = [f"# tf tree seen by a listener at {time.strftime('%Y-%m-%d %H:%M:%S')}",
             "# parent -> child: translation (x, y, z) [m], yaw [deg], broadcaster"]

    def walk(frame, depth):
        for child in sorted(children.get(frame, [])):
            t = demo.tf_buffer.lookup_transform(frame, child, rospy.Time(0)).transform
            q = t.rotation
            yaw = math.degrees(math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z)))
            lines.append(f"{'  ' * depth}{frame} -> {child}: ({t.translation.x:.3f}, {t.translation.y:.3f}, "
                         f"{t.translation.z:.3f}), {yaw:.1f} deg, {frames[child].get('broadcaster', '?')}")
            walk(child, depth + 1)

    for root in roots:
        lines.append(root)
        walk(root, 1)
    conflicts = frames_with_two_parents()
    for child, parents in sorted(conflicts.items()):
        lines.append(f"# ERROR: {child} has {len(parents)} parents: "
                     + ", ".join(f"{parent} (from {who})" for parent, who in sorted(parents)))
    (demo.out / "tf_tree.txt").write_text("\n".join(lines) + "\n")
    if conflicts:
        child, parents = sorted(conflicts.items())[0]
        raise DemoError(f"tf frame {child} has {len(parents)} parents ("
                        + ", ".join(f"{parent} from {who}" for parent, who in sorted(parents))
                        + "): a frame may have one parent only, otherwise lookups through it fail at "
                        "random; see tf_tree.txt")
    for parent, child in (("map", "odom"), ("odom", "base_link"), ("base_link", "laser")):
        if demo.lookup(parent, child) is None:
            raise DemoError(f"the tf tree lacks {parent} -> {child} (REP-105); see tf_tree.txt")
    return f"a tf tree of {len(frames)} frames under {', '.join(roots)} (tf_tree.txt)"


STEPS = [
    ("ROS master", start_master),
    ("simulator", start_simulator),
    ("chair", start_chair),
    ("localization", initialize),
    ("destination", choose_destination),
    ("drive", drive),
    ("rviz snapshots", take_snapshots),
    ("tf tree", dump_tf_tree),
    ("report", write_report),
]


def run(demo):
    """Runs the steps in order; returns the list of (step, result) or raises DemoError."""
    done = []
    for name, step in STEPS:
        started = time.monotonic()
        print(f"[demo] {name} ...", flush=True)
        try:
            result = step(demo)
        except DemoError as error:
            raise DemoError(f"step '{name}' failed: {error}") from None
        print(f"[demo] {name}: {result} [{time.monotonic() - started:.1f} s]", flush=True)
        done.append((name, result))
    return done


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="output directory (emptied first)")
    parser.add_argument("--world", default="flat", help="world under test/worlds (default: flat)")
    parser.add_argument("--place", default="living_centre",
                        help="named place where the chair starts (default: living_centre)")
    # kitchen_door again: the planner checks the footprint's sweep (rear overhang 0.80 m behind
    # the axle) and repairs the route with its footprint search; the half turn no longer hits.
    parser.add_argument("--goal", default="kitchen_door",
                        help="named place the rider chooses (default: kitchen_door)")
    parser.add_argument("--global", dest="global_localization", action="store_true",
                        help="start with global localization instead of an initial pose")
    parser.add_argument("--scan-interval", type=float, default=1.0,
                        help="one-switch scanning: seconds per highlight (default 1)")
    parser.add_argument("--snapshot-seconds", type=float, default=4.0, help="time rviz gets to fill its displays")
    args = parser.parse_args()
    if subprocess.run(["rospack", "find", "wheelchair_bringup"], capture_output=True).returncode != 0:
        print("[demo] error: the workspace is not built and sourced (use ./wheelchair demo)", file=sys.stderr)
        return 2
    demo = Demo(args)
    if demo.out.exists():
        shutil.rmtree(demo.out)
    demo.logs.mkdir(parents=True)
    os.environ["ROS_LOG_DIR"] = str(demo.logs / "ros")
    os.environ.setdefault("ROS_HOME", str(demo.out / "ros_home"))

    def on_signal(signum, _frame):
        raise DemoError(f"interrupted by signal {signum}")

    signal.signal(signal.SIGTERM, on_signal)
    signal.signal(signal.SIGINT, on_signal)
    started = time.monotonic()
    try:
        done = run(demo)
    except DemoError as error:
        print(f"[demo] error: {error}", file=sys.stderr)
        return 1
    finally:
        if demo.node is not None:
            rospy.signal_shutdown("demo finished")
        demo.stop_all()
    summary = (f"Demo ({time.monotonic() - started:.0f} s, world '{args.world}'): started "
               + "; ".join(result for _, result in done)
               + f". Every node ran under rosrun (no roslaunch) and all processes were stopped again; "
               f"the outputs are in {demo.out} (report.md, PNG snapshots, tf_tree.txt, logs/).")
    (demo.out / "summary.txt").write_text(summary + "\n")
    print(summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
