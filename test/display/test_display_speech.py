#!/usr/bin/env python3
"""Every announcement of the display is spoken: the real display (no simulator: a static pose
and a small map) writes each announcement with espeak-ng to a WAV file (~speech_wav_dir) and
says on ~said what it announced: its status sentences, and with auditory scanning each
highlighted room. Each WAV must be non-silent and last about as long as its sentence takes at
the set rate."""
import glob
import os
import sys
import tempfile
import time
import unittest
import wave

import numpy as np
import rospy
import rostest
from nav_msgs.msg import OccupancyGrid

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from display_harness import Display  # noqa: E402
from display_world import REMAPS, SAFETY_TOPIC  # noqa: E402
from display_world import WORLDS  # noqa: E402
from wheelchair_msgs.msg import HmiState, SafetyStatus  # noqa: E402

RATE = 150  # words per minute


def wav_measures(path):
    """(duration [s], RMS, share of 20 ms windows that carry sound) of a 16-bit mono WAV."""
    with wave.open(path) as w:
        rate, frames = w.getframerate(), w.readframes(w.getnframes())
    x = np.frombuffer(frames, dtype=np.int16).astype(float)
    window = int(0.02 * rate)
    blocks = x[: len(x) // window * window].reshape(-1, window)
    loud = np.sqrt((blocks ** 2).mean(axis=1)) > 300
    return len(x) / rate, float(np.sqrt((x ** 2).mean())), float(loud.mean())


class DisplaySpeech(unittest.TestCase):
    def test_every_announcement_becomes_audible_speech_of_the_right_length(self):
        rospy.init_node("test_display_speech")
        wav_dir = tempfile.mkdtemp(prefix="display_speech_")
        map_pub = rospy.Publisher("/map", OccupancyGrid, queue_size=1, latch=True)
        hmi = rospy.Publisher("/hmi/state", HmiState, queue_size=1, latch=True)
        safety = rospy.Publisher(SAFETY_TOPIC, SafetyStatus, queue_size=1, latch=True)
        d = Display("display", (1024, 768), f"{WORLDS}/flat.places.yaml",
                    {"speech_wav_dir": wav_dir, "speak_highlight": "true", "speech_rate": RATE},
                    REMAPS)
        try:
            self.assertTrue(d.wait_up(60.0), "the display did not start")
            grid = OccupancyGrid()
            grid.header.frame_id = "map"
            grid.info.resolution, grid.info.width, grid.info.height = 0.05, 200, 240
            grid.info.origin.orientation.w = 1.0
            grid.data = [0] * (200 * 240)
            map_pub.publish(grid)
            self.assertTrue(d.wait_status(lambda t: t == "Choose where to go.", 20.0), d.status)
            for k in (0, 1):
                msg = HmiState(state=HmiState.SCANNING_ROOMS, items=["living_room", "kitchen"],
                               highlighted=k, time_left=2.0, step_time=2.0)
                hmi.publish(msg)
                time.sleep(1.5)
            safety.publish(SafetyStatus(reason=SafetyStatus.OBSTACLE, stop=True,
                                        sentence="Stopped: something is in the way."))
            self.assertTrue(d.wait_status(lambda t: t.startswith("Stopped"), 10.0), d.status)
            time.sleep(3.0)  # the last file is written
        finally:
            d.stop()
        # What was spoken: the files, in order (~said may miss the first one, said before this
        # test's subscription reached the new node).
        expected = ["Waiting for the map.", "Choose where to go.", "Living room?", "Kitchen?",
                    "Stopped: something is in the way."]
        texts = sorted(glob.glob(os.path.join(wav_dir, "*.txt")))
        spoken = [open(t).read().strip() for t in texts]
        self.assertEqual([t for t in spoken if t != "I don't know where the chair is yet."],
                         expected, f"spoken: {spoken}")
        self.assertEqual(d.said, spoken[len(spoken) - len(d.said):], "~said differs from the WAVs")
        for txt in texts:
            text = open(txt).read().strip()
            duration, rms, voiced = wav_measures(txt[:-4] + ".wav")
            words = len(text.split())
            estimate = words * 60.0 / RATE
            rospy.loginfo("display speech: '%s' %.2f s (estimate %.2f s), RMS %.0f, voiced %.0f %%",
                          text, duration, estimate, rms, 100 * voiced)
            self.assertGreater(rms, 500, f"'{text}' is (almost) silent")
            self.assertGreater(voiced, 0.3, f"'{text}' is mostly silence")
            self.assertGreater(duration, 0.5 * estimate, f"'{text}' too short: {duration:.2f} s")
            self.assertLess(duration, 2.0 * estimate + 0.6, f"'{text}' too long: {duration:.2f} s")


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "display_speech", DisplaySpeech, sys.argv)
