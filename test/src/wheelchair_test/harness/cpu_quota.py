"""A CPU quota on a process, the legacy-PC budget (issue 20): the cgroup v1 cpu controller,
cpu.cfs_quota_us of cpu.cfs_period_us (15000 of 100000 = 15 % of one core, what CPUQuota=15%
gives the deployed unit). As root; the whole process (every thread) moves into a cgroup of its
own and back out on close(). stats() says how often the quota throttled it and how much CPU it
used (cpuacct, when mounted), so a report can state the margin.

The group also weighs what the process's nice gave it (cpu.shares): in a cgroup of its own a
process leaves its session's autogroup, so the harness's nice -5 (the deployed Nice=-5) no longer
ranked it above the other sessions of a shared machine. With the default 1024 the capped chair
weighed as much as one build among ten and waited behind them on every wake-up (scan gaps of
0.3 s, 100 ms pauses of the 50 Hz control loop); a quota should cap, not also demote."""
import os
import subprocess
import time

SYS = "/sys/fs/cgroup"
# The kernel's CFS weight of each nice level (kernel/sched/core.c sched_prio_to_weight), -20..19.
NICE_WEIGHT = (88761, 71755, 56483, 46273, 36291, 29154, 23254, 18705, 14949, 11916,
               9548, 7620, 6100, 4904, 3906, 3121, 2501, 1991, 1586, 1277,
               1024, 820, 655, 526, 423, 335, 272, 215, 172, 137,
               110, 87, 70, 56, 45, 36, 29, 23, 18, 15)
OWN = "/run/wheelchair_cgroup"  # where it mounts the hierarchies if /sys has none


def _hierarchy(controller):
    """The cgroup v1 hierarchy of `controller`: /sys/fs/cgroup/<controller>, or, where /sys has
    no cgroups (`ip netns exec` mounts a fresh sysfs), the same hierarchy mounted again under
    /run (as root). None if the kernel has no such v1 controller."""
    path = os.path.join(SYS, controller)
    if os.path.isdir(path):
        return path
    path = os.path.join(OWN, controller)
    if not os.path.exists(os.path.join(path, "cgroup.procs")):
        os.makedirs(path, exist_ok=True)
        if subprocess.run(["mount", "-t", "cgroup", "-o", controller, "cgroup", path],
                          capture_output=True).returncode != 0:
            return None
    return path


def group_weight(pid):
    """cpu.shares for a group holding only `pid`: the CFS weight of the process's nice (the
    weight its autogroup had when the harness set that to the process's nice)."""
    return NICE_WEIGHT[os.getpriority(os.PRIO_PROCESS, pid) + 20]


class CpuQuota:
    def __init__(self, pid, percent, name=None, period_us=100000):
        cpu, cpuacct = _hierarchy("cpu"), _hierarchy("cpuacct")
        if cpu is None:
            raise RuntimeError("no cgroup v1 cpu controller (as root?)")
        self.pid, self.percent = pid, percent
        self.name = name or f"wheelchair_quota_{os.getpid()}_{pid}"
        self.dirs = [os.path.join(cpu, self.name)]
        if cpuacct and os.path.realpath(cpuacct) != os.path.realpath(cpu):
            self.dirs.append(os.path.join(cpuacct, self.name))
        for d in self.dirs:
            os.makedirs(d, exist_ok=True)
        self._write("cpu.cfs_period_us", period_us)
        self._write("cpu.cfs_quota_us", int(round(period_us * percent / 100.0)))
        self.shares = group_weight(pid)
        self._write("cpu.shares", self.shares)
        for d in self.dirs:
            with open(os.path.join(d, "cgroup.procs"), "w") as f:
                f.write(str(pid))
        self.started = time.monotonic()
        self.usage0 = self._usage()

    def _write(self, key, value):
        with open(os.path.join(self.dirs[0], key), "w") as f:
            f.write(str(value))

    def _usage(self):
        for d in self.dirs:
            path = os.path.join(d, "cpuacct.usage")
            if os.path.exists(path):
                with open(path) as f:
                    return int(f.read()) * 1e-9
        return None

    def stats(self):
        """{quota_percent, periods, throttled_periods, throttled_s, used_percent (of one core,
        since the start; None without cpuacct)}."""
        with open(os.path.join(self.dirs[0], "cpu.stat")) as f:
            stat = dict(line.split() for line in f if line.strip())
        wall = time.monotonic() - self.started
        usage = self._usage()
        used = None if usage is None or self.usage0 is None else 100.0 * (usage - self.usage0) / wall
        return {"quota_percent": self.percent, "shares": self.shares,
                "periods": int(stat.get("nr_periods", 0)),
                "throttled_periods": int(stat.get("nr_throttled", 0)),
                "throttled_s": int(stat.get("throttled_time", 0)) * 1e-9,
                "used_percent": used, "wall_s": wall}

    def close(self):
        """Moves whatever is left back to the root cgroups and removes the group."""
        for d in self.dirs:
            root = os.path.dirname(d)
            try:
                with open(os.path.join(d, "cgroup.procs")) as f:
                    pids = f.read().split()
                for p in pids:
                    with open(os.path.join(root, "cgroup.procs"), "w") as f:
                        f.write(p)
                os.rmdir(d)
            except OSError:
                pass
