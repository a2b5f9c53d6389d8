#!/usr/bin/python3
"""The chair under test: the simulator (motors behind the CAN path over UDP) + the one-process
chair (`rosrun wheelchair_bringup wheelchair CONFIG`), started together on free UDP ports.

The bring-up file is wheelchair_bringup's config/chair_sim.yaml when it exists, else
test/table2/chair_table2.yaml (or --config). A copy of it gets the base driver's
transport/ports and use_sim_time; nothing else is changed. Both run at --nice (default -5,
the chair's priority as deployed: deploy/wheelchair.service `Nice=-5`), when allowed. Ends both
processes when either ends or on SIGINT/SIGTERM; exits with the first one's code.
"""
import argparse
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time

import rospkg
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
DRIVER_TYPE = "wheelchair_base_driver/BaseDriverNodelet"


def free_udp_port():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def default_config():
    try:
        theirs = os.path.join(rospkg.RosPack().get_path("wheelchair_bringup"), "config",
                              "chair_sim.yaml")
        if os.path.exists(theirs):
            return theirs
    except rospkg.ResourceNotFound:
        pass
    return os.path.join(HERE, "chair_table2.yaml")


def chair_config(path, driver_port, sim_port):
    """The bring-up file with the driver on UDP (driver_port -> sim_port) and sim time."""
    with open(path) as f:
        config = yaml.safe_load(f)
    config.setdefault("params", {})
    config["params"] = dict(config["params"] or {}, use_sim_time=True)
    drivers = [n for n in config.get("nodelets", []) if n.get("type") == DRIVER_TYPE]
    if len(drivers) != 1:
        raise SystemExit("%s: expected one %s, found %d" % (path, DRIVER_TYPE, len(drivers)))
    drivers[0]["params"] = dict(drivers[0].get("params") or {}, transport="udp",
                                udp_local_port=driver_port, udp_remote_port=sim_port)
    return config


def set_niceness(target):
    """This process (so the simulator and chair it starts, threads included) at niceness
    `target`. At 1x real time on a loaded 2-core machine the chair was starved for 0.1-0.2 s (the
    motor controller's 100 ms command watchdog braked, the controller stopped on stale odometry);
    on the chair, systemd runs it at Nice=-5 for that reason. Without the privilege
    (CAP_SYS_NICE) it runs at what it inherited."""
    try:
        os.setpriority(os.PRIO_PROCESS, 0, target)
    except OSError as e:
        print("table2_stack: cannot set nice %d: %s" % (target, e), flush=True)


def set_session_niceness(pid, target):
    """The session of `pid` at niceness `target`; returns the niceness it competes with. With
    autogroup scheduling (/proc/sys/kernel/sched_autogroup_enabled, the default of desktop
    kernels) a process's nice only ranks it inside its session, and each process here leads its
    own session: it is the session's (autogroup's) nice that weighs against other sessions'
    builds."""
    try:
        with open("/proc/%d/autogroup" % pid, "w") as f:
            f.write(str(target))
        with open("/proc/%d/autogroup" % pid) as f:  # "/autogroup-123 nice -5"
            return int(f.read().split()[-1])
    except (OSError, ValueError, IndexError) as e:
        print("table2_stack: no autogroup nice %d for %d (%s)" % (target, pid, e), flush=True)
    return os.getpriority(os.PRIO_PROCESS, pid)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--config", default=None)
    parser.add_argument("--world", default=os.path.join(HERE, "..", "worlds", "flat.yaml"))
    parser.add_argument("--speed", type=float, default=2.0)
    parser.add_argument("--initial", type=float, nargs=3, default=[3.0, 2.2, 0.0])
    parser.add_argument("--nice", type=int, default=-5,
                        help="niceness of simulator and chair (deploy/wheelchair.service: -5)")
    args, _ = parser.parse_known_args(
        [a for a in sys.argv[1:] if not a.startswith("__")])  # roslaunch adds __name, __log
    config_path = args.config or default_config()
    driver_port, sim_port = free_udp_port(), free_udp_port()
    while sim_port == driver_port:
        sim_port = free_udp_port()
    tmp = tempfile.NamedTemporaryFile("w", suffix=".yaml", prefix="table2_chair_", delete=False)
    chair_config_data = chair_config(config_path, driver_port, sim_port)
    yaml.safe_dump(chair_config_data, tmp)
    tmp.close()
    print("table2_stack: chair %s, UDP driver %d <-> sim %d, speed %.1f" %
          (config_path, driver_port, sim_port, args.speed), flush=True)
    x, y, yaw = args.initial
    sim = ["rosrun", "wheelchair_sim", "simulator", "__name:=simulator",
           "_world:=" + os.path.abspath(args.world), "_motor_bus:=udp",
           "_udp_local_port:=%d" % sim_port, "_udp_remote_port:=%d" % driver_port,
           "_speed:=%g" % args.speed, "_initial_x:=%g" % x, "_initial_y:=%g" % y,
           "_initial_yaw:=%g" % yaw]
    # the manager's threads: a scan update may wait 100 ms for tf while the driver and the
    # controller must keep running (chair_sim.yaml's num_worker_threads; 8 if it has none)
    threads = int(chair_config_data.get("num_worker_threads", 8))
    chair = ["rosrun", "wheelchair_bringup", "wheelchair", tmp.name,
             "_num_worker_threads:=%d" % threads]
    set_niceness(args.nice)
    procs = [subprocess.Popen(sim, start_new_session=True)]
    time.sleep(0.5)  # the simulator owns /clock: let it come up first
    procs.append(subprocess.Popen(chair, start_new_session=True))
    nice = [set_session_niceness(p.pid, args.nice) for p in procs]
    print("table2_stack: simulator and chair at nice %s" % nice, flush=True)

    stopping = []

    def stop(*_):
        stopping.append(True)

    signal.signal(signal.SIGINT, stop)
    signal.signal(signal.SIGTERM, stop)
    code = 0
    while not stopping:
        done = [p for p in procs if p.poll() is not None]
        if done:
            code = done[0].returncode
            print("table2_stack: %s exited with %d" % (done[0].args[2], code), flush=True)
            break
        time.sleep(0.2)
    for sig, grace in ((signal.SIGINT, 5.0), (signal.SIGTERM, 3.0), (signal.SIGKILL, 1.0)):
        for p in procs:
            if p.poll() is None:
                os.killpg(p.pid, sig)
        deadline = time.time() + grace
        while time.time() < deadline and any(p.poll() is None for p in procs):
            time.sleep(0.1)
    os.unlink(tmp.name)
    sys.exit(code)


if __name__ == "__main__":
    main()
