"""What the reverse tests watch besides the Rider: the chair's true forward speed (negative
backing up) from /sim/ground_truth."""
import math
import threading

import rospy
from nav_msgs.msg import Odometry


class ReverseWatch:
    def __init__(self):
        self.lock = threading.Lock()
        self.speeds = []  # (t, v)
        rospy.Subscriber("/sim/ground_truth", Odometry, self._on_truth, queue_size=50)

    def _on_truth(self, msg):
        with self.lock:
            self.speeds.append((msg.header.stamp.to_sec(), msg.twist.twist.linear.x))

    def reversed_distance(self, since):
        """Metres the chair's axle moved backwards since sim time `since` (truth)."""
        with self.lock:
            s = [(t, v) for t, v in self.speeds if t >= since]
        return sum(-v * (t1 - t0) for (t0, v), (t1, _) in zip(s, s[1:]) if v < 0.0)

    def slowest(self, since):
        with self.lock:
            return min((v for t, v in self.speeds if t >= since), default=0.0)


def drive_and_check_arrival(test, s, goal, limit=220.0):
    """Sends `goal` from the Rider `s` and asserts what every reverse drive must end in: the
    controller's goal_reached, the chair at rest within 10 cm / 10 deg of the goal by the truth,
    no contact. Returns (since, what, distance, heading): the mark before the goal, the drive's
    description and the true end pose's error [m, rad]."""
    since = s.mark()
    s.send_goal(*goal)
    done = s.wait(lambda: s.controller_says("goal_reached", since) or
                  s.controller_says("aborted", since) or s.collided or
                  s.announced("Cannot go there", since), limit)
    what = s.describe(since)
    test.assertTrue(done and s.controller_says("goal_reached", since), what)
    test.assertTrue(s.wait(s.at_rest, 20.0))
    distance, heading = s.error_to(*goal)
    test.assertLess(distance, 0.10, what)
    test.assertLess(heading, math.radians(10), what)
    test.assertFalse(s.collided, "collision: " + what)
    return since, what, distance, heading
