"""What the reverse tests watch besides the Rider: the chair's true forward speed (negative
backing up) from /sim/ground_truth."""
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
