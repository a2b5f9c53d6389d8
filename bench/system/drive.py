#!/usr/bin/env python3
"""The rider of bench/system: waits for the chair, sets its pose, sends one goal and waits for
the controller's goal_reached (or abort, collision, or the window), announcing "driving" when the
controller starts to follow the plan (aligning/tracking). Prints one event per line
on stdout ("<event> <wall time> <sim time> [detail]") for the measuring script to time its
/proc samples against; the rider is wheelchair_test.harness's Rider. With --cpu-topic (the chair
process's ~callback_cpu: CPU seconds per nodelet so far) the latest totals follow the "driving"
and the outcome event as a line "cpu <wall> <sim> <json>"."""
import argparse
import pathlib
import sys
import time

# the harness from this checkout (test/src), else the installed wheelchair_test
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "test" / "src"))
from wheelchair_test.harness import Rider, place  # noqa: E402

import rospy  # noqa: E402
from std_msgs.msg import String  # noqa: E402

CPU = {}  # topic -> the latest totals (JSON text)


def event(name, detail=""):
    print(f"{name} {time.time():.3f} {rospy.get_time():.3f} {detail}".rstrip(), flush=True)


def cpu_event():
    for topic, text in sorted(CPU.items()):
        event("cpu", text)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--start", default="living_centre")
    parser.add_argument("--goal", default="kitchen_door")  # the demo's destination
    parser.add_argument("--window", type=float, default=30.0, help="wall seconds of driving at most")
    parser.add_argument("--ready-timeout", type=float, default=180.0)
    parser.add_argument("--cpu-topic", nargs="*", default=[], help="chair processes' ~callback_cpu")
    args = parser.parse_args()
    rider = Rider("bench_system_rider")
    for topic in args.cpu_topic:
        rospy.Subscriber(topic, String, lambda m, t=topic: CPU.__setitem__(t, m.data), queue_size=1)
    why = rider.wait_ready(args.ready_timeout)
    if why:
        event("failed", why)
        return 1
    if abs(rider.truth[0] - rospy.get_time()) > 10.0:  # sim stamps vs this node's clock
        event("failed", "the rider is not on the simulator's /clock (/use_sim_time unset when it started)")
        return 1
    event("ready")
    if not rider.initialize(*place(args.start), wall_timeout=args.ready_timeout):
        event("failed", "not localized: " + rider.describe())
        return 1
    event("localized")
    since = rospy.get_time()
    rider.send_goal(*place(args.goal))
    event("goal_sent", args.goal)
    rider.wait(lambda: rider.controller_says("aligning", since) or
               rider.controller_says("tracking", since) or rider.drive_outcome(since), args.window)
    if not rider.drive_outcome(since):
        cpu_event()
        event("driving")
    rider.wait(lambda: rider.drive_outcome(since), args.window)
    outcome = rider.drive_outcome(since) or "window_end"
    cpu_event()
    event(outcome, f"travelled {rider.travelled(since):.2f} m; " + rider.describe(since))
    return 0


if __name__ == "__main__":
    sys.exit(main())
