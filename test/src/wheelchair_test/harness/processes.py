"""Processes of a test, demo, report or bench run: each in its own process group with its own
log, checked while the run goes on, and all stopped and reaped at the end.

Stopping a process: SIGINT to its group first (roscpp and rospy nodes shut down cleanly and
unregister from the master), then SIGTERM, then SIGKILL, `grace` seconds apart, until no member
of the group is left. The master is
started with interrupt=False: rosmaster may ignore SIGINT (ROS_ON_DEBIAN.md), so it gets SIGTERM
first. Processes are stopped newest first, so the master (started first) goes last.
"""
import os
import pathlib
import signal
import socket
import subprocess
import time


class ProcessError(RuntimeError):
    """A process of the run ended (or could not start); the message names it and says why."""


def free_port(kind=socket.SOCK_STREAM):
    """A port of 127.0.0.1 that is free now (TCP by default; socket.SOCK_DGRAM for UDP)."""
    with socket.socket(socket.AF_INET, kind) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def free_udp_ports(count=2):
    """`count` distinct free UDP ports (a CAN bus over UDP: driver, motors)."""
    ports = []
    while len(ports) < count:
        port = free_port(socket.SOCK_DGRAM)
        if port not in ports:
            ports.append(port)
    return ports


class _Started:
    def __init__(self, name, popen, interrupt, grace, log):
        self.name, self.popen, self.interrupt, self.grace, self.log = name, popen, interrupt, grace, log
        self.nice = None  # the niceness it competes with, when one was asked for


class Processes:
    """The processes one run started, in start order.

    logs: directory for one `<name>.log` per process (None: output is inherited).
    env: environment of the children (None: this process's, read at each start)."""

    def __init__(self, logs=None, env=None, cwd=None, grace=8.0):
        self.logs = pathlib.Path(logs) if logs is not None else None
        if self.logs is not None:
            self.logs.mkdir(parents=True, exist_ok=True)
        self.env = env
        self.cwd = cwd
        self.grace = grace
        self._started = []

    # ---- starting -----------------------------------------------------------------------------
    def start(self, name, argv, stdout=None, interrupt=True, grace=None, nice=None):
        """Starts `argv` in its own session (process group); output to logs/<name>.log unless
        `stdout` is given (e.g. subprocess.PIPE; stderr then still goes to the log). `nice`: the
        niceness of the process and of its session's autogroup (set_session_niceness)."""
        log = self.logs / f"{name}.log" if self.logs is not None else None
        log_file = open(log, "wb") if log is not None else None
        try:
            popen = subprocess.Popen(
                argv, stdout=stdout if stdout is not None else log_file,
                stderr=log_file if log_file is not None else None,
                stdin=subprocess.DEVNULL, start_new_session=True, env=self.env, cwd=self.cwd,
                text=stdout is not None)
        except OSError as e:
            raise ProcessError(f"{name}: cannot start {argv[0]}: {e}") from None
        finally:
            if log_file is not None:
                log_file.close()
        started = _Started(name, popen, interrupt, grace or self.grace, log)
        self._started.append(started)
        if nice is not None:
            started.nice = set_niceness(popen.pid, nice)
        return popen

    def rosrun(self, name, package, executable, *arguments, prefix=None, **options):
        """`rosrun [--prefix PREFIX] package executable arguments`, after checking that the
        executable exists (a clear error instead of a process that dies at once)."""
        found = subprocess.run(["rosrun", "--prefix", "echo", package, executable],
                               capture_output=True, text=True, env=self.env)
        if found.returncode != 0:
            reason = (found.stdout + found.stderr).strip().splitlines()
            raise ProcessError(f"`rosrun {package} {executable}` is not available "
                               f"({reason[-1] if reason else 'not built'}); build the workspace "
                               f"(./wheelchair build)")
        command = ["rosrun"] + (["--prefix", prefix] if prefix else []) + [package, executable]
        return self.start(name, command + [str(a) for a in arguments], **options)

    # ---- watching -----------------------------------------------------------------------------
    def get(self, name):
        return next(s.popen for s in self._started if s.name == name)

    def niceness(self, name):
        """The niceness a process started with `nice=` competes with (None: not asked)."""
        return next(s.nice for s in self._started if s.name == name)

    def ended(self, *names):
        """The first of `names` (default: all) that has ended, as (name, exit code), or None."""
        for s in self._started:
            if (not names or s.name in names) and s.popen.poll() is not None:
                return s.name, s.popen.returncode
        return None

    def check(self, *names):
        """Raises ProcessError if one of `names` (default: all) has ended."""
        ended = self.ended(*names)
        if ended is not None:
            name, code = ended
            tail = self.log_tail(name)
            where = f" (log: {self._log_of(name)})" if self._log_of(name) else ""
            raise ProcessError(f"{name} exited with code {code}: {tail or '(no output)'}{where}")

    def log_tail(self, name, lines=3):
        """The last `lines` lines of a process's log, joined with " | "."""
        log = self._log_of(name)
        if log is None or not log.exists():
            return ""
        text = log.read_text(errors="replace").strip().splitlines()
        return " | ".join(line.strip() for line in text[-lines:])

    def wait_for(self, what, condition, timeout, watch=(), period=0.1):
        """Polls condition() until it returns something true and returns it; raises ProcessError
        after `timeout` seconds, or at once when one of the processes named in `watch` ended."""
        deadline = time.monotonic() + timeout
        while True:
            if watch:
                self.check(*watch)
            result = condition()
            if result:
                return result
            if time.monotonic() > deadline:
                raise ProcessError(f"timed out after {timeout:.0f} s waiting for {what}")
            time.sleep(period)

    def _log_of(self, name):
        return next((s.log for s in self._started if s.name == name), None)

    # ---- stopping -----------------------------------------------------------------------------
    def stop(self, name):
        """Stops one process and its group; returns its exit code."""
        return _stop(next(s for s in self._started if s.name == name))

    def stop_all(self):
        """Stops every process (newest first) and reaps it."""
        for s in reversed(self._started):
            _stop(s)

    def __enter__(self):
        return self

    def __exit__(self, *_):
        self.stop_all()


def _group_alive(pgid):
    try:
        os.killpg(pgid, 0)
        return True
    except ProcessLookupError:
        return False
    except PermissionError:
        return True


def _stop(started):
    """Signals the process group until no member is left (a child that outlives its leader,
    e.g. a background job that ignores SIGINT, gets the next signal); reaps the leader."""
    popen = started.popen
    signals = ((signal.SIGINT,) if started.interrupt else ()) + (signal.SIGTERM, signal.SIGKILL)
    for sig in signals:
        popen.poll()  # a leader that ended is reaped, else it counts as a member
        if not _group_alive(popen.pid):
            break
        try:
            os.killpg(popen.pid, sig)
        except ProcessLookupError:
            break
        deadline = time.monotonic() + (started.grace if sig != signal.SIGKILL else 5.0)
        while time.monotonic() < deadline:
            popen.poll()
            if not _group_alive(popen.pid):
                break
            time.sleep(0.05)
    popen.wait()  # reaped: no zombie
    if popen.stdout is not None:
        popen.stdout.close()
    return popen.returncode


def set_niceness(pid, nice):
    """Process `pid` (it has just started: its threads inherit it) and its session's autogroup
    at niceness `nice`, when allowed (CAP_SYS_NICE; else it keeps what it inherited); returns the
    niceness it competes with. At 1x real time on a loaded 2-core machine the chair was starved
    for 0.1-0.2 s (the motor controller's 100 ms command watchdog braked); on the chair, systemd
    runs it at Nice=-5 for that reason. With autogroup scheduling
    (/proc/sys/kernel/sched_autogroup_enabled, the default of desktop kernels) a process's nice
    only ranks it inside its session, and each process here leads its own session: it is the
    session's nice that weighs against other sessions' work (a nice-19 build)."""
    try:
        os.setpriority(os.PRIO_PROCESS, pid, nice)
    except OSError as e:
        print(f"[harness] cannot set nice {nice} for {pid}: {e}", flush=True)
    try:
        with open(f"/proc/{pid}/autogroup", "w") as f:
            f.write(str(nice))
        with open(f"/proc/{pid}/autogroup") as f:  # "/autogroup-123 nice -5"
            return int(f.read().split()[-1])
    except (OSError, ValueError, IndexError) as e:
        print(f"[harness] no autogroup nice {nice} for {pid} ({e})", flush=True)
    try:
        return os.getpriority(os.PRIO_PROCESS, pid)
    except OSError:
        return None
