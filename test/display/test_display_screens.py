#!/usr/bin/env python3
"""The rider's display in each state, at 1024x768 (dark theme) and 1920x1080 (light theme), with
the real display node, simulator and chair: before localization, scanning a room, scanning a
place (the chair's own HMI scanning, its /hmi/state, the rider's presses on /switch), the HMI's
confirmation lapsing, confirming (a place
chosen with the pointer, its route checked), driving, stopped by the rider, stopped by the
supervisor (a typed SafetyStatus from the test publisher), refused (a spot the chair cannot
stand on: the chair's own route check refuses it). Each screenshot is measured: the map region shows the map, the chair's footprint is
where the simulator's truth puts it, the highlighted item is marked, the status line's letters
are at least as tall as at 48 px and its contrast is at least 7:1."""
import math
import os
import sys
import time
import unittest

import numpy as np
import rospy
import rostest
import tf2_ros

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from display_harness import (THEMES, Display, colour_mask, footprint_offset, load_map,  # noqa
                             map_shows_map, status_band, status_text_measures)
from display_world import (FOOTPRINT, REMAPS, SAFETY_TOPIC, START, go_button, place_xy,  # noqa
                           places, room_box, room_point, test_output)
from wheelchair_test.harness import Rider as Scenario  # noqa: E402
from wheelchair_test.harness.rider import READY_SERVICES  # noqa: E402
from display_world import WORLDS  # noqa: E402
from wheelchair_msgs.msg import HmiState, SafetyStatus  # noqa: E402


class DisplayScreens(unittest.TestCase):
    def setUp(self):
        self.s = Scenario("test_display_screens")
        # WHEELCHAIR_DISPLAY_SHOTS: where the demo wants the screenshots.
        self.shots, places_copy = test_output("display_shots",
                                              os.environ.get("WHEELCHAIR_DISPLAY_SHOTS"))
        self.grid = load_map(f"{WORLDS}/flat.yaml")
        self.tf = tf2_ros.Buffer()
        self.tf_listener = tf2_ros.TransformListener(self.tf)
        self.hmi_state, self.hmi_count = None, 0
        self.hmi = rospy.Subscriber("/hmi/state", HmiState, self._on_hmi)
        self.safety = rospy.Publisher(SAFETY_TOPIC, SafetyStatus, queue_size=1, latch=True)
        self.displays = [
            Display("display_small", (1024, 768), places_copy, {"theme": "dark"}, REMAPS),
            Display("display_large", (1920, 1080), places_copy, {"theme": "light"}, REMAPS)]

    def tearDown(self):
        self.hmi.unregister()
        for d in self.displays:
            d.stop()

    def _on_hmi(self, msg):
        self.hmi_state = msg
        self.hmi_count += 1

    # ---- helpers ------------------------------------------------------------------------------
    def shoot(self, state, chair_shown=True):
        """Screenshots of both displays in `state`, each checked: map, footprint, status line."""
        images = []
        for d in self.displays:
            theme = THEMES["dark" if d.size[0] == 1024 else "light"]
            truth_before, truth_stamp = self.s.truth[1:4], self.s.truth[0]
            taken = time.monotonic()
            image = d.screenshot(os.path.join(self.shots, f"{state}_{d.size[0]}x{d.size[1]}.png"))
            truth_after = self.s.truth[1:4]
            where = f"{state} at {d.size}"
            # The frame on the screen was drawn with one of the views published meanwhile.
            view, shown = max(((v, map_shows_map(image, v, self.grid, theme))
                               for v in d.views_since(taken - 0.5)),
                              key=lambda c: c[1]["occupied"]["wall"] + c[1]["free"]["floor"])
            walls, floor = shown["occupied"]["wall"], shown["free"]["floor"]
            self.assertGreater(walls, 0.8, f"{where}: walls shown as walls {shown}")
            self.assertLess(shown["occupied"]["floor"], 0.03, f"{where}: walls shown as floor {shown}")
            self.assertGreater(floor, 0.5, f"{where}: floor shown as floor {shown}")
            self.assertLess(shown["free"]["wall"], 0.03, f"{where}: floor shown as walls {shown}")
            u, v = view.to_screen(*truth_before[:2])
            x0, y0, w, h = view.map_region
            in_view = x0 + 20 < u < x0 + w - 20 and y0 + 20 < v < y0 + h - 20
            # The whole footprint on the map (the map region clips a chair at its edge, which
            # moves the drawn centre): otherwise only its being in view is checked.
            c, s_ = math.cos(truth_before[2]), math.sin(truth_before[2])
            whole = all(x0 + 2 < cu < x0 + w - 2 and y0 + 2 < cv < y0 + h - 2 for cu, cv in (
                view.to_screen(truth_before[0] + c * px - s_ * py, truth_before[1] + s_ * px + c * py)
                for px, py in FOOTPRINT))
            if self.localized and in_view and not whole:
                rospy.loginfo("display %s: the footprint reaches the map's edge: not measured", where)
            if self.localized and in_view and whole:
                # The pose of the frame shown may be a little older than the shot on a loaded
                # machine (tf, the frame's tick): the motion from 0.25 s before it is allowed.
                with self.s.lock:
                    recent = [(x, y) for t, x, y in self.s.truth_path if t >= truth_stamp - 0.25]
                moved = max([math.hypot(truth_after[0] - x, truth_after[1] - y) for x, y in recent] +
                            [math.hypot(truth_after[0] - truth_before[0],
                                        truth_after[1] - truth_before[1])])
                pose = [(a + b) / 2 for a, b in zip(truth_before, truth_after)]
                offset, share = footprint_offset(image, view, pose, FOOTPRINT, theme)
                # A few pixels: the localizer's estimate against the truth, and motion meanwhile.
                # After a drive on a loaded machine the localizer itself may be off by more than
                # 2 cm: that error (the estimate the display draws, from tf, against the truth)
                # is added, and the footprint must then be where the estimate puts it (at rest:
                # while driving the estimate read now is not the one of the frame).
                estimate = self.estimate() if moved < 0.01 else None  # at rest only
                error = math.hypot(estimate[0] - pose[0], estimate[1] - pose[1]) if estimate else 0.0
                limit = 3.0 + max(0.02, error) * view.scale + moved * view.scale
                self.assertLess(offset, limit, f"{where}: footprint {offset:.1f} px off the truth, "
                                f"the localizer {error * 100:.1f} cm off it")
                self.assertGreater(share, 0.6, f"{where}: footprint fill {share:.2f}")
                if estimate:
                    drawn, _ = footprint_offset(image, view, estimate, FOOTPRINT, theme)
                    self.assertLess(drawn, 3.0 + 0.02 * view.scale + moved * view.scale,
                                    f"{where}: footprint {drawn:.1f} px off the localizer's pose")
                rospy.loginfo("display %s: footprint %.1f px off the truth (limit %.1f; the "
                              "localizer %.1f cm off it), fill %.2f", where, offset, limit,
                              error * 100, share)
            band = status_band(image, view)
            cap, cap48, ratio = status_text_measures(band, d.status[0], theme)
            self.assertGreaterEqual(cap, cap48 - 1, f"{where}: status letters {cap} px < {cap48}")
            self.assertGreaterEqual(ratio, 7.0, f"{where}: status contrast {ratio:.1f}")
            rospy.loginfo("display %s: '%s' cap %d px (48 px font: %d), contrast %.1f:1, map %.2f/%.2f",
                          where, d.status, cap, cap48, ratio, walls, floor)
            if self.localized and chair_shown:
                self.assertTrue(in_view, f"{where}: the chair is not in the view")
            images.append(image)
        return images

    def estimate(self):
        """The localizer's pose (tf map -> base_link, as the display reads it), or None."""
        try:
            t = self.tf.lookup_transform("map", "base_link", rospy.Time(0), rospy.Duration(1.0))
        except (tf2_ros.LookupException, tf2_ros.ExtrapolationException,
                tf2_ros.ConnectivityException):
            return None
        q = t.transform.rotation
        yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
        return t.transform.translation.x, t.transform.translation.y, yaw

    def hmi_shows(self, state, item):
        m = self.hmi_state
        return m is not None and m.state == state and 0 <= m.highlighted < len(m.items) and \
            m.items[m.highlighted] == item

    def wait_hmi(self, state, item, timeout=90.0):
        self.assertTrue(self.s.wait(lambda: self.hmi_shows(state, item), timeout),
                        f"the HMI never highlighted {item}: {self.hmi_state}")

    def shoot_highlight(self, name, state, item, chair_shown=True, tries=3):
        """Photographs both displays while the chair's HMI highlights `item` (in `state`); when
        the highlight moved on before both were taken, again at the item's next turn."""
        for _ in range(tries):
            self.wait_hmi(state, item)
            seen = self.hmi_count
            time.sleep(0.3)  # both displays draw it
            images = self.shoot(name, chair_shown)
            if self.hmi_count == seen:
                return images
            rospy.logwarn("display screens: the highlight moved on during %s; again", name)
            self.assertTrue(self.s.wait(lambda: not self.hmi_shows(state, item), 30.0))
        self.fail(f"{name}: the HMI's highlight of {item} moved on during every screenshot")

    def both(self, status_test, timeout=30.0):
        for d in self.displays:
            self.assertTrue(d.wait_status(status_test, timeout), f"{d.name}: status '{d.status}'")

    def click_world(self, d, x, y):
        d.click(*d.view.to_screen(x, y))

    def highlight_near(self, image, d, xy, theme, radius):
        """Highlight-coloured pixels within `radius` px of world point xy."""
        u, v = d.view.to_screen(*xy)
        crop = image[max(0, int(v - radius)):int(v + radius), max(0, int(u - radius)):int(u + radius)]
        return int(colour_mask(crop, theme["highlight_background"]).sum())

    # ---- the test ------------------------------------------------------------------------------
    def test_every_state_at_both_sizes(self):
        s = self.s
        self.localized = False
        for d in self.displays:
            self.assertTrue(d.wait_up(60.0), f"{d.name} did not start: see {d.out_dir}")
        self.assertEqual(s.wait_ready(services=READY_SERVICES + ("/route_check/make_plan",)), "")
        self.both(lambda t: t == "I don't know where the chair is yet.")
        self.shoot("not_localized")

        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        self.localized = True
        self.both(lambda t: t == "Choose where to go.")

        # Scanning a room: the kitchen's area framed (thick, flashing), its name on a filled plate.
        # The chair's HMI offers the rooms largest first, ties in the file's order.
        rooms = ["living_room", "kitchen", "study", "bathroom", "guest_room", "bedroom"]
        self.wait_hmi(HmiState.SCANNING_ROOMS, "kitchen")
        self.assertEqual(list(self.hmi_state.items), rooms)
        # How each display draws all the rooms while the HMI scans them (the pointer's clicks
        # below start from it).
        overview = {}
        for d, image in zip(self.displays,
                            self.shoot_highlight("scanning_room", HmiState.SCANNING_ROOMS, "kitchen")):
            theme = THEMES["dark" if d.size[0] == 1024 else "light"]
            overview[d.name] = d.view.values
            x0, y0, x1, y1 = room_box("kitchen")
            frame = np.zeros(image.shape[:2], dtype=bool)
            for colour in theme["highlight_frames"]:
                frame |= colour_mask(image, colour)
            edge_hits = []
            for t in np.linspace(0.1, 0.9, 9):
                for wx, wy in ((x0 + t * (x1 - x0), y0), (x0 + t * (x1 - x0), y1),
                               (x0, y0 + t * (y1 - y0)), (x1, y0 + t * (y1 - y0))):
                    u, v = d.view.to_screen(wx, wy)
                    edge_hits.append(frame[int(v) - 3:int(v) + 4, int(u) - 3:int(u) + 4].any())
            self.assertGreater(np.mean(edge_hits), 0.75, f"{d.size}: kitchen frame {edge_hits}")
            centre = ((x0 + x1) / 2, (y0 + y1) / 2)
            self.assertGreater(self.highlight_near(image, d, centre, theme, 60), 400,
                               f"{d.size}: the kitchen's plate is not highlighted")
            other = room_box("bedroom")
            self.assertEqual(self.highlight_near(image, d, ((other[0] + other[2]) / 2,
                                                            (other[1] + other[3]) / 2), theme, 30), 0)

        # Scanning a place: the rider presses on the kitchen; its places are offered in the
        # file's order; stove's plate highlighted, sink's and kitchen_door's not.
        self.wait_hmi(HmiState.SCANNING_ROOMS, "kitchen")
        s.press()
        kitchen = [p["name"] for p in places() if p["room"] == "kitchen"]
        self.wait_hmi(HmiState.SCANNING_PLACES, "sink")
        self.assertEqual(list(self.hmi_state.items), kitchen)
        for d, image in zip(self.displays, self.shoot_highlight(
                "scanning_place", HmiState.SCANNING_PLACES, "stove", chair_shown=False)):
            theme = THEMES["dark" if d.size[0] == 1024 else "light"]
            self.assertGreater(self.highlight_near(image, d, place_xy("stove"), theme,
                                                   0.3 * d.size[1]),
                               600, f"{d.size}: stove not highlighted")
            for name in ("sink", "kitchen_door"):
                self.assertEqual(self.highlight_near(image, d, place_xy(name), theme, 6), 0,
                                 f"{d.size}: {name} looks highlighted")

        # The HMI's confirmation: a press on a kitchen place; unconfirmed, it lapses back to the
        # rooms (confirm_timeout, 8 s), where the pointer chooses freely again.
        s.press()
        self.assertTrue(s.wait(lambda: self.hmi_state.state == HmiState.CONFIRMING, 10.0))
        self.assertIn(self.hmi_state.place, kitchen)
        self.assertTrue(s.wait(lambda: self.hmi_state.state == HmiState.SCANNING_ROOMS, 30.0),
                        f"the confirmation did not lapse: {self.hmi_state}")

        # Confirming: the pointer opens the kitchen and clicks kitchen_door; the route check answers.
        # Each click is made on the frame the display shows: all the rooms again once it has
        # seen the lapse, then the kitchen once it has opened it (on a loaded machine either
        # can take longer than a fixed wait).
        self.open_room("kitchen", overview)
        for d in self.displays:
            self.click_world(d, *place_xy("kitchen_door"))
        self.both(lambda t: t.startswith("Kitchen door is") and t.endswith("m away."), 60.0)
        for d, image in zip(self.displays, self.shoot("confirming")):
            theme = THEMES["dark" if d.size[0] == 1024 else "light"]
            gx, gy, gw, gh = go_button(d.view, d.size[1])
            left = image[gy + 12:gy + gh - 12, gx + 12:gx + int(0.2 * gw)]  # no text there
            self.assertGreater(colour_mask(left, theme["button_background"]).mean(), 0.9,
                               f"{d.size}: no Go button")

        # Driving: Go on the small display; the large one sees the goal and drives along.
        small = self.displays[0]
        since = s.mark()
        gx, gy, gw, gh = go_button(small.view, small.size[1])
        small.click(gx + gw / 2, gy + gh / 2)
        self.both(lambda t: t.startswith("Driving to Kitchen door"), 30.0)
        self.assertTrue(s.wait(lambda: s.travelled(since) > 0.4, 60.0), "no drive: " + s.describe(since))
        self.shoot("driving")

        # Stopped by the rider: a click on the STOP area.
        small.click(1024 - 40, 384)
        self.assertTrue(small.wait_status(lambda t: t == "Stopped: you pressed stop.", 10.0), small.status)
        self.assertTrue(s.wait(s.at_rest, 20.0), "still moving: " + s.describe(since))
        self.shoot("stopped_by_rider")

        # Stopped by the supervisor (its typed status), with its sentence.
        stop = SafetyStatus(reason=SafetyStatus.OBSTACLE, stop=True, sentence="Stopped: something is in the way.",
                            detail="obstacle 0.9 m ahead", value=0.9, limit=1.2)
        stop.header.stamp = rospy.Time.now()
        self.safety.publish(stop)
        self.both(lambda t: t == "Stopped: something is in the way.", 10.0)
        self.shoot("stopped_obstacle")
        self.safety.publish(SafetyStatus(reason=SafetyStatus.NONE, stop=False, sentence=""))

        # Refused: a free cell against the kitchen's wall, where the chair's body does not fit
        # (one the screen shows as bare floor, not under a name).
        for d in self.displays:
            self.assertTrue(d.wait_status(lambda t: not t.startswith("Stopped: something"), 10.0))
        self.open_room("kitchen", overview)
        for d in self.displays:
            theme = THEMES["dark" if d.size[0] == 1024 else "light"]
            image = d.screenshot(os.path.join(self.shots, f"room_{d.size[0]}.png"))
            self.click_world(d, *self.tight_spot(room_box("kitchen"), d, image, theme))
        self.both(lambda t: t.startswith("The chair cannot"), 60.0)
        self.shoot("refused", chair_shown=False)
        self.assertFalse(s.collided)

    def open_room(self, room, overview):
        """On each display: waits until it shows all the rooms (`overview`, its view then), and
        opens `room` with a click, waiting until it is drawn."""
        for d in self.displays:
            self.assertTrue(d.wait_view(overview[d.name]),
                            f"{d.name}: not back to all the rooms (status '{d.status}', view "
                            f"{d.view.values}, all the rooms {overview[d.name]})")
            self.assertTrue(d.click_for_view(*d.view.to_screen(*room_point(room))),
                            f"{d.name}: a click did not open {room} (status '{d.status}')")

    def tight_spot(self, box, d, image, theme):
        """A free cell in `box` 5-10 cm from the nearest wall cell, shown as bare floor."""
        g = self.grid
        r = g["resolution"]
        occ = np.argwhere(g["occupied"])
        for iy in range(int((box[1] - g["origin"][1]) / r), int((box[3] - g["origin"][1]) / r)):
            for ix in range(int((box[0] - g["origin"][0]) / r), int((box[2] - g["origin"][0]) / r)):
                if not g["free"][iy, ix]:
                    continue
                dist = np.min(np.hypot(occ[:, 0] - iy, occ[:, 1] - ix)) * r
                if not 0.05 <= dist <= 0.1:
                    continue
                x, y = g["origin"][0] + (ix + 0.5) * r, g["origin"][1] + (iy + 0.5) * r
                u, v = d.view.to_screen(x, y)
                x0, y0, w, h = d.view.map_region
                if not (x0 + 80 < u < x0 + w - 10 and y0 + 80 < v < y0 + h - 10):
                    continue  # away from the "All rooms" plate and the edges
                if any(np.hypot(*(d.view.to_screen(p["x"], p["y"]) - np.array([u, v]))) < 45
                       for p in places()):
                    continue  # a place's dot is a target around it
                around = image[int(v) - 4:int(v) + 5, int(u) - 4:int(u) + 5]
                if colour_mask(around, theme["floor"]).mean() > 0.5 and \
                        not colour_mask(around, theme["chair_fill"]).any():
                    return x, y
        self.fail(f"{d.size}: no tight spot on bare floor in the kitchen")


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "display_screens", DisplayScreens, sys.argv)
