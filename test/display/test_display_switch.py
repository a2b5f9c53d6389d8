#!/usr/bin/env python3
"""One press of the switch means one thing (wheelchair_display/switch_press.h), with the real
display, simulator and the chair's own HMI: a destination chosen with the pointer waits for its
confirmation (Go shown) while the HMI scans the rooms; a press of the switch then is the HMI's
choice of the highlighted room, not the display's confirmation as well: the chair does not
move, no drive starts, the HMI scans that room's places and the display withdraws the
pointer's choice (the switch's choice leads)."""
import os
import sys
import time
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from display_harness import Display  # noqa: E402
from display_world import REMAPS, START, place_xy, room_point, test_output  # noqa: E402
from wheelchair_test.harness import Rider as Scenario  # noqa: E402
from wheelchair_test.harness.rider import READY_SERVICES  # noqa: E402
from wheelchair_msgs.msg import HmiState, NavigatorState  # noqa: E402


class DisplaySwitch(unittest.TestCase):
    def setUp(self):
        self.s = Scenario("test_display_switch")
        self.out, places_copy = test_output("display_switch")
        self.hmi_state, self.navigator_active = None, []
        self.subs = [
            rospy.Subscriber("/hmi/state", HmiState, lambda m: setattr(self, "hmi_state", m)),
            rospy.Subscriber("/navigator/state", NavigatorState,
                             lambda m: m.active and self.navigator_active.append(m.goal_id))]
        self.d = Display("display", (1024, 768), places_copy, {}, REMAPS, self.out)

    def tearDown(self):
        for sub in self.subs:
            sub.unregister()
        self.d.stop()

    def hmi_in(self, state):
        return self.hmi_state is not None and self.hmi_state.state == state

    def test_a_press_while_the_hmi_scans_is_its_choice_and_not_a_confirmation_too(self):
        s, d = self.s, self.d
        self.assertTrue(d.wait_up(60.0), f"the display did not start: see {self.out}")
        self.assertEqual(s.wait_ready(services=READY_SERVICES + ("/route_check/make_plan",)), "")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        self.assertTrue(d.wait_status(lambda t: t == "Choose where to go.", 20.0), d.status)
        self.assertTrue(s.wait(lambda: self.hmi_in(HmiState.SCANNING_ROOMS), 30.0),
                        f"the HMI does not scan the rooms: {self.hmi_state}")

        # The pointer chooses Kitchen door; the route check answers; Go waits for the rider.
        self.assertTrue(d.click_for_view(*d.view.to_screen(*room_point("kitchen"))),
                        "a click did not open the kitchen")
        d.click(*d.view.to_screen(*place_xy("kitchen_door")))
        self.assertTrue(d.wait_status(lambda t: t.startswith("Kitchen door is"), 60.0), d.status)
        d.screenshot(os.path.join(self.out, "pointer_choice.png"))
        self.assertTrue(self.hmi_in(HmiState.SCANNING_ROOMS), f"{self.hmi_state}")

        # One press: the HMI's choice of the room it highlights.
        since = s.mark()
        rooms, lit = list(self.hmi_state.items), self.hmi_state.highlighted
        s.press()
        self.assertTrue(s.wait(lambda: self.hmi_in(HmiState.SCANNING_PLACES), 10.0),
                        f"the HMI did not take the press: {self.hmi_state}")
        # The room highlighted at the press (or the next one, had the highlight just moved on).
        self.assertIn(self.hmi_state.room, (rooms[lit], rooms[(lit + 1) % len(rooms)]))
        # The display withdrew the pointer's choice: nothing to confirm, no Go.
        self.assertTrue(d.wait_status(lambda t: t == "Choose where to go.", 10.0),
                        f"the pointer's choice still shown: '{d.status}'")
        # And did not confirm it: no drive starts, the chair stays where it is.
        time.sleep(5.0)
        self.assertEqual(self.navigator_active, [], "a drive started on the press")
        self.assertLess(s.travelled(since), 0.02, "the chair moved: " + s.describe(since))
        d.screenshot(os.path.join(self.out, "after_press.png"))
        rospy.loginfo("display switch: the press chose %s on the HMI; the display withdrew its "
                      "choice; travelled %.3f m", self.hmi_state.room, s.travelled(since))


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "display_switch", DisplaySwitch, sys.argv)
