#!/usr/bin/env python3
"""The display's one parameter loader refuses what it cannot use, before it opens a window: an
unknown key (naming it and the known ones), a renamed key (naming the new name), a missing
places file, an invalid value. Each refusal ends `rosrun wheelchair_display display` with exit
code 1 and the reason; no X server is needed for that."""
import os
import subprocess
import sys
import unittest

import rospkg
import rostest

PLACES = os.path.join(rospkg.RosPack().get_path("wheelchair_display"), "test", "places.yaml")


RUNS = [0]


def run(*params):
    """rosrun's exit code and output; each run under its own name (private parameters set on
    the command line stay on the master)."""
    RUNS[0] += 1
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    done = subprocess.run(["rosrun", "wheelchair_display", "display",
                           f"__name:=display_params_{RUNS[0]}", *params],
                          capture_output=True, text=True, timeout=60, env=env)
    return done.returncode, done.stdout + done.stderr


class DisplayParameters(unittest.TestCase):
    def test_an_unknown_key_is_refused_naming_it_and_the_known_keys(self):
        code, out = run(f"_places_file:={PLACES}", "_dwel_time:=2.0")
        self.assertEqual(code, 1, out)
        self.assertIn("unknown parameter 'dwel_time'", out)
        self.assertIn("dwell_time", out)

    def test_a_renamed_key_names_its_new_name(self):
        code, out = run(f"_places_file:={PLACES}", "_chair_params:=/tmp/chair.yaml")
        self.assertEqual(code, 1, out)
        self.assertIn("chair_file", out)

    def test_the_places_file_is_required(self):
        code, out = run("_theme:=light")
        self.assertEqual(code, 1, out)
        self.assertIn("places_file", out)

    def test_invalid_values_are_refused(self):
        for param, word in (("_theme:=blue", "theme"), ("_dwell_time:=0.1", "dwell_time"),
                            ("_speech_volume:=300", "speech_volume")):
            code, out = run(f"_places_file:={PLACES}", param)
            self.assertEqual(code, 1, out)
            self.assertIn(word, out)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_display", "display_parameters", DisplayParameters, sys.argv)
