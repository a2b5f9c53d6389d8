#!/usr/bin/env python3
"""The navigator's commands with the whole chair in the simulator loop (issue 22):
- a goal before the localizer has a pose is refused with the rider's sentence (not a tf
  error), through the navigator's actions and through the HMI, and the chair stays;
- a goal through the move_base action is driven; canceled mid-drive through the action, the
  chair comes to a controlled stop and the drive has exactly one result: canceled.
One stack for both (the refusal needs the chair before its first pose estimate)."""
import sys
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from wheelchair_msgs.msg import NavigateResult

from wheelchair_test.harness import Rider, place
from wheelchair_test.harness.drives import Drives

START = (3.0, 2.2, 0.0)  # living_centre
NOT_LOCALIZED = "I don't know where the chair is yet: set its position first."


class Commands(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.s = Rider("test_navigation_commands")
        cls.d = Drives()

    def test_1_a_goal_before_the_first_pose_estimate_is_refused_with_the_riders_sentence(self):
        s, d = self.s, self.d
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(d.wait_servers(), "the navigator's actions are not up")
        self.assertFalse(s.localized(), "localized before any pose estimate")
        t0 = s.mark()
        named = d.go(place="kitchen_door")
        self.assertTrue(named.wait(30.0), "no answer: " + named.describe())
        self.assertEqual(named.status(), GoalStatus.REJECTED, named.describe())
        self.assertEqual(named.result().reason, NavigateResult.NOT_LOCALIZED, named.describe())
        self.assertEqual(named.result().sentence, NOT_LOCALIZED)
        pose = d.go_move_base(*place("kitchen_door"))
        self.assertTrue(pose.wait(30.0), "no answer: " + pose.describe())
        self.assertEqual(pose.status(), GoalStatus.REJECTED)
        self.assertEqual(pose.client.get_goal_status_text(), NOT_LOCALIZED)
        # The rider choosing a place hears the same sentence, not a developer log.
        accepted, message = s.go_to_place("kitchen_door")
        self.assertTrue(accepted, message)
        self.assertTrue(s.wait(lambda: s.announced(NOT_LOCALIZED, t0), 20.0),
                        "the rider was not told: " + s.describe(t0))
        for _, text in s.received("announcements", t0):
            self.assertNotIn("base_link", text)
            self.assertNotIn("tf", text.split())
        s.sim_sleep(1.0)
        self.assertEqual(len(named.result_messages()), 1, named.result_messages())
        self.assertEqual(len(pose.result_messages()), 1, pose.result_messages())
        with s.lock:
            paths = [p for p in s.plans if p.poses]
        self.assertEqual(paths, [], "a route was handed to the controller")
        self.assertLess(s.travelled(t0), 0.01, "the chair moved: " + s.describe(t0))

    def test_2_a_drive_canceled_through_the_action_stops_with_one_result(self):
        s, d = self.s, self.d
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        t0 = s.mark()
        drive = d.go_move_base(*place("kitchen_door"))
        self.assertTrue(s.wait(lambda: s.travelled(t0) > 0.8, 60.0),
                        "the chair did not start: " + drive.describe() + "; " + s.describe(t0))
        self.assertEqual(drive.status(), GoalStatus.ACTIVE, drive.describe())
        t_cancel = rospy.get_time()
        drive.cancel()
        self.assertTrue(drive.wait(30.0), "the drive did not end: " + drive.describe())
        self.assertEqual(drive.status(), GoalStatus.PREEMPTED, drive.describe())
        self.assertEqual(drive.client.get_goal_status_text(), "Stopped, as you asked.")
        self.assertTrue(s.wait(s.at_rest, 20.0), "still moving: " + s.describe(t0))
        t_rest = rospy.get_time()
        stopped_at = s.truth[1:3]
        s.sim_sleep(2.0)
        moved = ((s.truth[1] - stopped_at[0]) ** 2 + (s.truth[2] - stopped_at[1]) ** 2) ** 0.5
        self.assertLess(moved, 0.01, "the chair moved on after the stop")
        self.assertEqual(len(drive.result_messages()), 1, drive.result_messages())
        self.assertGreater(s.error_to(*place("kitchen_door"))[0], 0.5, "it drove on")
        self.assertFalse(s.collided)
        rospy.loginfo("navigation: canceled after %.2f m, at rest %.2f s (sim) after the cancel",
                      s.travelled(t0), t_rest - t_cancel)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "navigation_commands", Commands, sys.argv)
