#!/usr/bin/env python3
"""A 4000 x 4000 map served on /map by another node while the chair drives (issue 20): once it
took the chair process to 840 MB and stalled it into a "laser silent" stop. Now every consumer
refuses it at the boundary (max_map_cells, sized for the legacy PC) and keeps its last good map:
over the next DRIVE simulated seconds the chair keeps its 50 Hz control rate and drives on with
no safety stop, the refusal is logged with its reason, and its memory grows by no more than the
message's own two copies (the socket's buffer and the one deserialized message, which roscpp
makes before any callback can refuse it; no consumer copies it). Before the navigator caught
its conversion's refusal, the map aborted the whole chair process (SIGABRT)."""
import sys
import threading
import time
import unittest
import xmlrpc.client

import numpy
import rosgraph
import rospy
import rostest
from nav_msgs.msg import OccupancyGrid
from rosgraph_msgs.msg import Log
from rospy.numpy_msg import numpy_msg
from wheelchair_msgs.msg import WheelTorques

from wheelchair_test.harness import Rider

START = (3.0, 2.2, 0.0)  # living_centre, heading +x
GOAL = "kitchen_door"
SIDE = 4000  # cells: 200 m x 200 m at 5 cm, 16 MB
CHAIR_NODE = "/wheelchair"
MAP_MB = SIDE * SIDE / 2.0 ** 20
DRIVE = 8.0  # [s] simulated, watched after the map
CONTROL_PERIOD = 0.02  # [s] the controller's 50 Hz


def big_map():
    msg = numpy_msg(OccupancyGrid)()
    msg.header.frame_id = "map"
    msg.header.stamp = rospy.Time.now()
    msg.info.resolution = 0.05
    msg.info.width = msg.info.height = SIDE
    msg.info.origin.orientation.w = 1.0
    msg.data = numpy.zeros(SIDE * SIDE, dtype=numpy.int8)  # all free: plans would go anywhere
    return msg


def chair_memory_mb():
    """(VmRSS, VmHWM) [MB] of the chair process, found through its node's XML-RPC getPid."""
    uri = rosgraph.Master("/test_big_map").lookupNode(CHAIR_NODE)
    _, _, pid = xmlrpc.client.ServerProxy(uri).getPid("/test_big_map")
    fields = {}
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            key, _, value = line.partition(":")
            fields[key] = value.strip()
    return tuple(float(fields[k].split()[0]) / 1024.0 for k in ("VmRSS", "VmHWM"))


class BigMap(unittest.TestCase):
    def test_a_huge_map_is_refused_and_the_chair_drives_on(self):
        s = Rider("test_big_map")
        lock = threading.Lock()
        commands, refusals = [], []  # command stamps (sim s); (node, text) of map refusals

        def on_torques(msg):
            with lock:
                commands.append(msg.header.stamp.to_sec())

        def on_log(msg):
            if msg.name == CHAIR_NODE and "map refused" in msg.msg:
                with lock:
                    refusals.append(msg.msg)

        rospy.Subscriber("/wheel_torques", WheelTorques, on_torques, queue_size=200)
        rospy.Subscriber("/rosout", Log, on_log, queue_size=200)
        t_go = s.start_driving(self, START, GOAL, 0.5)
        rss_before, peak_before = chair_memory_mb()
        # Another map server: latched, so every subscriber of the chair gets it.
        pub = rospy.Publisher("/map", numpy_msg(OccupancyGrid), queue_size=1, latch=True)
        wall0 = time.time()
        pub.publish(big_map())
        t_map = rospy.get_time()
        rospy.loginfo("4000 x 4000 map published at %.2f s (%.1f s wall to serialize)", t_map,
                      time.time() - wall0)
        s.sim_sleep(DRIVE)
        t_end = rospy.get_time()
        self.assertNotIn(s.drive_outcome(t_go), ("aborted", "collided"), s.describe(t_go))
        self.assertGreater(s.travelled(t_map), 1.0, "the chair hardly moved after the map: " +
                           s.describe(t_map))
        self.assertIsNone(s.first_stop(t_map), "a safety stop after the map: %s" % s.stops(t_map))
        self.assertFalse(s.collided)

        # The control loop kept its rate from the map to the goal.
        with lock:
            stamps = sorted(t for t in commands if t_map <= t <= t_end)
        self.assertGreater(len(stamps), 10, "no motor commands seen after the map")
        gaps = [b - a for a, b in zip(stamps, stamps[1:])]
        rate = (len(stamps) - 1) / (stamps[-1] - stamps[0])
        # 3 periods: the controller itself stops when a step is late by more than 0.1 s.
        self.assertLess(max(gaps), 3 * CONTROL_PERIOD + 0.005,
                        "control loop paused %.3f s after the map" % max(gaps))
        self.assertGreater(rate, 0.9 / CONTROL_PERIOD, "control rate %.1f Hz" % rate)

        # Refused with a reason by the chair's consumers, its memory within the budget.
        self.assertTrue(s.wait(lambda: len(refusals) >= 3, 10.0), "refusals: %s" % refusals)
        with lock:
            self.assertTrue(all("4000 x 4000" in r and "max_map_cells" in r for r in refusals),
                            refusals)
        rss_after, peak = chair_memory_mb()
        self.assertLess(peak - peak_before, 2 * MAP_MB + 10.0,
                        "chair peak RSS %.0f -> %.0f MB" % (peak_before, peak))
        rospy.loginfo("big map: refused %d times; in %.0f s after it %.1f m driven, control "
                      "%.1f Hz, longest step %.0f ms; RSS %.0f -> %.0f MB, peak %.0f -> %.0f MB",
                      len(refusals), DRIVE, s.travelled(t_map), rate, 1e3 * max(gaps),
                      rss_before, rss_after, peak_before, peak)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "big_map", BigMap, sys.argv)
