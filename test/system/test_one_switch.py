#!/usr/bin/env python3
"""A rider with one switch chooses three places in a row. The test plays the rider: it watches
the announcements (/hmi/announce) and presses (/switch) when its room, then its place is
highlighted, then confirms; the chair drives there; then the next one. Reports presses and
scan steps per destination (group scanning promises <= 3 presses)."""
import sys
import unittest

import rospy
import rostest

from wheelchair_test.harness import Rider, RiderError, place

START = (3.0, 2.2, 0.0)  # living_centre
# Places with room to turn at the goal: the chair's rear corners sweep 0.86 m about the axle
# centre; several of flat's places are closer than that to furniture.
ROUTE = [("living_door", "living_room"), ("kitchen_door", "kitchen"),
         ("living_centre", "living_room")]


class OneSwitch(unittest.TestCase):
    def test_three_places_in_a_row(self):
        s = Rider("test_one_switch")
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        figures = []
        for name, room in ROUTE:
            since = s.mark()  # not a time: the last leg's end can carry this leg's start time
            last = s.received("controller")[-1:]
            rospy.loginfo("one switch: %s marked at %.3f s, last status %s", name, since.time,
                          "at %.3f s (%s)" % last[0] if last else "none")
            try:  # presses like the rider; (presses, scan steps) once the goal is sent
                presses, steps = s.choose_by_switch(name, room, sim_timeout=90.0)
            except RiderError as e:
                self.fail(str(e))
            self.assertLessEqual(presses, 3, name)
            self.assertTrue(s.wait(lambda: s.controller_says("goal_reached", since) or
                                   s.controller_says("aborted", since), 120.0),
                            f"{name}: the drive did not end: " + s.describe(since))
            # The end belongs to this drive: the controller drove (aligning or tracking) first.
            statuses = [text for _, text in s.received("controller", since)]
            self.assertIn(statuses[0], ("aligning", "tracking"),
                          f"{name}: not this drive's end: " + s.describe(since))
            # Judged by the simulator's truth: the controller may end with "goal not reached
            # within tolerance" a few mm / degrees off (reported to the controller's owner).
            self.assertTrue(s.wait(s.at_rest, 20.0))
            distance, heading = s.error_to(*place(name))
            self.assertLess(distance, 0.15, f"{name}: {s.describe(since)}")
            self.assertLess(heading, 0.2, f"{name}: {s.describe(since)}")
            self.assertTrue(s.wait(lambda: s.announced("Arrived", since) or
                                   s.announced("Stopped", since), 10.0), s.describe(since))
            figures.append((name, presses, steps, distance))
        self.assertFalse(s.collided)
        for name, presses, steps, distance in figures:
            rospy.loginfo("one switch: %s in %d presses, %d scan steps; stopped %.3f m off",
                          name, presses, steps, distance)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "one_switch", OneSwitch, sys.argv)
