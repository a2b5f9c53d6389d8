#!/usr/bin/env python3
"""A way known blocked at the start, with the whole chair in the simulator loop (issue 22): at
the living room's door, facing the hallway, the bathroom's one doorway (80 cm) has a 0.5 m
obstacle in it that the live layer /obstacles shows before the rider asks for the toilet. The
planner (map + layer) finds no route; the navigator does not refuse at once: the rider is told
"The way is blocked near bathroom door: the chair waits until it is free.", the chair stays
where it is, and the first route is asked again every replan_period. The obstacle taken away,
the chair goes by itself and arrives; one result (a goal of the `navigate` action). That the
wait is bounded (blocked_timeout, then BLOCKED with where) is the navigator's gtest."""
import sys
import unittest

import rospy
import rostest
from nav_msgs.msg import OccupancyGrid
from wheelchair_msgs.msg import NavigatorState
from wheelchair_sim.srv import AddMovingObstacle

from wheelchair_test.harness import Rider
from wheelchair_test.harness.drives import (Drives, check_arrived, clear_obstacles,
                                            layer_occupied_near)

HALL_START = (5.1, 4.9, 1.5708)  # living_door, facing the hallway's door
DOORWAY = (4.45, 7.20)  # hallway_bathroom (flat.doors.yaml), 0.80 m wide
DOOR_BLOCK = 0.25  # [m] radius: 0.15 m left either side of the chair's 0.62 m
TOLD = "The way is blocked near bathroom door: the chair waits until it is free."


class BlockedAtTheStart(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.s = Rider("test_navigation_blocked_start")
        cls.d = Drives()
        cls.add = rospy.ServiceProxy("/sim/add_moving_obstacle", AddMovingObstacle)
        cls.layer = None
        rospy.Subscriber("/obstacles", OccupancyGrid, lambda m: setattr(cls, "layer", m))

    def doorway_in_layer(self):
        """Whether /obstacles has anything within 0.4 m of the doorway (None: no layer yet)."""
        return layer_occupied_near(self.layer, DOORWAY, 0.4)
        info, r = grid.info, 0.4
        for dy in range(-8, 9):
            for dx in range(-8, 9):
                x, y = DOORWAY[0] + dx * r / 8, DOORWAY[1] + dy * r / 8
                i = int((x - info.origin.position.x) / info.resolution)
                j = int((y - info.origin.position.y) / info.resolution)
                if 0 <= i < info.width and 0 <= j < info.height and grid.data[j * info.width + i] >= 50:
                    return True
        return False

    def test_1_a_way_blocked_at_the_start_is_waited_for_and_driven_once_free(self):
        s, d = self.s, self.d
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(d.wait_servers(), "the navigator's actions are not up")
        self.assertTrue(s.teleport(*HALL_START).success)
        s.sim_sleep(1.0)  # the scans taken before the teleport are through the localizer
        self.assertTrue(s.initialize(*HALL_START), "not localized: " + s.describe())
        answer = self.add(DOORWAY[0], DOORWAY[1], DOOR_BLOCK, 0.0, 0.0, 0.0, 0.0)
        self.assertTrue(answer.success, answer.message)
        self.assertTrue(s.wait(self.doorway_in_layer, 30.0),
                        "the live layer never showed the doorway blocked")
        t0 = s.mark()
        drive = d.go(place="toilet")
        self.assertTrue(s.wait(lambda: d.was_in(NavigatorState.BLOCKED, t0.time), 30.0),
                        "not blocked: " + drive.describe() + "; " + s.describe(t0))
        self.assertTrue(s.wait(lambda: s.announced(TOLD, t0), 10.0),
                        "the rider was not told: " + s.describe(t0))
        s.sim_sleep(6.0)  # longer than replan_period: asked again, still blocked
        self.assertFalse(drive.done(), "refused at once: " + drive.describe())
        self.assertLess(s.travelled(t0), 0.05, "the chair moved towards a blocked doorway")
        t_clear = rospy.get_time()
        self.assertTrue(clear_obstacles().success)
        self.assertTrue(drive.wait(90.0), "the drive did not end: " + drive.describe())
        check_arrived(self, s, drive, "toilet", t0)
        rospy.loginfo("navigation: blocked at the start, told '%s'; free again: arrived %.1f s "
                      "(sim) later", TOLD, rospy.get_time() - t_clear)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "navigation_blocked_start", BlockedAtTheStart, sys.argv)
