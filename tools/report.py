#!/usr/bin/python3
"""`./wheelchair report`: the paper's Table 2 protocol end to end, and Table 1, side by side
with the paper (the workspace must be sourced).

Starts its own ROS master on a free port, the simulator behind the CAN (UDP) path and the
one-process chair (test/table2/table2_stack.py's start, through wheelchair_test.harness), drives
the 10 pairs of
test/table2/flat_pairs.yaml (test/table2/table2_protocol.py), and writes into --out:
  report.md            the paper's Tables 1 and 2 beside ours, definitions, figures
  runs.json            every run: plan, truth, estimate, MSErc, MSEre, goal errors, outcome
  run_NN.png           per run, in the style of the paper's Figures 7 and 8 (matplotlib)
  overview.png         every route on the map (the paper's Figure 5)
  snapshots/run_NN.png rviz off-screen snapshot at the end of each run (plan, truth, estimate)
  kld_bench.json       `bench/kld/run` (the KLD package's benchmark) for Table 1
  logs/                one log per process
Exit 0 when every run reached its goal and both means beat the paper, else 1.

--cpu-quota 15: the chair process confined to 15 % of one core (cgroup v1 cpu controller, as
root; the deployed unit's CPUQuota=15%), the legacy-PC budget, in periods of --cpu-period-ms
(default 10, the unit's CPUQuotaPeriodSec=10ms: with the default 100 ms period a burst of work
uses the period's 15 ms and every thread then waits 85 ms, past the motor controller's 100 ms
command watchdog); runs.json and report.md then give the quota's throttling and CPU used.

--slam-map MAP.yaml: the same protocol on a map the chair made (bench/slam_table2: flat mapped
live by wheelchair_slam, brought into the world frame): the map server serves it (so the
localizer, the planners and the navigator all work on it) and the figures are drawn on it.
"""
import argparse
import json
import math
import os
import pathlib
import subprocess
import sys
import time

import rospkg
import rospy
import yaml
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path

ROOT = pathlib.Path(__file__).resolve().parent.parent
TABLE2 = ROOT / "test" / "table2"
sys.path.insert(0, str(TABLE2))
sys.path.insert(0, str(ROOT / "test" / "src"))  # wheelchair_test.harness, by path
import table2_figures as figures  # noqa: E402
import table2_protocol as protocol  # noqa: E402
import table2_stack  # noqa: E402
from wheelchair_test.harness import Processes, start_master  # noqa: E402

TRUTH_TOPIC, ESTIMATE_TOPIC = "/table2/truth_path", "/table2/estimate_path"
RUNNER = "table2_report"  # this node: the HMI's go_to_caller in the bring-up copy (the rider)


def rviz_config(out):
    """wheelchair_bringup's rviz config plus the recorded truth (blue) and estimate (red)."""
    source = pathlib.Path(rospkg.RosPack().get_path("wheelchair_bringup")) / "config" / "wheelchair.rviz"
    config = yaml.safe_load(source.read_text())
    displays = config["Visualization Manager"]["Displays"]
    plan = next(d for d in displays if d.get("Class") == "rviz/Path")
    # truth and estimate lie within 1-3 cm of the plan: each drawn above and narrower than the
    # one below (plan 5 cm green, truth 3 cm blue, estimate 1.5 cm red), or the plan hides them
    for name, topic, color, width, z in (("Truth", TRUTH_TOPIC, "0; 90; 255", 0.03, 0.01),
                                         ("Estimate", ESTIMATE_TOPIC, "230; 30; 30", 0.015, 0.02)):
        displays.append(dict(plan, Name=name, Topic=topic, Color=color,
                             Offset={"X": 0, "Y": 0, "Z": z}, **{"Line Width": width}))
    for d in displays:  # particles hide the trajectories; a trajectory of all runs clutters
        if d.get("Topic") == "/particlecloud" or d.get("Name", "").startswith("Trajectory"):
            d["Enabled"] = False
    target = out / "table2.rviz"
    target.write_text(yaml.safe_dump(config))
    return target


def path_message(samples):
    msg = Path()
    msg.header.frame_id = "map"
    for s in samples:
        p = PoseStamped()
        p.header.frame_id = "map"
        p.pose.position.x, p.pose.position.y = s[1], s[2]
        p.pose.orientation.z, p.pose.orientation.w = math.sin(s[3] / 2), math.cos(s[3] / 2)
        msg.poses.append(p)
    return msg


def snapshot(record, config, out, logs):
    xs = [p[0] for p in record["plan"]] or [5.0]
    ys = [p[1] for p in record["plan"]] or [6.0]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 2.0) + 1.5
    # the 3D view is about 620 x 700 px of the 1000 x 800 window (the displays panel takes the rest)
    view = f"{(min(xs) + max(xs)) / 2:.2f},{(min(ys) + max(ys)) / 2:.2f},{min(600 / span, 200):.0f}"
    target = out / f"run_{record['index']:02d}.png"
    result = subprocess.run(["rosrun", "wheelchair_bringup", "snapshot", "--out", str(target),
                             "--config", str(config), "--view", view, "--size", "1000x800", "--seconds", "8",
                             "--log", str(logs / f"rviz_run_{record['index']:02d}.log")],
                            capture_output=True, text=True, timeout=180)
    if result.returncode != 0:
        return "snapshot failed: " + (result.stdout + result.stderr).strip()[-200:]
    return None


def run_protocol(args, out, logs):
    world, pairs = protocol.load_pairs()
    if args.pairs:
        pairs = [p for p in pairs if p["index"] in args.pairs]
    procs = Processes(logs)
    records = []
    bringup_copy = None
    quota = None
    try:
        start_master(procs, rosout=True, use_sim_time=True, export=True)
        bringup_copy = table2_stack.start(
            procs, args.bringup or table2_stack.default_config(),
            ROOT / "test" / "worlds" / "flat.yaml", args.speed, pairs[0]["start"], args.nice,
            rider="/" + RUNNER)  # the runner releases a stop as the rider's display does
        if args.cpu_quota:
            from wheelchair_test.harness.cpu_quota import CpuQuota

            quota = CpuQuota(procs.get("chair").pid, args.cpu_quota,
                             period_us=int(args.cpu_period_ms * 1000))
            print(f"chair process confined to {args.cpu_quota:g} % of one core "
                  f"(period {args.cpu_period_ms:g} ms)", flush=True)
        rospy.init_node(RUNNER, disable_signals=True)
        runner = protocol.Table2Runner(wall_scale=args.wall_scale)
        runner.check_processes = procs.check
        runner.wait_ready()
        args.nice = procs.niceness("chair")  # what the stack got
        truth_pub = rospy.Publisher(TRUTH_TOPIC, Path, queue_size=1, latch=True)
        estimate_pub = rospy.Publisher(ESTIMATE_TOPIC, Path, queue_size=1, latch=True)
        config = rviz_config(out) if args.snapshots else None
        for pair in pairs:
            procs.check()
            try:
                record = runner.run_pair(pair)
            except RuntimeError as e:
                record = {"index": pair["index"], "name": pair["name"], "via": pair["via"],
                          "start": list(pair["start"]), "goal": list(pair["goal"]),
                          "outcome": f"error: {e}"}
            if record.get("released_before_run"):
                print(f"  the rider released the earlier run's stop through the HMI: "
                      f"{record['released_before_run']}", flush=True)
            print(f"run {pair['index']:2d} {pair['name']:26s} {record['outcome']:14s} "
                  f"MSErc {record.get('mse_rc_cm2', math.nan):6.2f}  "
                  f"MSEre {record.get('mse_re_cm2', math.nan):6.2f} cm2  goal "
                  f"{100 * record.get('goal_position_error_m', math.nan):5.1f} cm "
                  f"{record.get('goal_heading_error_deg', math.nan):5.1f} deg", flush=True)
            if config is not None and "truth" in record:
                truth_pub.publish(path_message(record["truth"]))
                estimate_pub.publish(path_message(record["estimate"]))
                problem = snapshot(record, config, out / "snapshots", logs)
                if problem:
                    record["snapshot"] = problem
                    print("  " + problem, flush=True)
            records.append(record)
    finally:
        if quota is not None:
            args.quota_stats = quota.stats()
            quota.close()
        procs.stop_all()
        if bringup_copy is not None:
            os.unlink(bringup_copy)
    return world, records


def use_slam_map(args, out):
    """--slam-map: a copy of the bring-up file (--bringup or chair_sim.yaml) whose map server
    serves the SLAM map; args.bringup points at it. Returns its path."""
    source = pathlib.Path(args.bringup or table2_stack.default_config())
    config = yaml.safe_load(source.read_text())
    servers = [n for n in config.get("nodelets", [])
               if n.get("type") == "wheelchair_mapping/MapServerNodelet"]
    if len(servers) != 1:
        raise SystemExit(f"{source}: expected one map server, found {len(servers)}")
    slam_map = pathlib.Path(args.slam_map).resolve()
    if not slam_map.exists():
        raise SystemExit(f"--slam-map {slam_map}: no such file")
    servers[0]["params"] = dict(servers[0].get("params") or {}, map_file=str(slam_map))
    target = out / "chair_slam_map.yaml"
    target.write_text(f"# {source} with the map server on {slam_map} (--slam-map)\n" +
                      yaml.safe_dump(config, sort_keys=False))
    args.bringup = str(target)
    print(f"map server on the SLAM map {slam_map}", flush=True)
    return target


def kld_bench(out, logs, timeout):
    """The KLD package's own benchmark: out/bench/kld.json from `./wheelchair bench kld` when
    there is one (it takes 15-30 min on a loaded 2-core machine), else bench/kld/run now.
    Returns (rows, None) or (None, the reason)."""
    saved = ROOT / "out" / "bench" / "kld.json"
    if saved.exists():
        doc = json.loads(saved.read_text())
        (out / "kld_bench.json").write_text(json.dumps(doc, indent=1))
        return doc["results"], None
    try:
        result = subprocess.run([str(ROOT / "bench" / "kld" / "run")], cwd=ROOT,
                                capture_output=True, text=True, timeout=timeout)
    except (subprocess.TimeoutExpired, OSError) as e:
        return None, f"bench/kld/run: {e}"
    (logs / "kld_bench.log").write_text(result.stderr)
    if result.returncode != 0:
        return None, f"bench/kld/run exited with {result.returncode}"
    try:
        rows = json.loads(result.stdout)
    except json.JSONDecodeError as e:
        return None, f"bench/kld/run printed no JSON: {e}"
    (out / "kld_bench.json").write_text(json.dumps(rows, indent=1))
    return rows, None


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=str(ROOT / "out" / "report"))
    parser.add_argument("--pairs", type=lambda s: [int(v) for v in s.split(",")], default=None,
                        help="comma-separated 1-based pair indices (default: all 10)")
    parser.add_argument("--speed", type=float, default=1.0,
                        help="simulated / wall time (the stack misses deadlines at 2x under load)")
    parser.add_argument("--nice", type=int, default=-5,
                        help="niceness of simulator and chair (deploy/wheelchair.service: -5)")
    parser.add_argument("--wall-scale", type=float, default=1.0,
                        help="multiplies every wall-clock timeout (loaded machine)")
    parser.add_argument("--bringup", help="bring-up file (default: chair_sim.yaml)")
    parser.add_argument("--cpu-quota", type=float, default=None, metavar="PERCENT",
                        help="confine the chair process to PERCENT of one core (root)")
    parser.add_argument("--cpu-period-ms", type=float, default=10.0,
                        help="the quota's period (cfs_period_us), the unit's CPUQuotaPeriodSec; "
                             "100 (the kernel's and systemd's default) starves the motor watchdog")
    parser.add_argument("--slam-map", metavar="MAP.yaml",
                        help="serve this map (flat as wheelchair_slam mapped it, in the world "
                             "frame) instead of the drawn one")
    parser.add_argument("--no-snapshots", dest="snapshots", action="store_false")
    parser.add_argument("--no-kld-bench", dest="kld_bench", action="store_false")
    parser.add_argument("--kld-bench-timeout", type=float, default=2400.0)
    parser.add_argument("--from-json", help="redo tables and plots from a runs.json, no runs")
    args = parser.parse_args()
    out = pathlib.Path(args.out).resolve()
    logs = out / "logs"
    for d in (out, logs, out / "snapshots"):
        d.mkdir(parents=True, exist_ok=True)
    os.environ.setdefault("ROS_LOG_DIR", str(logs / "ros"))

    if args.from_json:
        data = json.loads(pathlib.Path(args.from_json).read_text())
        world, records = data["world"], data["runs"]
        args.speed, args.nice = data.get("speed", args.speed), data.get("nice")
        wall = data.get("wall_time_s")
    else:
        if args.slam_map:
            use_slam_map(args, out)
        wall0 = time.time()
        world, records = run_protocol(args, out, logs)
        wall = time.time() - wall0
        finished = [r for r in records if "mse_rc_cm2" in r]
        (out / "runs.json").write_text(json.dumps(
            {"world": world, "speed": args.speed, "nice": args.nice, "wall_time_s": wall,
             "cpu_quota": getattr(args, "quota_stats", None), "slam_map": args.slam_map,
             "runs": records, "summary": protocol.summarize(finished)}))
    bench_rows, bench_problem = (kld_bench(out, logs, args.kld_bench_timeout) if args.kld_bench
                                 else (None, "not run (--no-kld-bench)"))
    map_file = ROOT / "test" / "worlds" / world
    if args.from_json and data.get("slam_map"):
        args.slam_map = data["slam_map"]
    if args.slam_map:
        map_file = pathlib.Path(args.slam_map).resolve()
    figures.run_figures(records, map_file, out)
    figures.overview_figure(records, map_file, out / "overview.png")
    ok = figures.write_markdown(records, bench_rows, bench_problem, out / "report.md",
                                speed=args.speed, nice=args.nice, wall_time_s=wall)
    stats = getattr(args, "quota_stats", None)
    if stats:
        reached = sum(r.get("outcome") == "goal_reached" for r in records)
        used = "n/a" if stats["used_percent"] is None else f"{stats['used_percent']:.1f} %"
        with open(out / "report.md", "a") as f:
            f.write(f"\n**CPU quota** {stats['quota_percent']:g} % of one core on the chair "
                    f"process: {reached}/{len(records)} goals reached; CPU used {used} over "
                    f"{stats['wall_s']:.0f} s; throttled in {stats['throttled_periods']} of "
                    f"{stats['periods']} periods ({stats['throttled_s']:.1f} s).\n")
    if args.slam_map:
        with open(out / "report.md", "a") as f:
            f.write(f"\n**Map**: every run on the SLAM map `{args.slam_map}` (served by the map "
                    f"server: localizer, planners and navigator on it), not the drawn "
                    f"`{world}`.\n")
    print((out / "report.md").read_text())
    print(f"report written to {out}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
