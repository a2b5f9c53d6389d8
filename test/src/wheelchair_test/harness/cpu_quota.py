"""A CPU quota on a process, the legacy-PC budget (issue 20): the cgroup v1 cpu controller,
cpu.cfs_quota_us of cpu.cfs_period_us (15000 of 100000 = 15 % of one core, what CPUQuota=15%
gives the deployed unit). As root; the whole process (every thread) moves into a cgroup of its
own and back out on close(). stats() says how often the quota throttled it and how much CPU it
used (cpuacct, when mounted), so a report can state the margin."""
import os
import time

CPU = "/sys/fs/cgroup/cpu"
CPUACCT = "/sys/fs/cgroup/cpuacct"


class CpuQuota:
    def __init__(self, pid, percent, name=None, period_us=100000):
        if not os.path.isdir(CPU):
            raise RuntimeError(f"no cgroup v1 cpu controller at {CPU}")
        self.pid, self.percent = pid, percent
        self.name = name or f"wheelchair_quota_{os.getpid()}_{pid}"
        self.dirs = [os.path.join(CPU, self.name)]
        if os.path.isdir(CPUACCT) and os.path.realpath(CPUACCT) != os.path.realpath(CPU):
            self.dirs.append(os.path.join(CPUACCT, self.name))
        for d in self.dirs:
            os.makedirs(d, exist_ok=True)
        self._write("cpu.cfs_period_us", period_us)
        self._write("cpu.cfs_quota_us", int(round(period_us * percent / 100.0)))
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
        return {"quota_percent": self.percent, "periods": int(stat.get("nr_periods", 0)),
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
