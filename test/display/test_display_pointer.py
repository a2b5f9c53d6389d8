#!/usr/bin/env python3
"""Pointer and dwell selection, as a head-mouse or eye-tracker rider does it, with the real
display, simulator and chair: a click opens the kitchen and chooses Kitchen door (the route
check answers "... m away"); then, with the pointer only resting (dwelling) and never clicking,
the rider goes back to all rooms, opens the living room, chooses Living door and confirms it on
the Go button (resting on bare floor chooses nothing: a spot takes a click); the ring fills meanwhile, nothing is chosen before the dwell time, and the chair
drives there in the simulator (judged by its truth)."""
import os
import sys
import time
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from display_harness import THEMES, Display, colour_mask  # noqa: E402
from display_world import (REMAPS, START, back_plate, go_button, place_pose, place_xy,  # noqa
                           room_point, test_output)
from wheelchair_test.harness import Rider as Scenario  # noqa: E402
from wheelchair_test.harness.rider import READY_SERVICES  # noqa: E402

DWELL = 1.5  # the display's default dwell time [s]


class DisplayPointer(unittest.TestCase):
    def setUp(self):
        self.s = Scenario("test_display_pointer")
        self.out, places_copy = test_output("display_pointer")
        self.d = Display("display", (1024, 768), places_copy, {"theme": "dark"}, REMAPS, self.out)

    def tearDown(self):
        self.d.stop()

    def dwell_until(self, x, y, predicate, what, limit=4 * DWELL):
        """Rests the pointer on (x, y) until predicate(status); returns the seconds it took."""
        d = self.d
        start = time.monotonic()
        while time.monotonic() - start < limit:
            d.dwell(x, y, 0.2)
            if predicate(d.status):
                return time.monotonic() - start
        self.fail(f"dwelling on {what} did nothing: status '{d.status}'")

    def test_click_one_place_then_dwell_on_another_and_drive_there(self):
        s, d = self.s, self.d
        self.assertTrue(d.wait_up(60.0), f"the display did not start: see {self.out}")
        self.assertEqual(s.wait_ready(services=READY_SERVICES + ("/route_check/make_plan",)), "")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        self.assertTrue(d.wait_status(lambda t: t == "Choose where to go."), d.status)

        # A click: the kitchen opens, Kitchen door is chosen and its route checked.
        d.click(*d.view.to_screen(*room_point("kitchen")))
        time.sleep(0.8)
        d.click(*d.view.to_screen(*place_xy("kitchen_door")))
        self.assertTrue(d.wait_status(lambda t: t.startswith("Kitchen door is"), 60.0), d.status)

        # Dwelling only: back to every room, the living room, Living door, Go.
        self.dwell_until(*back_plate(d.view), lambda t: t == "Choose where to go.", "All rooms")
        time.sleep(0.5)
        x, y = d.view.to_screen(*room_point("living_room"))
        d.move(x + 40, y)  # leave the spot the last choice was made at
        # The room opens after the dwell time (the status stays; the view zooms in).
        scale_before = d.view.scale
        start = time.monotonic()
        while d.view.scale == scale_before and time.monotonic() - start < 4 * DWELL:
            d.dwell(x, y, 0.1)
        took = time.monotonic() - start
        self.assertGreater(d.view.scale, scale_before, "the living room did not open")
        self.assertGreater(took, 0.8 * DWELL, f"opened after {took:.2f} s, before the dwell time")
        time.sleep(0.5)  # the zoomed view is published
        u, v = d.view.to_screen(*place_xy("living_door"))
        d.screenshot(os.path.join(self.out, "living_room.png"))
        rospy.loginfo("display pointer: living_door at (%.0f, %.0f) px", u, v)
        took = self.dwell_until(u, v, lambda t: t.startswith("Checking") or "Living door is" in t,
                                "Living door")
        self.assertTrue(d.wait_status(lambda t: t.startswith("Living door is"), 60.0), d.status)

        # On Go: halfway through the dwell the ring is half full and nothing is sent yet.
        gx, gy, gw, gh = go_button(d.view, 768)
        since = s.mark()
        d.move(gx + gw * 0.3, gy + gh / 2)
        d.dwell(gx + gw * 0.3, gy + gh / 2, 0.6 * DWELL, jitter=2)
        image = d.screenshot(os.path.join(self.out, "dwell_ring_on_go.png"), settle=0.0)
        self.assertTrue(d.status.startswith("Living door is"), "chosen before the dwell time")
        ring = colour_mask(image[int(gy - 60):int(gy + gh + 60), int(gx):int(gx + gw * 0.6)],
                           THEMES["dark"]["highlight_background"], tolerance=30)
        self.assertGreater(ring.sum(), 100, "no dwell ring at the pointer")
        self.dwell_until(gx + gw * 0.3, gy + gh / 2, lambda t: t.startswith("Driving to Living door"),
                         "Go")

        # The chair drives there (the simulator's truth) and the display says it arrived.
        self.assertTrue(s.wait(lambda: s.controller_says("goal_reached", since) or
                               s.controller_says("aborted", since), 120.0),
                        "the drive did not end: " + s.describe(since))
        self.assertTrue(s.wait(s.at_rest, 20.0))
        distance, heading = s.error_to(*place_pose("living_door"))
        self.assertLess(distance, 0.15, s.describe(since))
        self.assertLess(heading, 0.2, s.describe(since))
        self.assertTrue(d.wait_status(lambda t: t == "Arrived at Living door.", 20.0), d.status)
        d.screenshot(os.path.join(self.out, "arrived.png"))
        self.assertFalse(s.collided)
        rospy.loginfo("display pointer: arrived %.3f m, %.3f rad off Living door", distance, heading)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "display_pointer", DisplayPointer, sys.argv)
