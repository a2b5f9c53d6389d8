#!/usr/bin/env python3
"""The headless demo of `./wheelchair demo` (the workspace must be sourced).

Starts its own ROS master on a free port and, with `rosrun` only (no roslaunch), the simulator
(on the CAN motor bus) and the whole chair in one process (`rosrun wheelchair_bringup
wheelchair`); initializes the localizer (rviz's 2D Pose Estimate, or --global), chooses the
destination like a one-switch rider (scripted /switch presses on the HMI's group scanning),
drives there, renders rviz off-screen and writes into --out:
  overview.png, chair.png   rviz snapshots: map, particles, plan, true trajectory; close-up
  display_*.png             the rider's display (1024x768) scanning, driving, arrived, stopped
                            by the rider (tools/demo_display.py)
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
import subprocess
import sys
import time

import rospy
import tf2_ros
import yaml
from nav_msgs.msg import OccupancyGrid
from sensor_msgs.msg import LaserScan
from tf2_msgs.msg import TFMessage

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "test" / "src"))  # wheelchair_test.harness, by path
from wheelchair_test.harness import (  # noqa: E402
    ProcessError, Processes, Rider, RiderError, places, stack, wait_for_service)
from wheelchair_test.harness import start_master as start_master_of  # noqa: E402

import demo_display  # noqa: E402  (beside this file)

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
        self.processes = Processes(self.logs, cwd=self.out)
        self.facts = {}  # step results used by later steps and by the summary
        self.node = None  # rospy is initialized once the master is up
        self.tf_buffer = None
        self.rider = None  # the one-switch rider, once the chair is up
        self.display = None  # the rider's display (demo_display.py)

    def wait_for(self, what, condition, process_names=(), timeout=STARTUP_TIMEOUT):
        """Polls `condition()` until true; fails early if one of the named processes died."""
        return self.processes.wait_for(what, condition, timeout, watch=process_names)

    def lookup(self, parent, child):
        try:
            return self.tf_buffer.lookup_transform(parent, child, rospy.Time(0))
        except Exception:  # tf2 raises several types; all mean "not yet"
            return None


# ---- steps ------------------------------------------------------------------------------------
def start_master(demo):
    """rosmaster on a free port + rosout; this process becomes a node with a tf listener."""
    uri = start_master_of(demo.processes, rosout=True, use_sim_time=True, export=True)
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
    stack.simulator(demo.processes, world, CAN_PORTS, (place["x"], place["y"], place["yaw"]),
                    speed=0.5)
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
    stack.chair(demo.processes, ports=CAN_PORTS, overrides={
        "map_server/map_file": f"{world}.yaml", "hmi/places_file": f"{world}.places.yaml",
        "hmi/scan_interval": demo.args.scan_interval,
        "hmi/switch_publisher": "/wheelchair_demo"})  # the demo's rider presses the switch
    received = []
    subscriber = rospy.Subscriber("/map", OccupancyGrid, received.append, queue_size=1)
    grid = demo.wait_for("a map on /map", lambda: received[-1] if received else None, ["wheelchair"])
    subscriber.unregister()
    demo.facts["map"] = grid
    demo.wait_for("tf odom -> base_link from the base driver", lambda: demo.lookup("odom", "base_link"),
                  ["wheelchair"])
    demo.wait_for("tf base_link -> laser", lambda: demo.lookup("base_link", "laser"), ["wheelchair"])
    for service in ("/go_to_place", "/planner/make_plan", "/global_localization"):
        wait_for_service(service, STARTUP_TIMEOUT, demo.processes, ["wheelchair"])
    demo.rider = Rider()
    info = grid.info
    return (f"the chair (one process: map server, description, KLD localizer, harmonic planner, "
            f"controller, base driver, supervisor, HMI) with a {info.width * info.resolution:.1f} m x "
            f"{info.height * info.resolution:.1f} m map")


def initialize(demo):
    """Localization: rviz's 2D Pose Estimate at the start (default) or global localization."""
    place, rider = demo.facts["start"], demo.rider
    if demo.args.global_localization:
        localized = rider.global_localization(wall_timeout=60.0)
        how = "global localization (particles over the whole map)"
    else:
        localized = rider.initialize(place["x"], place["y"], place["yaw"], wall_timeout=60.0,
                                     std=0.1)
        how = f"an initial pose at '{place['name']}' (10 cm, 6 deg std)"
    if not localized:
        demo.processes.check("wheelchair")
        raise DemoError("timed out after 60 s waiting for the localizer to report 'localized'")
    demo.facts["localized_how"] = how
    return f"localized from {how}"


def choose_destination(demo):
    """The one-switch rider: presses /switch when the destination's room, then the place is
    announced, then confirms; counts presses and scan steps."""
    goal = demo_pose(demo, demo.args.goal)
    demo.facts["goal"] = goal
    try:
        presses, steps = demo.rider.choose_by_switch(
            goal["name"], goal["room"], sim_timeout=30.0,
            check=lambda: demo.processes.check("wheelchair"))
    except RiderError as error:
        raise DemoError(str(error)) from None
    demo.facts["presses"], demo.facts["steps"] = presses, steps
    demo.facts["go_time"] = rospy.get_time()
    return (f"'{goal['name']}' ({goal['room']}) chosen with {presses} switch presses after "
            f"{steps} scan steps")


def drive(demo):
    """The chair plans and drives; ends at the controller's goal_reached (or a stop)."""
    rider, goal, since = demo.rider, demo.facts["goal"], demo.facts["go_time"]
    ended = demo.wait_for(f"the drive to {goal['name']}", lambda: rider.drive_outcome(since),
                          ["wheelchair", "simulator"], timeout=DRIVE_TIMEOUT)
    time.sleep(1.0)  # come to rest
    t, x, y, yaw = rider.truth[:4]
    error = math.hypot(x - goal["x"], y - goal["y"])
    heading = abs(math.degrees(math.remainder(yaw - goal["yaw"], 2 * math.pi)))
    # Judged by the simulator's truth (the controller may abort a few mm off its own tolerance).
    reached = error <= 0.15 and heading <= 10.0 and not rider.collided
    length = rider.travelled(since)
    demo.facts.update(reached=reached, error=error, heading=heading, length=length,
                      drive_time=t - since, end=(x, y, yaw), ended=ended)
    stops = rider.stops(since)
    demo.facts["stops"] = stops
    verdict = "reached" if reached else "NOT reached"
    text = (f"{goal['name']} {verdict}: {length:.2f} m driven in {t - since:.1f} s (simulated), final "
            f"error {error * 100:.1f} cm and {heading:.1f} deg")
    if not reached:
        last = [s for _, s in rider.received("controller", since)][-1:]
        raise DemoError(f"{text}; controller {last}, safety stops {stops[:2]}, collided {rider.collided}")
    return text


def demo_pose(demo, name):
    """A named place of the world: {name, room, x, y, yaw}."""
    listed = places(demo.args.world)
    if name not in listed:
        raise DemoError(f"no place named '{name}' in {demo.args.world}.places.yaml (there are: "
                        f"{', '.join(listed)})")
    return listed[name]


def snapshot(demo, name, view):
    started = time.monotonic()
    command = ["rosrun", "wheelchair_bringup", "snapshot", "--out", str(demo.out / f"{name}.png"),
               "--seconds", str(demo.args.snapshot_seconds), "--view", ",".join(f"{v:.3f}" for v in view),
               "--log", str(demo.logs / f"rviz_{name}.log")]
    process = demo.processes.start(f"snapshot_{name}", command)  # stopped with the rest if interrupted
    try:
        code = process.wait(demo.args.snapshot_seconds + 120)
    except subprocess.TimeoutExpired:
        raise DemoError(f"snapshot {name}.png did not finish (log: logs/snapshot_{name}.log)") from None
    if code != 0:
        raise DemoError(f"snapshot {name}.png failed: {demo.processes.log_tail(f'snapshot_{name}', 1)}")
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
        f"- Collision: {'yes' if demo.rider.collided else 'no'}",
        "",
        "![overview](overview.png)",
        "",
        "![chair at the goal](chair.png)",
        "",
    ] + demo_display.report_lines(demo)
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
    ("rider's display", demo_display.start_display),
    ("localization", initialize),
    ("display: scanning", demo_display.shot_scanning),
    ("destination", choose_destination),
    ("display: driving", demo_display.shot_driving),
    ("drive", drive),
    ("display: arrived", demo_display.shot_arrived),
    ("rviz snapshots", take_snapshots),
    ("tf tree", dump_tf_tree),
    ("display: stopped by the rider", demo_display.shot_stopped),
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
        except (DemoError, ProcessError, RiderError, demo_display.DemoDisplayError) as error:
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
        demo_display.stop_display(demo)
        demo.processes.stop_all()
    summary = (f"Demo ({time.monotonic() - started:.0f} s, world '{args.world}'): started "
               + "; ".join(result for _, result in done)
               + f". Every node ran under rosrun (no roslaunch) and all processes were stopped again; "
               f"the outputs are in {demo.out} (report.md, PNG snapshots, tf_tree.txt, logs/).")
    (demo.out / "summary.txt").write_text(summary + "\n")
    print(summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
