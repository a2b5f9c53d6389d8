#!/usr/bin/env python3
"""A person crossing the route ahead, with the whole chair in the simulator loop (issue 22):
the chair stops, waits, and goes on by itself once the person has passed; it arrives without
contact, and the drive (a goal of the navigator's `navigate` action) has exactly one result."""
import math
import sys
import unittest

import rospy
import rostest
from wheelchair_msgs.msg import NavigatorState
from wheelchair_sim.srv import AddMovingObstacle

from wheelchair_test.harness import Rider
from wheelchair_test.harness.drives import Drives, check_arrived

START = (3.0, 2.2, 0.0)  # living_centre
AHEAD = 1.9  # [m] along the route where the person crosses
WALK = 0.15  # [m/s] the person's speed across the route


def along(plan, x, y, distance):
    """(point, unit tangent) `distance` along the plan from the vertex nearest to (x, y)."""
    points = [(p.pose.position.x, p.pose.position.y) for p in plan.poses]
    i = min(range(len(points)), key=lambda k: math.hypot(points[k][0] - x, points[k][1] - y))
    walked = 0.0
    for a, b in zip(points[i:], points[i + 1:]):
        step = math.hypot(b[0] - a[0], b[1] - a[1])
        if step > 0 and walked + step >= distance:
            f = (distance - walked) / step
            return (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])), \
                ((b[0] - a[0]) / step, (b[1] - a[1]) / step)
        walked += step
    return None, None


class Person(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.s = Rider("test_navigation_person")
        cls.d = Drives()
        cls.add = rospy.ServiceProxy("/sim/add_moving_obstacle", AddMovingObstacle)

    def test_1_a_person_crossing_ahead_makes_the_chair_wait_and_go_on(self):
        s, d = self.s, self.d
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(d.wait_servers(), "the navigator's actions are not up")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        t0 = s.mark()
        drive = d.go(place="kitchen_door")
        self.assertTrue(s.wait(lambda: s.travelled(t0) > 0.8, 60.0),
                        "the chair did not start: " + drive.describe())
        _, x, y, _, v, _ = s.truth
        with s.lock:
            plan = s.plans[-1]
        point, tangent = along(plan, x, y, AHEAD)
        self.assertIsNotNone(point, "route too short for the test")
        # On the route now, walking off it to the left; gone once 0.9 m away (clear of the
        # chair's corridor by then).
        t_person = rospy.get_time()
        answer = self.add(point[0], point[1], 0.15, -WALK * tangent[1], WALK * tangent[0],
                          t_person, t_person + 6.0)
        self.assertTrue(answer.success, answer.message)
        self.assertTrue(s.wait(lambda: d.was_in(NavigatorState.WAITING, t_person), 30.0),
                        "the chair did not wait: " + drive.describe() + "; " + s.describe(t0))
        self.assertTrue(drive.wait(120.0), "the drive did not end: " + drive.describe())
        check_arrived(self, s, drive, "kitchen_door", t0)
        self.assertGreaterEqual(drive.result().waits, 1, drive.describe())
        # It goes on by itself: on the same route once the way is free, or round the person's
        # trace in the live layer (both without a new command).
        said = d.sentences_since(t_person)
        self.assertTrue("The way is free: going on." in said
                        or any(x.startswith("Going another way") for x in said),
                        drive.describe())
        rospy.loginfo("navigation: person crossing %.1f m ahead at %.2f m/s (chair %.2f m/s): "
                      "waited %d time(s), arrived in %.1f s (sim)", AHEAD, WALK, v,
                      drive.result().waits, drive.result().duration)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "navigation_person", Person, sys.argv)
