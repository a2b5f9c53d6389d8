#!/usr/bin/env python3
"""An obstacle appears on the route while a second route is free, with the whole chair in the
simulator loop (issue 22): from the living room's centre to the kitchen door the route passes
east of the dining table (the 1.15 m gap between the table and the kitchen wall); a 0.4 m
obstacle the map does not have is put in the middle of that gap once the chair drives (0.375 m
left either side, the chair is 0.62 m wide). The chair takes the
other way, round the table's north side (the planner plans on the map plus the live layer
/obstacles), and arrives without contact and without a new command; the drive (a goal of the
navigator's `navigate` action) has exactly one result. Where the chair went is the simulator's
truth (/sim/ground_truth)."""
import math
import sys
import unittest

import rospy
import rostest
from wheelchair_sim.srv import AddMovingObstacle

from wheelchair_test.harness import Rider
from wheelchair_test.harness.drives import Drives, check_arrived

START = (3.0, 2.2, 0.0)  # living_centre
TABLE = (3.6, 4.85, 2.8, 3.8)  # the dining table in flat: x0, x1, y0, y1 (the wall: x 6.0)
GAP_BLOCK = (5.425, 3.30, 0.20)  # x, y, radius: 0.375 m to the table and to the wall


def in_east_gap(x, y):
    return TABLE[1] < x < 6.0 and TABLE[2] < y < TABLE[3]


def north_of_table(x, y):
    return TABLE[0] < x < TABLE[1] and y > TABLE[3]


class Around(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.s = Rider("test_navigation_around")
        cls.d = Drives()
        cls.add = rospy.ServiceProxy("/sim/add_moving_obstacle", AddMovingObstacle)

    def test_1_an_obstacle_on_the_route_with_another_route_free_is_driven_round(self):
        s, d = self.s, self.d
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(d.wait_servers(), "the navigator's actions are not up")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        t0 = s.mark()
        drive = d.go(place="kitchen_door")
        self.assertTrue(s.wait(lambda: s.travelled(t0) > 0.3, 60.0),
                        "the chair did not start: " + drive.describe())
        with s.lock:
            plan = s.plans[-1]
        first = [(p.pose.position.x, p.pose.position.y) for p in plan.poses]
        self.assertTrue(any(in_east_gap(x, y) for x, y in first),
                        "the first route does not pass east of the table: the scenario is off")
        x, y, r = GAP_BLOCK
        answer = self.add(x, y, r, 0.0, 0.0, 0.0, 0.0)  # there for good
        self.assertTrue(answer.success, answer.message)
        t_block = rospy.get_time()
        self.assertTrue(drive.wait(100.0), "the drive did not end: " + drive.describe() + "; "
                        + s.describe(t0))
        with s.lock:
            plans = [c for c in s.certificates if c.header.stamp.to_sec() >= t_block]
        routes = ", ".join("%.3f s %s (footprint search %.3f s)"
                           % (c.planning_time, c.path_stage, c.search_time) for c in plans)
        rospy.loginfo("navigation: routes after the obstacle appeared: %s", routes)
        # Where the chair believed it was at the end (the navigator's pose, the localizer's
        # estimate), beside the truth: an arrival short of the place by the truth is then told
        # apart as a localization error (one run of 5 on 2026-12-02: 0.59 m short).
        with d.lock:
            last = d.states[-1][1].pose.pose if d.states else None
        if last is not None:
            rospy.loginfo("navigation: the chair's estimate at the end (%.2f, %.2f), the truth "
                          "%s", last.position.x, last.position.y, s.describe(t0).split("; ")[-2])
        check_arrived(self, s, drive, "kitchen_door", t0)
        result = drive.result()
        self.assertGreaterEqual(result.replans, 1, drive.describe())
        with s.lock:
            truth = [(x, y) for t, x, y in s.truth_path if t >= t_block]
        self.assertTrue(any(north_of_table(x, y) for x, y in truth),
                        "the chair did not go round the north of the table: " + drive.describe())
        closest = min(math.hypot(px - x, py - y) for px, py in truth)
        self.assertGreater(closest, r + 0.31, "the chair drove into the blocked gap")
        said = d.sentences_since(t_block)
        self.assertTrue(any(t.startswith("Going another way") for t in said), said)
        rospy.loginfo("navigation: obstacle in the table's east gap: round the north side, "
                      "arrived in %.1f s (sim) after the goal, %d replan(s), %d wait(s), "
                      "closest %.2f m to the obstacle's centre; routes after it: %s",
                      result.duration, result.replans, result.waits, closest, routes)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "navigation_around", Around, sys.argv)
