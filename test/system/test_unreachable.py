#!/usr/bin/env python3
"""Unreachable goals are refused with a sentence a rider understands (the navigator's table
of reasons: no frame names, no planner internals), and the chair does not move: a goal inside
a wall, one outside the map, and one in a pocket of free space the chair (0.62 m wide) cannot
get into. The goals are given as a script gives them, through the navigator's `navigate`
action; each has exactly one result."""
import sys
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from wheelchair_msgs.msg import NavigateResult

from wheelchair_test.harness import Rider
from wheelchair_test.harness.drives import Drives, reason_name

START = (3.0, 2.2, 0.0)  # living_centre
N = NavigateResult
GOALS = [
    ("inside the kitchen wall", 6.05, 3.0, (N.GOAL_IN_OBSTACLE,),
     "That destination is inside a wall or furniture: choose another one."),
    ("outside the map", -2.0, -3.0, (N.GOAL_OUTSIDE_MAP,),
     "That destination is outside the map: choose another one."),
    ("a pocket narrower than the chair", 1.075, 8.175, (N.GOAL_NO_ROOM,),
     "The chair does not fit at that destination: choose another one."),
]


class Unreachable(unittest.TestCase):
    def test_unreachable_goals_are_refused_and_the_chair_stays(self):
        s = Rider("test_unreachable")
        d = Drives()
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(d.wait_servers(), "the navigator's actions are not up")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        t0 = rospy.get_time()
        for what, x, y, reasons, sentence in GOALS:
            since = rospy.get_time()
            drive = d.go(pose=(x, y, 0.0))
            self.assertTrue(drive.wait(30.0), f"{what}: no answer: " + drive.describe())
            self.assertEqual(drive.status(), GoalStatus.REJECTED, f"{what}: " + drive.describe())
            result = drive.result()
            self.assertIn(result.reason, reasons, f"{what}: " + drive.describe())
            self.assertEqual(result.sentence, sentence)
            for word in ("base_link", "map->", "footprint", "search", "cell"):
                self.assertNotIn(word, result.sentence)
            with s.lock:
                plans = [p for p in s.plans if p.header.stamp.to_sec() >= since - 0.01]
            self.assertTrue(all(len(p.poses) == 0 for p in plans), f"{what}: a path was published")
            rospy.loginfo("%s (%.2f, %.2f): %s: %s [%s]", what, x, y, reason_name(result.reason),
                          result.sentence, result.detail)
            s.sim_sleep(1.0)
            self.assertEqual(len(drive.result_messages()), 1, drive.result_messages())
        self.assertLess(s.travelled(t0), 0.02, "the chair moved: " + s.describe(t0))
        distance, _ = s.error_to(*START)
        self.assertLess(distance, 0.02)
        self.assertFalse(s.collided)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "unreachable", Unreachable, sys.argv)
