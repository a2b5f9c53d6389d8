#!/usr/bin/env python3
"""A doorway sequence in `flat`: living room -> hallway -> study, through the 90 cm
living/hallway door and the 80 cm study door (the chair is 62 cm wide: 9 cm either side). The
chair must reach its goal (10 cm, 10 deg) without touching anything, and the true trajectory
must pass through each doorway. The goal faces the way the chair arrives: its rear corners
sweep 0.86 m when it turns on the spot, more than the room there allows."""
import math
import sys
import unittest

import rospy
import rostest
import yaml

from wheelchair_test.harness import Rider, worlds_dir

START = (3.0, 2.2, 0.0)  # living_centre
LEGS = [((7.0, 7.4, 0.0), ["living_hallway", "hallway_study"])]  # tail 0.4 m clear of the door


def doors():
    with open(worlds_dir() / "flat.doors.yaml") as f:
        return {d["name"]: d for d in yaml.safe_load(f)["doors"]}


class Doorways(unittest.TestCase):
    def test_doorway_sequence(self):
        s = Rider("test_doorways")
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        all_doors = doors()
        for goal, passed in LEGS:
            since = s.mark()  # not a time: the last leg's end can carry this leg's start time
            s.send_goal(*goal)
            done = s.wait(lambda: s.controller_says("goal_reached", since) or
                          s.controller_says("aborted", since) or s.collided, 150.0)
            reached, what = done and s.controller_says("goal_reached", since), s.describe(since)
            self.assertTrue(reached, f"{goal}: {what}")
            self.assertTrue(s.wait(s.at_rest, 20.0))
            distance, heading = s.error_to(*goal)
            self.assertLess(distance, 0.10, f"{goal}: {s.describe(since)}")
            self.assertLess(heading, math.radians(10), goal)
            with s.lock:
                path = [(x, y) for t, x, y in s.truth_path if t >= since.time]
            for name in passed:
                d = all_doors[name]
                closest = min(math.hypot(x - d["x"], y - d["y"]) for x, y in path)
                self.assertLess(closest, 0.3, f"{goal}: did not pass the door {name}")
            rospy.loginfo("doorways: %s reached %.3f m / %.1f deg off after %.1f s (sim), "
                          "%.2f m driven", goal, distance, math.degrees(heading),
                          rospy.get_time() - since.time, s.travelled(since))
        self.assertFalse(s.collided, "collision: " + s.describe())


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "doorways", Doorways, sys.argv)
