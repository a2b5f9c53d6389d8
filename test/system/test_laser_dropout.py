#!/usr/bin/env python3
"""Laser dropout mid-route: the supervisor stops the chair within the 300 ms watchdog plus the
braking time, says why (safety status and the rider's announcement), and the chair stays at
rest — it does not drive on when the laser comes back, only on a new command."""
import math
import sys
import unittest

import rospy
import rostest
from wheelchair_msgs.msg import SafetyStatus
from wheelchair_sim.srv import EnableLaser

from wheelchair_test.harness import Rider, describe_stop

START = (3.0, 2.2, 0.0)  # living_centre, heading +x
GOAL = "kitchen_door"


class LaserDropout(unittest.TestCase):
    def test_laser_dropout_stops_with_reason(self):
        s = Rider("test_laser_dropout")
        s.start_driving(self, START, GOAL, 1.0)
        laser = rospy.ServiceProxy("/sim/enable_laser", EnableLaser)
        t_off = rospy.get_time()
        self.assertTrue(laser(False).success)
        self.assertTrue(s.wait(lambda: s.first_stop(t_off), 30.0),
                        "no safety stop: " + s.describe(t_off))
        stopped_at, stop = s.first_stop(t_off)
        reason = describe_stop(stop)
        self.assertEqual(stop.reason, SafetyStatus.LASER_SILENT, reason)
        self.assertIn("laser", stop.sentence)
        # 300 ms watchdog + one supervisor period (50 ms) + scan period slack (100 ms).
        self.assertLess(stopped_at - t_off, 0.3 + 0.05 + 0.1 + 0.1, reason)
        self.assertTrue(s.wait(s.at_rest, 30.0), "still moving: " + s.describe(t_off))
        rest = rospy.get_time()
        self.assertLess(rest - t_off, 3.0, "controlled stop took too long")
        self.assertTrue(s.wait(lambda: s.announced("laser", t_off), 10.0),
                        "the rider was not told: " + s.describe(t_off))
        self.assertTrue(laser(True).success)
        s.sim_sleep(2.0)
        self.assertLess(s.travelled(rest + 0.5), 0.05, "drove on without a new command")
        self.assertFalse(s.collided)
        rospy.loginfo("laser dropout: stop published %.2f s after the dropout, at rest after "
                      "%.2f s", stopped_at - t_off, rest - t_off)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "laser_dropout", LaserDropout, sys.argv)
