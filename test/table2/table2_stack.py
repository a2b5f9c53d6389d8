#!/usr/bin/python3
"""The chair under test: the simulator (motors behind the CAN path over UDP) + the one-process
chair (`rosrun wheelchair_bringup wheelchair CONFIG`), started together on free UDP ports.

The bring-up file is wheelchair_bringup's config/chair_sim.yaml when it exists, else
test/table2/chair_table2.yaml (or --config). A copy of it gets the base driver's
transport/ports and use_sim_time, and with --rider NODE the HMI's go_to_caller (the one caller
whose /go_to_place releases a latched stop: the protocol's runner plays the rider); nothing
else is changed. Both run at --nice (default -5,
the chair's priority as deployed: deploy/wheelchair.service `Nice=-5`), when allowed. Ends both
processes when either ends or on SIGINT/SIGTERM; exits with the first one's code. start() is
the same for tools/report.py, which runs the pairs in its own process.
"""
import argparse
import os
import signal
import sys
import tempfile
import time

import rospkg
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "src"))  # wheelchair_test.harness, by path
from wheelchair_test.harness import Processes, free_udp_ports, stack  # noqa: E402

DRIVER_TYPE = "wheelchair_base_driver/BaseDriverNodelet"
HMI_TYPE = "wheelchair_hmi/HmiNodelet"


def default_config():
    try:
        theirs = os.path.join(rospkg.RosPack().get_path("wheelchair_bringup"), "config",
                              "chair_sim.yaml")
        if os.path.exists(theirs):
            return theirs
    except rospkg.ResourceNotFound:
        pass
    return os.path.join(HERE, "chair_table2.yaml")


def bringup_for_run(path, driver_port, sim_port, rider=None):
    """The bring-up file with the driver on UDP (driver_port -> sim_port) and sim time; with
    `rider` (a node name) the HMI's go_to_caller is that node, so that its go_to_place releases
    a latched stop as the rider's display does."""
    with open(path) as f:
        config = yaml.safe_load(f)
    config.setdefault("params", {})
    config["params"] = dict(config["params"] or {}, use_sim_time=True)
    drivers = [n for n in config.get("nodelets", []) if n.get("type") == DRIVER_TYPE]
    if len(drivers) != 1:
        raise SystemExit("%s: expected one %s, found %d" % (path, DRIVER_TYPE, len(drivers)))
    drivers[0]["params"] = dict(drivers[0].get("params") or {}, transport="udp",
                                udp_local_port=driver_port, udp_remote_port=sim_port)
    if rider is not None:
        hmis = [n for n in config.get("nodelets", []) if n.get("type") == HMI_TYPE]
        if len(hmis) != 1:
            raise SystemExit("%s: expected one %s for the rider %s, found %d" %
                             (path, HMI_TYPE, rider, len(hmis)))
        hmis[0]["params"] = dict(hmis[0].get("params") or {}, go_to_caller=rider)
    return config


def start(processes, config_path, world, speed, initial, nice, rider=None):
    """Starts the simulator and the chair (processes "simulator" and "chair") on free UDP ports;
    `rider`: the node whose go_to_place releases a stop (bringup_for_run). Returns the copy of
    the bring-up file they run (the caller removes it)."""
    driver_port, sim_port = free_udp_ports(2)
    tmp = tempfile.NamedTemporaryFile("w", suffix=".yaml", prefix="table2_chair_", delete=False)
    bringup = bringup_for_run(config_path, driver_port, sim_port, rider)
    yaml.safe_dump(bringup, tmp)
    tmp.close()
    print("table2_stack: chair %s, UDP driver %d <-> sim %d, speed %.1f" %
          (config_path, driver_port, sim_port, speed), flush=True)
    stack.simulator(processes, os.path.abspath(world), (driver_port, sim_port), initial,
                    options={"nice": nice}, speed="%g" % speed)
    time.sleep(0.5)  # the simulator owns /clock: let it come up first
    # the manager's threads: a scan update may wait 100 ms for tf while the driver and the
    # controller must keep running (chair_sim.yaml's num_worker_threads; 8 if it has none)
    threads = int(bringup.get("num_worker_threads", 8))
    stack.chair(processes, tmp.name, name="chair", overrides={"num_worker_threads": threads},
                options={"nice": nice})
    print("table2_stack: simulator and chair at nice %s" %
          [processes.niceness(n) for n in ("simulator", "chair")], flush=True)
    return tmp.name


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--config", default=None)
    parser.add_argument("--world", default=os.path.join(HERE, "..", "worlds", "flat.yaml"))
    parser.add_argument("--speed", type=float, default=2.0)
    parser.add_argument("--initial", type=float, nargs=3, default=[3.0, 2.2, 0.0])
    parser.add_argument("--rider", default=None,
                        help="node name made the HMI's go_to_caller (the protocol's runner)")
    parser.add_argument("--nice", type=int, default=-5,
                        help="niceness of simulator and chair (deploy/wheelchair.service: -5)")
    args, _ = parser.parse_known_args(
        [a for a in sys.argv[1:] if not a.startswith("__")])  # roslaunch adds __name, __log
    processes = Processes(grace=5.0)  # output inherited (the rostest's screen)
    stopping = []

    def stop(*_):
        stopping.append(True)

    signal.signal(signal.SIGINT, stop)
    signal.signal(signal.SIGTERM, stop)
    config = start(processes, args.config or default_config(), args.world, args.speed,
                   args.initial, args.nice, args.rider)
    code = 0
    try:
        while not stopping:
            ended = processes.ended()
            if ended:
                name, code = ended
                print("table2_stack: %s exited with %d" % (name, code), flush=True)
                break
            time.sleep(0.2)
    finally:
        processes.stop_all()
        os.unlink(config)
    sys.exit(code)


if __name__ == "__main__":
    main()
