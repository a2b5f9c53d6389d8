#!/usr/bin/env python3
"""Every node of the stack starts with plain `rosrun` (no roslaunch), registers with the
master and keeps running; the one-process bring-up loads its nodelets from a config file. A
node given an unknown or renamed parameter, or a file it needs that is missing, refuses to start
with a message that says so."""
import os
import tempfile
import time
import unittest

import rosgraph
import rostest
import yaml

from wheelchair_test.harness import Processes, worlds_dir

WORLDS = worlds_dir()
CONFIG = WORLDS.parent / "config"

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
    ("wheelchair_slam", "slam_node", [], ["/slam_node"]),
    ("wheelchair_bringup", "wheelchair", [f"{CONFIG}/bringup_minimal.yaml"], ["/wheelchair"]),
]


def _missing_home_config():
    """bringup_minimal.yaml with the rider's places in a file that does not exist."""
    doc = yaml.safe_load((CONFIG / "bringup_minimal.yaml").read_text())
    for nodelet in doc["nodelets"]:
        if nodelet["name"] == "hmi":
            nodelet["params"]["places_file"] = "/nonexistent/home/places.yaml"
    path = os.path.join(tempfile.mkdtemp(prefix="rosrun_nodes_"), "missing_home.yaml")
    with open(path, "w") as f:
        yaml.safe_dump(doc, f)
    return path


# (package, executable, arguments, what the refusal must say)
REFUSED = [
    ("wheelchair_safety", "safety", ["_scan_timout:=0.5"], "unknown parameter 'scan_timout'"),
    ("wheelchair_safety", "safety", ["_scan_timeout:=0.0"], "scan_timeout must be positive"),
    ("wheelchair_slam", "slam_node", ["_map_perod:=2.0"], "unknown parameter 'map_perod'"),
    ("wheelchair_slam", "slam_node", ["_continue_dir:=/nonexistent/map"], "/nonexistent/map"),
    ("wheelchair_hmi", "hmi", [f"_places_file:={WORLDS}/flat.places.yaml", "_frame_id:=map"],
     "'frame_id' is now called 'map_frame'"),
    ("wheelchair_hmi", "hmi", ["_places_file:=/nonexistent/places.yaml"],
     "cannot open places file"),
    ("wheelchair_bringup", "wheelchair", [_missing_home_config()],
     "/hmi/places_file: cannot read '/nonexistent/home/places.yaml'"),
    ("wheelchair_bringup", "wheelchair", [f"{CONFIG}/bringup_minimal.yaml", "_hmii/scan_interval:=1.0"],
     "override ~hmii/scan_interval names no nodelet"),
    # a bare file name is one of wheelchair_bringup's configs (mapping.yaml has no hmi)
    ("wheelchair_bringup", "wheelchair", ["mapping.yaml", "_hmi/scan_interval:=1.0"],
     "override ~hmi/scan_interval names no nodelet"),
]
STARTUP = 30.0  # [s] on a loaded 2-core machine


def _all_nodes():
    state = rosgraph.Master("/test_rosrun_nodes").getSystemState()
    return {node for group in state for _, nodes in group for node in nodes}


class RosrunEveryNode(unittest.TestCase):
    def setUp(self):
        self.logs = tempfile.mkdtemp(prefix="rosrun_nodes_")
        self.processes = Processes(self.logs, grace=10.0)

    def tearDown(self):
        self.processes.stop_all()

    def output(self, name):
        return self.processes.log_tail(name, lines=20)[-1500:]

    def run_node(self, package, executable, arguments, names):
        self.processes.rosrun(executable, package, executable, *arguments)
        deadline = time.monotonic() + STARTUP
        while time.monotonic() < deadline and not set(names) <= _all_nodes():
            if self.processes.ended(executable):
                self.fail(f"rosrun {package} {executable} exited with "
                          f"{self.processes.ended(executable)[1]}: {self.output(executable)}")
            time.sleep(0.2)
        self.assertTrue(set(names) <= _all_nodes(),
                        f"rosrun {package} {executable}: {names} not registered after {STARTUP} s")
        time.sleep(1.0)
        if self.processes.ended(executable):
            self.fail(f"rosrun {package} {executable} died after starting: {self.output(executable)}")
        self.processes.stop(executable)
        # the node is gone again before the next one starts
        deadline = time.monotonic() + 10.0
        while time.monotonic() < deadline and set(names) & _all_nodes():
            time.sleep(0.2)

    def run_refused(self, package, executable, arguments, message):
        self.processes.rosrun(executable, package, executable, *arguments)
        deadline = time.monotonic() + STARTUP
        while time.monotonic() < deadline and not self.processes.ended(executable):
            time.sleep(0.2)
        ended = self.processes.ended(executable)
        self.assertIsNotNone(ended, f"rosrun {package} {executable} {arguments} did not refuse")
        self.assertEqual(ended[1], 1, self.output(executable))
        self.assertIn(message, self.output(executable))
        # the refused parameters stay on the master: gone before the next node starts
        for namespace in {f"/{executable}", "/hmi", "/map_server"}:
            try:
                rosgraph.Master("/test_rosrun_nodes").deleteParam(namespace)
            except rosgraph.MasterException:
                pass


def _make_test(spec, run):
    def test(self):
        getattr(self, run)(*spec)
    return test


for _spec in NODES:
    setattr(RosrunEveryNode, f"test_{_spec[0]}__{_spec[1]}", _make_test(_spec, "run_node"))
for _i, _spec in enumerate(REFUSED):
    setattr(RosrunEveryNode, f"test_refuses_{_i}_{_spec[0]}__{_spec[1]}",
            _make_test(_spec, "run_refused"))

if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "rosrun_every_node", RosrunEveryNode)
