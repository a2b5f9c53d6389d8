#!/usr/bin/env python3
"""The only route blocked, with the whole chair in the simulator loop (issue 22); every drive
is a goal of the navigator's `navigate` action and ends with exactly one result:
- from the living room to the toilet, a person-sized obstacle standing in the bathroom's 80 cm
  doorway, its one door: the chair stops short of it, the rider is told where the way is
  blocked, and after navigator/blocked_timeout (15 s here) the drive ends BLOCKED with that
  sentence;
- the obstacle gone (and forgotten by the live layer /obstacles), a new drive, the obstacle put
  back in the doorway while the chair drives: it stops for it; taken away again while the chair
  waits, it resumes without a new command and arrives.
The planner plans on the static map plus the live obstacle layer: a way around the doorway
does not exist, so the navigator must not keep driving into it."""
import math
import sys
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from nav_msgs.msg import OccupancyGrid
from wheelchair_msgs.msg import NavigateResult, NavigatorState
from wheelchair_sim.srv import AddMovingObstacle

from wheelchair_test.harness import Rider
from wheelchair_test.harness.drives import (Drives, check_arrived, clear_obstacles,
                                            layer_occupied_near)

HALL_START = (5.1, 4.9, 1.5708)  # living_door, facing the hallway's door
GOAL_BEHIND = "toilet"  # the bathroom's one door: hallway_bathroom
DOORWAY = (4.45, 7.20)  # hallway_bathroom (flat.doors.yaml), 0.80 m wide
DOOR_BLOCK = 0.25  # [m] radius: 0.15 m left either side of the chair's 0.62 m


class Blocked(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.s = Rider("test_navigation_blocked")
        cls.d = Drives()
        cls.add = rospy.ServiceProxy("/sim/add_moving_obstacle", AddMovingObstacle)
        cls.layer = None
        rospy.Subscriber("/obstacles", OccupancyGrid, lambda m: setattr(cls, "layer", m))

    def block_the_doorway(self):
        answer = self.add(DOORWAY[0], DOORWAY[1], DOOR_BLOCK, 0.0, 0.0, 0.0, 0.0)
        self.assertTrue(answer.success, answer.message)

    def blocked_told(self, since):
        return self.s.announced("The way is blocked near bathroom door", since)

    def test_1_the_only_route_blocked_ends_the_drive_with_where(self):
        s, d = self.s, self.d
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(d.wait_servers(), "the navigator's actions are not up")
        self.assertTrue(s.teleport(*HALL_START).success)
        s.sim_sleep(1.0)  # the scans taken before the teleport are through the localizer
        self.assertTrue(s.initialize(*HALL_START), "not localized: " + s.describe())
        self.block_the_doorway()
        t0 = s.mark()
        drive = d.go(place=GOAL_BEHIND)
        self.assertTrue(s.wait(lambda: d.was_in(NavigatorState.BLOCKED, t0.time), 120.0),
                        "never blocked: " + drive.describe() + "; " + s.describe(t0))
        self.assertTrue(s.wait(lambda: self.blocked_told(t0), 10.0),
                        "the rider was not told where: " + s.describe(t0))
        self.assertTrue(drive.wait(90.0), "the drive did not end: " + drive.describe())
        self.assertEqual(drive.status(), GoalStatus.ABORTED, drive.describe())
        self.assertEqual(drive.result().reason, NavigateResult.BLOCKED, drive.describe())
        self.assertEqual(drive.result().sentence, "The way is blocked near bathroom door. The "
                         "chair has stopped: choose a destination to go on.")
        self.assertTrue(s.wait(s.at_rest, 20.0))
        s.sim_sleep(1.0)
        self.assertEqual(len(drive.result_messages()), 1, drive.result_messages())
        self.assertFalse(s.collided, "contact: " + s.describe(t0))
        _, x, y, _, _, _ = s.truth
        self.assertGreater(math.hypot(x - DOORWAY[0], y - DOORWAY[1]), 0.6, "too close")

    def doorway_in_layer(self):
        """Whether /obstacles has anything within 0.4 m of the doorway (None: no layer yet)."""
        return layer_occupied_near(self.layer, DOORWAY, 0.4)

    def test_2_the_obstacle_taken_away_the_chair_resumes_without_a_new_command(self):
        s, d = self.s, self.d
        # The obstacle of test 1 gone and forgotten by the live layer: the way is open.
        self.assertTrue(clear_obstacles().success)
        self.assertTrue(s.wait(lambda: self.doorway_in_layer() is not True, 60.0),
                        "the obstacle layer still has the doorway blocked")
        t0 = s.mark()
        drive = d.go(place=GOAL_BEHIND)
        self.assertTrue(s.wait(lambda: s.travelled(t0) > 0.5, 60.0),
                        "the chair did not start: " + drive.describe())
        self.block_the_doorway()  # while the chair drives towards it
        stopped = (NavigatorState.WAITING, NavigatorState.BLOCKED)
        self.assertTrue(s.wait(lambda: any(d.was_in(x, t0.time) for x in stopped), 90.0),
                        "never stopped for it: " + drive.describe() + "; " + s.describe(t0))
        self.assertFalse(drive.done(), drive.describe())
        t_clear = rospy.get_time()
        self.assertTrue(clear_obstacles().success)
        self.assertTrue(drive.wait(150.0), "the drive did not end: " + drive.describe())
        check_arrived(self, s, drive, GOAL_BEHIND, t0)
        states = [m.state for m in d.states_since(t_clear)]
        self.assertIn(NavigatorState.DRIVING, states, "it did not drive on")
        rospy.loginfo("navigation: blocked doorway cleared: arrived %.1f s (sim) later",
                      rospy.get_time() - t_clear)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "navigation_blocked", Blocked, sys.argv)
