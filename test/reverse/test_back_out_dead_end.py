#!/usr/bin/env python3
"""Issue 24, the navigator's back-up recovery, with the whole chair in the simulator loop in
`loop` (two rooms joined by a 1.2 m and a 1.0 m corridor, 8 m long). The chair drives from room
a to room b through the straight 1.2 m one; once it is 5 m in, a box is dropped 1.8 m ahead of it,
in the middle of the corridor: the 0.35 m left either side are narrower than the chair's 0.62 m
body. (Against a wall, its echoes turned the localizer's heading 0.07 rad towards that wall and
the rear guard then stopped the backing chair for the corridor's own walls.) The chair cannot turn in 1.2 m (its body's diagonal is 1.26 m), and from where it stops the way out needs
more reverse than the planner plans (5 m): the navigator backs it out 2 m along the way it came
(its rule: the trail's end has a route that the chair's pose lacks), the rider told "Backing
out of the way we came.", then the planner's route from there (the rest backwards, then the
round corridor) takes it to room b: reached, no contact, no stop for anything behind."""
import math
import sys
import unittest

import rospy
import rostest
from wheelchair_msgs.msg import NavigateResult, SafetyStatus

from wheelchair_test.harness import Rider
from wheelchair_test.harness.drives import Drives

START = (2.0, 4.5, 0.0)  # a_door (loop.places.yaml), facing the straight corridor
GOAL = (13.0, 4.5, 0.0)  # b_door, beyond it
CORRIDOR = (3.5, 11.5, 3.9, 5.1)  # the straight corridor: x from, to; y from, to
DROP_AT = 8.5  # [m] the axle's x when the box is dropped ...
AHEAD = 1.8    # [m] ... this far ahead of it
BOX = 0.25     # [m] radius, on the corridor's centre line
BEHIND = (SafetyStatus.OBSTACLE_BEHIND, SafetyStatus.REAR_SENSOR_SILENT)


class BackOut(unittest.TestCase):
    def test_a_box_ahead_in_a_dead_end_backs_the_chair_out_and_it_arrives_the_other_way(self):
        s = Rider("test_back_out_dead_end")
        d = Drives()
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(d.wait_servers(), "the navigator's actions are not up")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        t0 = s.mark()
        drive = d.go(pose=GOAL)
        self.assertTrue(s.wait(lambda: s.truth[1] >= DROP_AT or drive.done(), 120.0),
                        "never in the corridor: " + drive.describe() + "; " + s.describe(t0))
        self.assertFalse(drive.done(), drive.describe())
        _, x, y, _, _, _ = s.truth
        self.assertLess(abs(y - 4.5), 0.2, "not in the straight corridor: " + s.describe(t0))
        box = (x + AHEAD, 4.5)
        self.assertTrue(s.add_obstacle(box[0], box[1], BOX).success)
        told = "Backing out of the way we came."
        self.assertTrue(s.wait(lambda: s.announced(told, t0) or drive.done(), 200.0),
                        "never backed out: " + drive.describe() + "; " + s.describe(t0))
        self.assertFalse(drive.done(), "ended before backing out: " + drive.describe())
        backing = s.mark()
        # ~95 s of simulated time from here (2 m back, 4 m more backwards, 19 m round): at half
        # real time and under load more than 200 s of wall time (one run of six).
        self.assertTrue(drive.wait(400.0), "the drive did not end: " + drive.describe())
        what = drive.describe() + "; " + s.describe(t0)
        self.assertEqual(drive.result().reason, NavigateResult.REACHED, what)
        self.assertTrue(s.wait(s.at_rest, 20.0))
        distance, heading = s.error_to(*GOAL)
        self.assertLess(distance, 0.15, what)
        self.assertLess(heading, 0.2, what)
        self.assertFalse(s.collided, "contact: " + what)
        behind = [st for _, st in s.received("safety", backing.time)
                  if st.stop and st.reason in BEHIND]
        self.assertEqual(behind, [], "stopped for something behind: " + what)
        # It went round: through the round corridor (y 1.0 .. 2.0), never past the box.
        with s.lock:
            path = [(x, y) for t, x, y in s.truth_path if t >= t0.time]
        self.assertTrue(any(CORRIDOR[0] < px < CORRIDOR[1] and py < 2.0 for px, py in path),
                        "not through the round corridor: " + what)
        self.assertLess(max(px for px, py in path if py > 3.5 and px < CORRIDOR[1]),
                        box[0] - BOX, "past the box: " + what)
        rospy.loginfo("back_out_dead_end: box %.2f m ahead at x %.2f; reached %.3f m / %.1f deg "
                      "off, %.1f s (sim) after the drive began, %.1f s after backing out began, "
                      "%.1f m driven", AHEAD, box[0], distance, math.degrees(heading),
                      rospy.get_time() - t0.time, rospy.get_time() - backing.time,
                      s.travelled(t0))


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "back_out_dead_end", BackOut, sys.argv)
