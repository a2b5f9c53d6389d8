#!/usr/bin/env python3
"""A person steps onto the path in front of the driving chair: the supervisor sees laser
returns that are not in the map within its stop distance ahead along the path and stops the
chair before contact (the simulator's collision check, which knows the person's disc, stays
clear), with the reason told to the rider."""
import sys
import unittest

import rospy
import rostest

from wheelchair_test.harness import Rider, point_ahead

START = (3.0, 2.2, 0.0)  # living_centre
GOAL = "kitchen_door"
AHEAD = 1.9  # [m] along the plan from the chair's axle centre (1.6 m in front of its front)
RADIUS = 0.15  # [m] a person seen from above


class Person(unittest.TestCase):
    def test_person_in_front_stops_before_contact(self):
        s = Rider("test_person")
        s.start_driving(self, START, GOAL, 0.8)
        plan = s.plans[-1]
        _, x, y, _, v, _ = s.truth
        person = point_ahead(plan, x, y, AHEAD)
        self.assertIsNotNone(person, "plan too short for the test")
        t_person, _, gap = s.stops_for_person(self, person, RADIUS, rest_wall_timeout=30.0)
        self.assertGreater(gap, 0.05, "stopped too close")
        self.assertTrue(s.wait(lambda: s.announced("in the way", t_person), 10.0),
                        "the rider was not told: " + s.describe(t_person))
        rospy.loginfo("person: chair at %.2f m/s when the person appeared %.2f m ahead; stopped "
                      "with %.2f m between its front and the person", v, AHEAD, gap)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "person", Person, sys.argv)
