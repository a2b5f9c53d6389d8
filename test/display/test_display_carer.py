#!/usr/bin/env python3
"""The carer's tools, with the real display, simulator and chair. They stay closed for what a
rider can do by accident (a pointer resting on the Carer button, a short click, the switch) and
open after holding the button pressed for 3 s. Then the carer sets the chair's position by
pressing where it stands and dragging the way it faces (-> /initialpose, and the localizer
localizes there), saves the current pose as a named place into the places file (read back with
the HMI's own reader's format), deletes it again, and switches to the light theme."""
import math
import os
import sys
import time
import unittest

import numpy as np
import rospy
import rostest
import yaml
from geometry_msgs.msg import PoseWithCovarianceStamped

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from display_harness import THEMES, Display, colour_mask  # noqa: E402
from display_world import REMAPS, room_point, test_output  # noqa: E402
from wheelchair_test.harness import Rider as Scenario  # noqa: E402
from wheelchair_test.harness.rider import yaw_of  # noqa: E402

W, H = 1024, 768


class DisplayCarer(unittest.TestCase):
    def setUp(self):
        self.s = Scenario("test_display_carer")
        self.out, self.places_file = test_output("display_carer")
        self.initial_poses = []
        self.sub = rospy.Subscriber("/initialpose", PoseWithCovarianceStamped,
                                    self.initial_poses.append)
        self.d = Display("display", (W, H), self.places_file, {"theme": "dark"}, REMAPS, self.out)

    def tearDown(self):
        self.d.stop()

    def carer_button(self):
        x0, y0, w, h = self.d.view.map_region
        prompt_y, prompt_h = y0 + h, H - (y0 + h)
        pad = max(8, round(0.012 * H))
        return pad + prompt_h / 4, prompt_y + prompt_h / 2

    def tools_open(self):
        """The tools' bordered controls in the left column (the chair's HMI, scanning, puts its
        list of rooms there too, without borders)."""
        time.sleep(0.5)
        return self.d.view.map_region[0] > 0 and len(self.controls("tools_open")) >= 3

    def hold_carer(self, seconds):
        d = self.d
        d.move(*self.carer_button())
        d.xdotool("mousedown", 1)
        time.sleep(seconds)
        d.xdotool("mouseup", 1)

    def controls(self, name):
        """The bordered controls of the tools' column, top to bottom, as (x, y, w, h)."""
        d = self.d
        image = d.screenshot(os.path.join(self.out, f"{name}.png"))
        x0, y0, w, h = d.view.map_region
        column = image[y0:y0 + h, 0:x0]
        border = colour_mask(column, (0xBF, 0xBF, 0xBF), tolerance=10)
        rows = np.nonzero(border.mean(axis=1) > 0.6)[0]
        lines = []
        for r in rows:
            if lines and r <= lines[-1][1] + 1:
                lines[-1][1] = r
            else:
                lines.append([r, r])
        rects = []
        for top, bottom in zip(lines[0::2], lines[1::2]):
            rects.append((4, y0 + top[0], x0 - 8, bottom[1] - top[0]))
        return rects

    def click_control(self, rect):
        x, y, w, h = rect
        self.d.click(x + w / 2, y + h / 2)
        time.sleep(0.5)

    def test_tools_open_only_on_a_long_press_and_do_their_work(self):
        s, d = self.s, self.d
        self.assertTrue(d.wait_up(60.0), f"the display did not start: see {self.out}")
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(d.wait_status(lambda t: t == "I don't know where the chair is yet."))

        # What a rider may do by accident opens nothing.
        d.dwell(*self.carer_button(), 5.0)
        self.assertFalse(self.tools_open(), "a resting pointer opened the carer's tools")
        d.click(*self.carer_button())
        self.assertFalse(self.tools_open(), "a click opened the carer's tools")
        s.press()
        self.assertFalse(self.tools_open(), "the switch opened the carer's tools")
        self.hold_carer(1.0)
        self.assertFalse(self.tools_open(), "a 1 s press opened the carer's tools")

        # Held for 3 s: the tools. Set position: press at the chair, drag the way it faces.
        self.hold_carer(3.5)
        self.assertTrue(self.tools_open(), "a 3.5 s press did not open the carer's tools")
        tools = self.controls("carer_tools")
        self.assertEqual(len(tools), 7, f"tools: {tools}")
        self.click_control(tools[0])
        _, tx, ty, tyaw, _, _ = s.truth
        a = d.view.to_screen(tx, ty)
        b = d.view.to_screen(tx + 1.5 * math.cos(tyaw), ty + 1.5 * math.sin(tyaw))
        d.move(*a)
        d.xdotool("mousedown", 1)
        for k in range(1, 11):
            d.move(*(a + (b - a) * k / 10))
            time.sleep(0.05)
        d.xdotool("mouseup", 1)
        self.assertTrue(s.wait(lambda: len(self.initial_poses) > 0, 10.0), "no /initialpose")
        p = self.initial_poses[-1].pose.pose
        self.assertEqual(self.initial_poses[-1].header.frame_id, "map")
        error = math.hypot(p.position.x - tx, p.position.y - ty)
        self.assertLess(error, 2.0 / d.view.scale + 0.02, f"set {error:.3f} m off the truth")
        self.assertLess(abs(math.remainder(yaw_of(p.orientation) - tyaw, 2 * math.pi)), 0.1)
        self.assertTrue(s.wait(s.localized, 40.0), s.describe())
        self.assertTrue(d.wait_status(lambda t: t == "Choose where to go.", 20.0), d.status)
        rospy.loginfo("display carer: pose set %.3f m off the truth", error)

        # Save the current pose as a named place: typed name, the room the chair is in.
        self.hold_carer(3.5)
        self.click_control(self.controls("carer_tools_again")[1])
        d.xdotool("type", "--delay", "50", "Reading spot")
        form = self.controls("carer_save_form")
        self.assertEqual(len(form), 4, f"name, room, Save, Cancel: {form}")
        self.click_control(form[2])
        with open(self.places_file) as f:
            saved = {p["name"]: p for p in yaml.safe_load(f)["places"]}
        self.assertIn("reading_spot", saved)
        self.assertEqual(saved["reading_spot"]["room"], "living_room")
        _, tx, ty, tyaw, _, _ = s.truth
        self.assertLess(math.hypot(saved["reading_spot"]["x"] - tx, saved["reading_spot"]["y"] - ty),
                        0.1)
        self.assertEqual(len(saved), 32)

        # Delete it again: open the room, choose the place, confirm. (The chair's HMI, which took
        # the switch press above as choosing a room, may still scan that room's places: its
        # states must not close the room the carer's tools opened.)
        tools = self.controls("carer_tools_saved")
        self.click_control(tools[2])
        self.assertTrue(d.click_for_view(*d.view.to_screen(*room_point("living_room"))),
                        "a click did not open the living room")
        d.click(*d.view.to_screen(saved["reading_spot"]["x"], saved["reading_spot"]["y"]))
        form = self.controls("carer_delete_form")
        self.assertEqual(len(form), 2, f"Delete, Keep it: {form}")
        self.click_control(form[0])
        with open(self.places_file) as f:
            names = [p["name"] for p in yaml.safe_load(f)["places"]]
        self.assertNotIn("reading_spot", names)
        self.assertEqual(len(names), 31)

        # The light theme, and the tools closed.
        tools = self.controls("carer_tools_deleted")
        self.click_control(tools[3])
        self.click_control(tools[6])
        image = d.screenshot(os.path.join(self.out, "light_theme.png"))
        self.assertFalse(self.tools_open())
        # The status line's background (its most common colour) is the light theme's.
        colours, counts = np.unique(image[:50, :800].reshape(-1, 3), axis=0, return_counts=True)
        self.assertEqual(tuple(colours[np.argmax(counts)]), THEMES["light"]["background"])


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "display_carer", DisplayCarer, sys.argv)
