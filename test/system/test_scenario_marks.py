#!/usr/bin/env python3
"""The system tests' windows of messages (Rider.mark): a message received before a mark
never counts after it, even at the same simulated time. No /clock runs here, so the sim time
stays 0 and every message and mark share it: the worst case of a loaded machine, where the
test's clock had not advanced between one leg's 'goal_reached' and the next leg's start."""
import sys
import unittest

import rospy
import rostest
from std_msgs.msg import String

from wheelchair_test.harness import Rider


class ScenarioMarks(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.s = Rider("test_scenario_marks")

    def status(self, text):
        self.s._on_controller(String(data=text))

    def announce(self, text):
        self.s._on_announcement(String(data=text))

    def test_the_clock_stands_still(self):
        self.assertEqual(rospy.get_time(), 0.0)

    def test_a_status_before_the_mark_is_not_after_it(self):
        s = self.s
        self.status("goal_reached")
        self.announce("Arrived.")
        since = s.mark()
        self.assertEqual(since.time, rospy.get_time())  # same time as the messages
        self.assertFalse(s.controller_says("goal_reached", since), s.describe(since))
        self.assertFalse(s.announced("Arrived", since), s.describe(since))
        self.status("aligning")
        self.assertFalse(s.controller_says("goal_reached", since))
        self.status("goal_reached")
        self.assertTrue(s.controller_says("goal_reached", since))
        self.assertEqual([t for _, t in s.received("controller", since)],
                         ["aligning", "goal_reached"])
        self.assertIn("aligning", s.describe(since))

    def test_a_time_still_selects_by_time(self):
        self.status("tracking")
        self.assertTrue(self.s.controller_says("tracking", rospy.get_time()))
        self.assertFalse(self.s.controller_says("tracking", rospy.get_time() + 1.0))


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "scenario_marks", ScenarioMarks, sys.argv)
