#!/usr/bin/env python3
"""Unreachable goals are refused with a message the rider sees, and the chair does not move:
a goal inside a wall, one outside the map, and one in a pocket of free space the chair
(0.62 m wide) cannot get into."""
import sys
import unittest

import rospy
import rostest

from wheelchair_test.harness import Rider

START = (3.0, 2.2, 0.0)  # living_centre
GOALS = [
    ("inside the kitchen wall", 6.05, 3.0),
    ("outside the map", -2.0, -3.0),
    ("a pocket narrower than the chair", 1.075, 8.175),
]


class Unreachable(unittest.TestCase):
    def test_unreachable_goals_are_refused_and_the_chair_stays(self):
        s = Rider("test_unreachable")
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        t0 = rospy.get_time()
        for what, x, y in GOALS:
            since = rospy.get_time()
            s.send_goal(x, y, 0.0)
            self.assertTrue(s.wait(lambda: s.announced("Cannot go there", since), 30.0),
                            f"{what}: no refusal told to the rider: " + s.describe(since))
            with s.lock:
                told = [text for t, text in s.announcements if t >= since and "Cannot" in text]
                plans = [p for p in s.plans if p.header.stamp.to_sec() >= since - 0.01]
            self.assertTrue(all(len(p.poses) == 0 for p in plans), f"{what}: a path was published")
            rospy.loginfo("%s (%.2f, %.2f): %s", what, x, y, told[0])
            s.sim_sleep(1.0)
        self.assertLess(s.travelled(t0), 0.02, "the chair moved: " + s.describe(t0))
        distance, _ = s.error_to(*START)
        self.assertLess(distance, 0.02)
        self.assertFalse(s.collided)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "unreachable", Unreachable, sys.argv)
