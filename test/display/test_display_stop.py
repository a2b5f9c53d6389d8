#!/usr/bin/env python3
"""A stop is always one action away: with the real display, simulator and chair, a drive the
HMI started (go_to_place) is stopped (1) by the pointer merely entering the full-height STOP
area, without a click, and (2) by one press of the switch. Each time the chair comes to rest in
the simulator and the display says why it stopped."""
import os
import sys
import time
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from display_harness import Display  # noqa: E402
from display_world import REMAPS, START, test_output  # noqa: E402
from wheelchair_test.harness import Rider as Scenario  # noqa: E402


class DisplayStop(unittest.TestCase):
    def setUp(self):
        self.s = Scenario("test_display_stop")
        self.out, places_copy = test_output("display_stop")
        self.d = Display("display", (1024, 768), places_copy, {}, REMAPS, self.out)

    def tearDown(self):
        self.d.stop()

    def drive(self, name):
        s, d = self.s, self.d
        since = s.mark()
        accepted, message = s.go_to_place(name)
        self.assertTrue(accepted, message)
        # The goal came from the HMI; the display names it by its place.
        self.assertTrue(d.wait_status(lambda t: t.startswith("Driving to Kitchen door"), 30.0),
                        d.status)
        self.assertTrue(s.wait(lambda: s.travelled(since) > 0.3, 60.0), s.describe(since))
        return since

    def stopped(self, since, how):
        s, d = self.s, self.d
        t0 = rospy.get_time()
        self.assertTrue(s.wait(s.at_rest, 20.0), f"{how}: still moving: " + s.describe(since))
        self.assertTrue(d.wait_status(lambda t: t == "Stopped: you pressed stop.", 10.0),
                        f"{how}: status '{d.status}'")
        rospy.loginfo("display stop (%s): at rest %.2f s (sim) after the action", how,
                      rospy.get_time() - t0)
        d.screenshot(os.path.join(self.out, f"stopped_{how}.png"))

    def test_the_stop_area_and_the_switch_each_stop_the_chair(self):
        s, d = self.s, self.d
        self.assertTrue(d.wait_up(60.0), f"the display did not start: see {self.out}")
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())

        since = self.drive("kitchen_door")
        d.move(700, 400)  # over the map: nothing happens
        time.sleep(0.5)
        self.assertTrue(d.status.startswith("Driving"), d.status)
        d.move(1024 - 60, 300)  # into the STOP area: no click
        self.stopped(since, "hover")

        d.move(500, 400)
        since = self.drive("kitchen_door")
        s.press()
        self.stopped(since, "switch")
        self.assertFalse(s.collided)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "display_stop", DisplayStop, sys.argv)
