#!/usr/bin/env python3
"""Every node of the stack starts with plain `rosrun` (no roslaunch), registers with the
master and keeps running; the one-process bring-up loads its nodelets from a config file."""
import os
import subprocess
import tempfile
import time
import unittest

import rosgraph
import rospkg
import rostest

WORLDS = os.path.join(rospkg.RosPack().get_path("wheelchair_test"), "worlds")
CONFIG = os.path.join(rospkg.RosPack().get_path("wheelchair_test"), "config")

# (package, executable, arguments, node names that must appear)
NODES = [
    ("wheelchair_mapping", "map_server", [f"{WORLDS}/flat.yaml"], ["/map_server"]),
    ("wheelchair_mapping", "mapping", [], ["/mapping"]),
    ("wheelchair_description", "description_publisher", [], ["/description_publisher"]),
    ("wheelchair_kld", "kld_localizer", [], ["/kld_localizer"]),
    ("wheelchair_planner", "planner_host", [], ["/planner_host"]),
    ("wheelchair_controller", "controller", [], ["/controller"]),
    ("wheelchair_base_driver", "base_driver", ["_transport:=fake"], ["/base_driver"]),
    ("wheelchair_sim", "simulator", [f"_world:={WORLDS}/flat.yaml", "_initial_x:=3.0",
                                     "_initial_y:=2.2"], ["/simulator"]),
    ("wheelchair_safety", "safety", [], ["/safety"]),
    ("wheelchair_hmi", "hmi", [f"_places_file:={WORLDS}/flat.places.yaml"], ["/hmi"]),
    ("wheelchair_bringup", "wheelchair", [f"{CONFIG}/bringup_minimal.yaml"], ["/wheelchair"]),
]
STARTUP = 30.0  # [s] on a loaded 2-core machine


def _all_nodes():
    state = rosgraph.Master("/test_rosrun_nodes").getSystemState()
    return {node for group in state for _, nodes in group for node in nodes}


class RosrunEveryNode(unittest.TestCase):
    def run_node(self, package, executable, arguments, names):
        log = tempfile.TemporaryFile()
        process = subprocess.Popen(["rosrun", package, executable, *arguments], stdout=log,
                                   stderr=subprocess.STDOUT, start_new_session=True)

        def output():
            log.seek(0)
            return log.read().decode(errors="replace")[-1500:]

        try:
            deadline = time.monotonic() + STARTUP
            while time.monotonic() < deadline and not set(names) <= _all_nodes():
                if process.poll() is not None:
                    self.fail(f"rosrun {package} {executable} exited with {process.returncode}: "
                              f"{output()}")
                time.sleep(0.2)
            self.assertTrue(set(names) <= _all_nodes(),
                            f"rosrun {package} {executable}: {names} not registered after {STARTUP} s")
            time.sleep(1.0)
            if process.poll() is not None:
                self.fail(f"rosrun {package} {executable} died after starting: {output()}")
        finally:
            if process.poll() is None:
                os.killpg(process.pid, 15)
            try:
                process.wait(10)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, 9)
                process.wait()
        # the node is gone again before the next one starts
        deadline = time.monotonic() + 10.0
        while time.monotonic() < deadline and set(names) & _all_nodes():
            time.sleep(0.2)


def _make_test(spec):
    def test(self):
        self.run_node(*spec)
    return test


for _spec in NODES:
    setattr(RosrunEveryNode, f"test_{_spec[0]}__{_spec[1]}", _make_test(_spec))

if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "rosrun_every_node", RosrunEveryNode)
