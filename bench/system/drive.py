#!/usr/bin/env python3
"""The rider of bench/system: waits for the chair, sets its pose, sends one goal and waits for
the controller's goal_reached (or abort, collision, or the window), announcing "driving" when the
controller starts to follow the plan (aligning/tracking). Prints one event per line
on stdout ("<event> <wall time> <sim time> [detail]") for the measuring script to time its
/proc samples against; uses the system tests' Scenario harness (test/system/scenario.py)."""
import argparse
import pathlib
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "test" / "system"))
from scenario import Scenario, place  # noqa: E402

import rospy  # noqa: E402


def event(name, detail=""):
    print(f"{name} {time.time():.3f} {rospy.get_time():.3f} {detail}".rstrip(), flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--start", default="living_centre")
    parser.add_argument("--goal", default="kitchen_door")  # the demo's destination
    parser.add_argument("--window", type=float, default=30.0, help="wall seconds of driving at most")
    parser.add_argument("--ready-timeout", type=float, default=180.0)
    args = parser.parse_args()
    scenario = Scenario("bench_system_rider")
    why = scenario.wait_ready(args.ready_timeout)
    if why:
        event("failed", why)
        return 1
    if abs(scenario.truth[0] - rospy.get_time()) > 10.0:  # sim stamps vs this node's clock
        event("failed", "the rider is not on the simulator's /clock (/use_sim_time unset when it started)")
        return 1
    event("ready")
    if not scenario.initialize(*place(args.start), wall_timeout=args.ready_timeout):
        event("failed", "not localized: " + scenario.describe())
        return 1
    event("localized")
    since = rospy.get_time()
    scenario.send_goal(*place(args.goal))
    event("goal_sent", args.goal)
    ended = lambda: (scenario.controller_says("goal_reached", since) or  # noqa: E731
                     scenario.controller_says("aborted", since) or scenario.collided)
    scenario.wait(lambda: scenario.controller_says("aligning", since) or
                  scenario.controller_says("tracking", since) or ended(), args.window)
    if not ended():
        event("driving")
    scenario.wait(ended, args.window)
    outcome = ("goal_reached" if scenario.controller_says("goal_reached", since) else
               "collided" if scenario.collided else
               "aborted" if scenario.controller_says("aborted", since) else "window_end")
    event(outcome, f"travelled {scenario.travelled(since):.2f} m; " + scenario.describe(since))
    return 0


if __name__ == "__main__":
    sys.exit(main())
