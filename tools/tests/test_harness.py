"""wheelchair_test.harness without a chair: processes are stopped (also one that ignores SIGINT,
and the children of its group) and reaped, a dead process is named with its log, ports are
free, and a master of the run's own answers and takes parameters."""
import os
import pathlib
import shutil
import sys
import tempfile
import time
import unittest
import xmlrpc.client

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "test" / "src"))
from wheelchair_test.harness import (  # noqa: E402
    ProcessError, Processes, free_udp_ports, master_online, start_master)

PYTHON = "/usr/bin/python3"
IGNORES_SIGINT = "import signal, time; signal.signal(signal.SIGINT, signal.SIG_IGN); time.sleep(60)"


def alive(pid):
    try:
        os.kill(pid, 0)
        return True
    except ProcessLookupError:
        return False


class Harness(unittest.TestCase):
    def setUp(self):
        self.logs = tempfile.mkdtemp(prefix="harness_test_")
        self.processes = Processes(self.logs, grace=1.0)

    def tearDown(self):
        self.processes.stop_all()
        shutil.rmtree(self.logs, ignore_errors=True)

    def test_a_process_that_ignores_sigint_is_stopped_and_reaped(self):
        popen = self.processes.start("stubborn", [PYTHON, "-c", IGNORES_SIGINT])
        time.sleep(0.5)  # its handler is installed
        started = time.monotonic()
        self.processes.stop_all()
        self.assertLess(time.monotonic() - started, 5.0)
        self.assertIsNotNone(popen.returncode)  # reaped: no zombie left
        self.assertFalse(alive(popen.pid))

    def test_the_whole_process_group_is_stopped(self):
        marker = pathlib.Path(self.logs) / "child.pid"
        self.processes.start("parent", ["bash", "-c", f"sleep 60 & echo $! > {marker}; wait"])
        self.processes.wait_for("the child", marker.exists, 5.0)
        time.sleep(0.2)
        child = int(marker.read_text())
        self.processes.stop_all()
        deadline = time.monotonic() + 3.0
        while alive(child) and time.monotonic() < deadline:
            time.sleep(0.05)
        self.assertFalse(alive(child))

    def test_a_dead_process_is_named_with_its_code_and_log(self):
        self.processes.start("failing", ["bash", "-c", "echo no map file >&2; exit 3"])
        with self.assertRaises(ProcessError) as raised:
            self.processes.wait_for("something", lambda: False, 5.0, watch=["failing"])
        self.assertIn("failing exited with code 3: no map file", str(raised.exception))
        self.assertEqual(self.processes.ended(), ("failing", 3))

    def test_a_wait_that_times_out_says_what_it_waited_for(self):
        with self.assertRaises(ProcessError) as raised:
            self.processes.wait_for("the laser", lambda: False, 0.2)
        self.assertIn("waiting for the laser", str(raised.exception))

    def test_udp_ports_are_distinct(self):
        ports = free_udp_ports(2)
        self.assertEqual(len(set(ports)), 2)

    @unittest.skipUnless(shutil.which("rosmaster"), "no rosmaster")
    def test_a_master_of_its_own_answers_and_takes_use_sim_time(self):
        uri = start_master(self.processes, use_sim_time=True)
        self.assertTrue(master_online(uri))
        self.assertEqual(self.processes.env["ROS_MASTER_URI"], uri)
        code, _, value = xmlrpc.client.ServerProxy(uri).getParam("/test", "/use_sim_time")
        self.assertEqual((code, value), (1, True))
        self.processes.stop_all()
        self.assertFalse(master_online(uri))


if __name__ == "__main__":
    unittest.main()
