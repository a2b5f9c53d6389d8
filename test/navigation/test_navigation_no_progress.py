#!/usr/bin/env python3
"""The no-progress timeout, with the whole chair in the simulator loop (issue 22): a drive
that does not get `progress_distance` closer to the goal within `no_progress_timeout` ends with
NO_PROGRESS, the rider's sentence, a controlled stop and exactly one result. The launch file
asks for 3 m of progress within 4 s, which the chair (0.6 m/s at most) cannot make, so the
ordinary drive living_centre -> kitchen_door must end that way after about 4 s of driving."""
import sys
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from wheelchair_msgs.msg import NavigateResult, NavigatorState

from wheelchair_test.harness import Rider
from wheelchair_test.harness.drives import Drives

START = (3.0, 2.2, 0.0)  # living_centre
TIMEOUT = 4.0  # [s] navigator/no_progress_timeout in the launch file


class NoProgress(unittest.TestCase):
    def test_a_drive_without_progress_ends_with_its_reason_and_one_result(self):
        s, d = Rider("test_navigation_no_progress"), Drives()
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(d.wait_servers(), "the navigator's actions are not up")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        t0 = s.mark()
        drive = d.go(place="kitchen_door")
        self.assertTrue(drive.wait(90.0), "the drive did not end: " + drive.describe())
        self.assertEqual(drive.status(), GoalStatus.ABORTED, drive.describe())
        result = drive.result()
        self.assertEqual(result.reason, NavigateResult.NO_PROGRESS, drive.describe())
        self.assertEqual(result.sentence, "The chair was not getting any closer, so it stopped.")
        self.assertIn("no progress for", result.detail)
        with d.lock:
            states = [(t, m.state) for t, m in d.states if t >= t0.time]
        driving = [t for t, state in states if state == NavigatorState.DRIVING]
        stopping = [t for t, state in states if state == NavigatorState.STOPPING]
        self.assertTrue(driving and stopping, drive.describe())
        # Ended once the timeout had passed while driving, not before and not much after.
        self.assertGreaterEqual(stopping[0] - driving[0], TIMEOUT - 0.2, drive.describe())
        self.assertLess(stopping[0] - driving[0], TIMEOUT + 1.5, drive.describe())
        self.assertTrue(s.wait(s.at_rest, 20.0), "still moving: " + s.describe(t0))
        s.sim_sleep(1.0)
        self.assertEqual(len(drive.result_messages()), 1, drive.result_messages())
        self.assertFalse(s.collided)
        rospy.loginfo("navigation: no progress: stopped %.1f s (sim) after driving began, %.2f m "
                      "driven; %s", stopping[0] - driving[0], s.travelled(t0), result.detail)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "navigation_no_progress", NoProgress, sys.argv)
