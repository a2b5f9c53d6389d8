#!/usr/bin/env python3
"""The headless demo of `./wheelchair demo` (the workspace must be sourced).

Starts its own ROS master on a free port, brings the chair up with `rosrun` only (no roslaunch),
renders rviz off-screen, and writes into --out:
  overview.png, chair.png   rviz snapshots (whole map; close-up of the chair)
  tf_tree.txt               the tf tree as seen by a listener
  logs/                     one log per process (+ ROS's own logs in logs/ros)
  summary.txt               the paragraph printed at the end
Exit 0 on success; otherwise non-zero and one line naming the step that failed and why.

The demo is a list of steps (STEPS below): the simulator drives the chair along a scripted
torque profile in `flat`; later stages (localizer, planner,
controller, driving to a place) are added as further steps.
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
from nav_msgs.msg import OccupancyGrid, Odometry
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Bool
from tf2_msgs.msg import TFMessage
from wheelchair_msgs.msg import WheelTorques

ROOT = pathlib.Path(__file__).resolve().parent.parent
STARTUP_TIMEOUT = 20.0  # [s] for a node to show its first output


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
    """The closed-loop simulator: the paper's model driven by wheel torques, the SICK laser on
    the world's ground truth, wheel odometry, /clock at real-time speed."""
    place = demo_pose(demo)
    demo.facts["pose"] = place
    world = ROOT / "test" / "worlds" / f"{demo.args.world}.yaml"
    demo.rosrun("simulator", "wheelchair_sim", "simulator", f"_world:={world}", f"_initial_x:={place['x']}",
                f"_initial_y:={place['y']}", f"_initial_yaw:={place['yaw']}", "_speed:=1.0",
                "_publish_laser_tf:=false")
    scans = []
    subscriber = rospy.Subscriber("/scan", LaserScan, scans.append, queue_size=1)
    scan = demo.wait_for("a laser scan on /scan", lambda: scans[-1] if scans else None, ["simulator"])
    subscriber.unregister()
    return (f"the simulator in {world.name} with a {len(scan.ranges)}-beam laser over "
            f"{math.degrees(scan.angle_max - scan.angle_min):.0f} deg and /clock")


def drive_torque_profile(demo):
    """A scripted torque profile, as the controller would send it: accelerate, curve, brake."""
    publisher = rospy.Publisher("/wheel_torques", WheelTorques, queue_size=1)
    truths, collisions = [], []
    subscribers = [rospy.Subscriber("/sim/ground_truth", Odometry, truths.append, queue_size=1),
                   rospy.Subscriber("/sim/collision", Bool, collisions.append, queue_size=1)]
    demo.wait_for("/sim/ground_truth", lambda: truths, ["simulator"])
    start = truths[-1].pose.pose.position
    # s, right, left [N m], brake: free ahead of living_centre up to x = 6 m (checked on the grid)
    profile = [(2.0, 5.0, 5.0, False), (2.0, 5.0, 4.0, False), (2.0, 0.0, 0.0, True)]
    for seconds, right, left, brake in profile:
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            demo.check_alive("simulator", dict(demo.processes)["simulator"])
            message = WheelTorques(right=right, left=left, brake=brake)
            message.header.stamp = rospy.Time.now()
            publisher.publish(message)
            time.sleep(0.02)
    for subscriber in subscribers:
        subscriber.unregister()
    if any(c.data for c in collisions):
        raise DemoError("the chair collided with the world during the torque profile")
    end_pose = truths[-1].pose.pose.position
    moved = math.hypot(end_pose.x - start.x, end_pose.y - start.y)
    if moved < 0.2:
        raise DemoError(f"the chair moved only {moved:.2f} m under the torque profile")
    demo.facts["pose"] = dict(demo.facts["pose"], x=end_pose.x, y=end_pose.y)
    return (f"a 6 s torque profile (accelerate, curve, brake) moved the chair {moved:.2f} m "
            f"without collision")


def start_map_server(demo):
    """The world's map on a latched /map."""
    world = ROOT / "test" / "worlds" / f"{demo.args.world}.yaml"
    if not world.is_file():
        raise DemoError(f"no world file {world}")
    demo.rosrun("map_server", "wheelchair_mapping", "map_server", str(world))
    received = []
    subscriber = rospy.Subscriber("/map", OccupancyGrid, received.append, queue_size=1)
    grid = demo.wait_for("a map on /map", lambda: received[-1] if received else None, ["map_server"])
    subscriber.unregister()
    info = grid.info
    demo.facts["map"] = grid
    width, height = info.width * info.resolution, info.height * info.resolution
    return (f"map server publishing {world.name} on /map ({width:.1f} m x {height:.1f} m, "
            f"{info.resolution * 100:.0f} cm cells)")


def start_description(demo):
    """The chair's URDF on /robot_description and its static tf (base_link -> laser, wheels...)."""
    demo.rosrun("description_publisher", "wheelchair_description", "description_publisher")
    demo.wait_for("/robot_description", lambda: rospy.has_param("/robot_description"), ["description_publisher"])
    demo.wait_for("tf base_link -> laser", lambda: demo.lookup("base_link", "laser"), ["description_publisher"])
    links = rospy.get_param("/robot_description").count("<link ")
    return f"the chair model ({links} links) on /robot_description with its static tf"


def demo_pose(demo):
    """The chair's pose for the demo: a named place of the world (x, y, yaw)."""
    places = ROOT / "test" / "worlds" / f"{demo.args.world}.places.yaml"
    listed = yaml.safe_load(places.read_text())["places"]
    for place in listed:
        if place["name"] == demo.args.place:
            return place
    raise DemoError(f"no place named '{demo.args.place}' in {places} (there are: "
                    f"{', '.join(p['name'] for p in listed)})")


def place_chair(demo):
    """map -> odom -> base_link: stand-ins until the localizer and the base driver (or the
    simulator) publish them; left alone if something already does."""
    place = demo.facts.get("pose") or demo_pose(demo)
    demo.facts["pose"] = place
    time.sleep(1.0)  # let tf arrive from anyone who already publishes it
    started = []
    simulated_odometry = demo.lookup("odom", "base_link") is not None  # starts at the identity
    if demo.lookup("map", "odom") is None:
        at = [place["x"], place["y"], 0, place["yaw"]] if simulated_odometry else [0, 0, 0, 0]
        demo.rosrun("tf_map_odom", "tf2_ros", "static_transform_publisher", *map(str, at), "0", "0",
                    "map", "odom", "__name:=tf_map_odom")
        started.append("map->odom (the start pose)" if simulated_odometry else "map->odom (identity)")
    if demo.lookup("odom", "base_link") is None:
        demo.rosrun("tf_odom_base_link", "tf2_ros", "static_transform_publisher", str(place["x"]),
                    str(place["y"]), "0", str(place["yaw"]), "0", "0", "odom", "base_link",
                    "__name:=tf_odom_base_link")
        started.append("odom->base_link")
    demo.wait_for("tf map -> laser", lambda: demo.lookup("map", "laser"),
                  ["tf_map_odom", "tf_odom_base_link"])
    how = f"static stand-ins for {' and '.join(started)}" if started else "tf from the running nodes"
    return (f"the chair at '{place['name']}' ({place['room']}: x {place['x']:.2f} m, y {place['y']:.2f} m, "
            f"yaw {math.degrees(place['yaw']):.0f} deg) via {how}")


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
    """rviz off-screen: the whole map, and a close-up of the chair."""
    info = demo.facts["map"].info
    width, height = info.width * info.resolution, info.height * info.resolution
    fit = 0.95 * min(RENDER_AREA[0] / width, RENDER_AREA[1] / height)
    overview = (info.origin.position.x + width / 2, info.origin.position.y + height / 2, fit)
    pose = demo.facts["pose"]
    names = [snapshot(demo, "overview", overview), snapshot(demo, "chair", (pose["x"], pose["y"], 200.0))]
    seconds = demo.facts["snapshot_seconds"]
    return f"rviz snapshots {' and '.join(names)} ({sum(seconds) / len(seconds):.0f} s each)"


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
    ("map server", start_map_server),
    ("chair description", start_description),
    ("chair pose", place_chair),
    ("torque profile", drive_torque_profile),
    ("rviz snapshots", take_snapshots),
    ("tf tree", dump_tf_tree),
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
               f"the outputs are in {demo.out} (PNG snapshots, tf_tree.txt, logs/).")
    (demo.out / "summary.txt").write_text(summary + "\n")
    print(summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
