#!/usr/bin/env python3
"""Faults of the command path on the running chair (the simulator + the one-process chair, as
the demo brings them up), one case per rostest (~case):

- foreign_torques: another node publishes 20 N m on /wheel_torques at 500 Hz to the idle chair
  (it drove 1.84 m/s into a wall): the chair stays put, the stop latches and is told.
- foreign_release: after a latched stop (laser dropout) another node publishes /safety/stop
  false, re-publishes the last /plan and a goal, and calls /base_driver/clear_estop (the chair
  drove 1.12 m): nothing moves; the rider's own choice on the HMI drives again.
- supervisor_unloaded: /wheelchair/unload_nodelet /safety mid-drive (the chair drove on into a
  person): the chair stops without a permit and cannot be driven until a supervisor is back.
- chair_hang / sim_hang: SIGSTOP of the chair process (or of the simulator) for 2 s mid-drive,
  then SIGCONT (the chair moved 0.18 m after the resume): no motion after the resume without a
  new command, and the rider is told why the drive ended.
- corrupt_frames: 1 s of random torque-command frames on the motor bus mid-drive (17
  brake/release cycles, a jolt): one controlled stop, latched, told.
- foreign_switch / foreign_go_to: after a latched stop another node presses /switch through a
  whole choice, or names a place on /hmi/go_to and calls go_to_place (a choice releases the
  stop and drives; the service's foreign call is a goal without release): refused
  and reported, nothing moves; the one expected publisher (/switch_keyboard, /display: played
  by `rostopic pub __name:=...`) is heard.
- foreign_speed_limit: mid-drive another node publishes /safety/speed_limit (a crawl, then a
  raise to 10 m/s) at 100 Hz: refused and reported, the chair drives at its own limits.
- switch_off / computer_power_lost (ISO 7176-14, switch-off while driving): SIGTERM of the chair
  process mid-drive (the orderly switch-off: the driver's last act is the brake), or SIGKILL
  (the chair's computer loses power: the motor controller's 100 ms watchdog brakes): at rest
  within the brake's distance, no motion after, no contact.
- Single faults after ISO 7176-14 (sim/motor_fault on the emulated motor controller):
  power_removed (the motor side loses supply), frozen_encoder (one wheel's encoder stops
  counting), output_fault (the output stage reports overcurrent), command_signal_lost (the
  controller nodelet unloaded: commands stop): each ends in a stop the rider is told.
Each case writes its figures (JSON) to ~result_file if set (bench/faults).
"""
import json
import os
import subprocess
import random
import socket
import struct
import signal
import sys
import time
import unittest
import xmlrpc.client

import rosgraph
import rospy
import rostest
from nav_msgs.msg import Path
from nodelet.srv import NodeletUnload
from rosgraph_msgs.msg import Log
from std_msgs.msg import Bool, Empty, Float64, String
from wheelchair_msgs.msg import HmiState, SafetyStatus, WheelTorques
from wheelchair_sim.srv import EnableLaser, MotorFault

from wheelchair_test.harness import Rider, describe_stop

START = (3.0, 2.2, 0.0)  # living_centre, heading +x
GOAL = "kitchen_door"


def trigger_class():
    """std_srvs/Trigger (Debian has no Python bindings of std_srvs without python3-std-srvs):
    generated from its definition, md5 '*' (roscpp's servers accept it)."""
    import genpy.dynamic

    req = genpy.dynamic.generate_dynamic("std_srvs/TriggerRequest", "")["std_srvs/TriggerRequest"]
    res = genpy.dynamic.generate_dynamic("std_srvs/TriggerResponse",
                                         "bool success\nstring message\n")[
        "std_srvs/TriggerResponse"]

    class Trigger:
        _type = "std_srvs/Trigger"
        _md5sum = "*"
        _request_class = req
        _response_class = res

    return Trigger


def diagnostic_status_class():
    """diagnostic_msgs/DiagnosticStatus (no Python bindings on Debian either), generated from its
    definition, md5 '*' (roscpp's publishers accept it)."""
    import genpy.dynamic

    text = ("byte OK=0\nbyte WARN=1\nbyte ERROR=2\nbyte STALE=3\nbyte level\nstring name\n"
            "string message\nstring hardware_id\nKeyValue[] values\n" + "=" * 80 +
            "\nMSG: diagnostic_msgs/KeyValue\nstring key\nstring value\n")
    cls = genpy.dynamic.generate_dynamic("diagnostic_msgs/DiagnosticStatus", text)[
        "diagnostic_msgs/DiagnosticStatus"]
    cls._md5sum = "*"
    return cls


def pid_of(node):
    """The process id of a ROS node (its XML-RPC getPid)."""
    master = rosgraph.Master("/test_command_path")
    uri = master.lookupNode(node)
    code, _, pid = xmlrpc.client.ServerProxy(uri).getPid("/test_command_path")
    assert code == 1, f"getPid of {node}: {code}"
    return pid


def speed(s):
    return 0.0 if s.truth is None else abs(s.truth[4])


def publish_as(node, topic, kind, value):
    """One message on `topic` from a separate process named `node` (rostopic pub)."""
    subprocess.run(["rostopic", "pub", "-1", topic, kind, value, f"__name:={node}"], check=True,
                   capture_output=True, timeout=60)


class CommandPath(unittest.TestCase):
    def setUp(self):
        self.s = Rider("test_command_path")
        self.errors = []  # (wall time, text) of every error in the log of any node
        self.hmi_states = []
        rospy.Subscriber("/rosout", Log, self._on_log, queue_size=100)  # every node's log
        rospy.Subscriber("/hmi/state", HmiState, self.hmi_states.append, queue_size=100)

    def _on_log(self, msg):
        if msg.level >= Log.ERROR:
            self.errors.append((time.time(), msg.msg))

    def reported(self, *words):
        """An error in the log with all `words` (the refusal names the topic and the sender)."""
        return any(all(w in text for w in words) for _, text in self.errors)

    def latched_stop_at_rest(self):
        """Drives, then a laser dropout: the supervisor's stop latches; the laser is back."""
        s = self.s
        s.start_driving(self, START, GOAL, 1.0)
        laser = rospy.ServiceProxy("/sim/enable_laser", EnableLaser)
        since = s.mark()
        self.assertTrue(laser(False).success)
        self.assertTrue(s.wait(lambda: s.first_stop(since), 30.0), "no stop: " + s.describe(since))
        self.assertTrue(s.wait(s.at_rest, 30.0), "still moving: " + s.describe(since))
        self.assertTrue(laser(True).success)
        s.sim_sleep(1.0)
        return since

    def ready(self):
        s = self.s
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())

    def stopped_and_told(self, since, what):
        """At rest, a stop told to the rider (the supervisor's status or the controller's end),
        and no motion for 3 s after."""
        s = self.s
        self.assertTrue(s.wait(s.at_rest, 30.0), f"{what}: still moving: " + s.describe(since))
        rest = rospy.get_time()
        told = lambda: s.first_stop(since) or s.controller_says("aborted", since)  # noqa: E731
        self.assertTrue(s.wait(told, 10.0), f"{what}: no stop told: " + s.describe(since))
        s.sim_sleep(3.0)
        self.assertLess(s.travelled(rest), 0.03, f"{what}: moved again without a command: " +
                        s.describe(since))
        self.assertFalse(s.collided)
        return rest

    def test_command_path_fault(self):
        case = rospy.get_param("~case")
        self.figures = {"case": case}
        getattr(self, "case_" + case)()
        path = rospy.get_param("~result_file", "")
        if path:
            with open(path, "w") as f:
                json.dump(self.figures, f)

    def record_stop(self, t0, since):
        """The figures of a stop that began at `t0`: distance travelled, the reason told."""
        s = self.s
        stop = s.first_stop(since)
        told = describe_stop(stop[1]) if stop else ""
        if not told:
            told = next((c for _, c in s.received("controller", since) if c.startswith("aborted")),
                        "")
        self.figures.update({
            "travelled_m": round(s.travelled(t0), 3),
            "stop_told": told,
            "sentence": stop[1].sentence if stop else "",
        })

    # ---- item 1: only the chair's own controller commands the motors ------------------------
    def case_foreign_torques(self):
        s = self.s
        self.ready()
        pub = rospy.Publisher("/wheel_torques", WheelTorques, queue_size=100, tcp_nodelay=True)
        time.sleep(1.0)  # connections
        since = s.mark()
        t0 = rospy.get_time()
        end = time.time() + 2.0
        while time.time() < end:  # 500 Hz of wall time, 20 N m each wheel
            m = WheelTorques()
            m.header.stamp = rospy.Time.now()
            m.left = m.right = 20.0
            pub.publish(m)
            time.sleep(0.002)
        s.sim_sleep(1.0)
        self.assertLess(s.travelled(t0), 0.03, "another node drove the chair: " + s.describe(since))
        self.assertTrue(s.wait(lambda: s.first_stop(since), 10.0),
                        "the foreign command was not told: " + s.describe(since))
        _, stop = s.first_stop(since)
        self.assertEqual(stop.reason, SafetyStatus.DRIVER_FAULT, describe_stop(stop))
        self.assertIn("another program", stop.sentence, describe_stop(stop))
        self.record_stop(t0, since)
        rospy.loginfo("foreign torques: travelled %.3f m; %s", s.travelled(t0), describe_stop(stop))

    # ---- item 2: the latch is released only by the rider ------------------------------------
    def case_foreign_release(self):
        s = self.s
        s.start_driving(self, START, GOAL, 1.0)
        laser = rospy.ServiceProxy("/sim/enable_laser", EnableLaser)
        since = s.mark()
        self.assertTrue(laser(False).success)
        self.assertTrue(s.wait(lambda: s.first_stop(since), 30.0), "no stop: " + s.describe(since))
        self.assertTrue(s.wait(s.at_rest, 30.0), "still moving: " + s.describe(since))
        self.assertTrue(laser(True).success)
        s.sim_sleep(1.0)
        # Everything another node can do.
        stop_pub = rospy.Publisher("/safety/stop", Bool, queue_size=1)
        plan_pub = rospy.Publisher("/plan", Path, queue_size=1)
        time.sleep(1.0)
        foreign = rospy.get_time()
        stop_pub.publish(Bool(False))
        if s.plans:
            plan = s.plans[-1]
            plan.header.stamp = rospy.Time.now()
            plan_pub.publish(plan)
        x, y = s.truth[1] + 2.0, s.truth[2]
        s.send_goal(x, y, 0.0)
        clear = rospy.ServiceProxy("/base_driver/clear_estop", trigger_class())()
        self.assertFalse(clear.success, clear.message)
        self.assertIn("only the rider", clear.message)
        s.sim_sleep(4.0)
        foreign_travel = s.travelled(foreign)
        self.assertLess(foreign_travel, 0.03,
                        "a foreign release drove the chair: " + s.describe(since))
        last = s.received("safety", since)[-1][1]
        self.assertTrue(last.stop, "the supervisor's stop was lifted: " + describe_stop(last))
        # The rider's own choice (the HMI) releases it.
        go = s.mark()
        accepted, message = s.go_to_place(GOAL)
        self.assertTrue(accepted, message)
        self.assertTrue(s.wait(lambda: s.travelled(go) > 0.3, 60.0),
                        "the rider's release did not drive: " + s.describe(go))
        self.figures.update({"travelled_m": round(foreign_travel, 3),
                             "rider_release_drove_m": round(s.travelled(go), 3),
                             "stop_told": describe_stop(last), "sentence": last.sentence})
        rospy.loginfo("foreign release: %.3f m after the foreign release, %.2f m after the rider's",
                      foreign_travel, s.travelled(go))

    # ---- the rider's inputs and the supervisor's limit: their one publisher only ------------
    def case_foreign_switch(self):
        s = self.s
        since = self.latched_stop_at_rest()
        me = rospy.get_name()
        foreign = rospy.get_time()
        # Presses through a whole choice (room, place, confirm at the 2 s scan): unguarded, they
        # choose a destination, which releases the stop and drives.
        for _ in range(6):
            s.press()
            s.sim_sleep(1.3)
        s.sim_sleep(3.0)
        travel = s.travelled(foreign)
        self.assertLess(travel, 0.03, "another node's presses drove the chair: " + s.describe(since))
        last = s.received("safety", since)[-1][1]
        self.assertTrue(last.stop, "the stop was lifted: " + describe_stop(last))
        self.assertTrue(s.wait(lambda: self.reported("/switch", me, "refused"), 10.0),
                        "the foreign presses were not reported: %s" % self.errors[-5:])
        self.assertFalse(any(m.state != HmiState.SCANNING_ROOMS for m in self.hmi_states[-5:]),
                         "the HMI took a foreign press")
        # The rider's own switch is heard: a press chooses the highlighted room.
        n = len(self.hmi_states)
        publish_as("switch_keyboard", "/switch", "std_msgs/Empty", "{}")
        self.assertTrue(s.wait(lambda: any(m.state == HmiState.SCANNING_PLACES
                                           for m in self.hmi_states[n:]), 10.0),
                        "the rider's switch was not heard")
        self.figures.update({"travelled_m": round(travel, 3), "stop_told": describe_stop(last),
                             "sentence": last.sentence})

    def case_foreign_go_to(self):
        s = self.s
        since = self.latched_stop_at_rest()
        me = rospy.get_name()
        pub = rospy.Publisher("/hmi/go_to", String, queue_size=1)
        time.sleep(1.0)  # connections
        foreign = rospy.get_time()
        pub.publish(String(GOAL))
        # The go_to_place service from a node other than the rider's display (this one): a goal
        # like rviz's, which never releases the stop.
        s.go_to_place(GOAL)
        s.sim_sleep(4.0)
        travel = s.travelled(foreign)
        self.assertLess(travel, 0.03, "another node's choice drove the chair: " + s.describe(since))
        last = s.received("safety", since)[-1][1]
        self.assertTrue(last.stop, "the stop was lifted: " + describe_stop(last))
        self.assertTrue(s.wait(lambda: self.reported("/hmi/go_to", me, "refused"), 10.0),
                        "the foreign choice was not reported: %s" % self.errors[-5:])
        self.assertTrue(s.wait(lambda: self.reported("go_to_place", me, "refused"), 10.0),
                        "the foreign go_to_place was not reported: %s" % self.errors[-5:])
        # Its one publisher (the rider's display) is heard: the chair drives again.
        go = s.mark()
        publish_as("display", "/hmi/go_to", "std_msgs/String", GOAL)
        self.assertTrue(s.wait(lambda: s.travelled(go) > 0.3, 60.0),
                        "the display's choice did not drive: " + s.describe(go))
        self.figures.update({"travelled_m": round(travel, 3), "stop_told": describe_stop(last),
                             "sentence": last.sentence})

    def case_foreign_speed_limit(self):
        s = self.s
        # The supervisor's own limit (its topic, from the chair process) and the limit the base
        # driver holds (its permits carry it; ~status says which): the driver's is the
        # supervisor's, never another node's.
        own, held = [], []

        def on_limit(msg, _=None):
            if msg._connection_header.get("callerid") == "/wheelchair":
                own.append(msg.data)

        def on_status(msg):
            held.extend(float(kv.value) for kv in msg.values
                        if kv.key == "safety speed limit held [m/s]")

        rospy.Subscriber("/safety/speed_limit", Float64, on_limit, queue_size=100)
        rospy.Subscriber("/base_driver/status", diagnostic_status_class(), on_status,
                         queue_size=100)
        s.start_driving(self, START, GOAL, 1.0)
        me = rospy.get_name()
        pub = rospy.Publisher("/safety/speed_limit", Float64, queue_size=10, tcp_nodelay=True)
        time.sleep(1.0)  # connections
        since = s.mark()
        t0 = rospy.get_time()
        v0 = speed(s)
        slowest = fastest = v0
        for limit in (0.05, 10.0):  # a crawl (unguarded: 0.05 m/s), then a raise
            end = time.time() + 3.0
            while time.time() < end:  # 100 Hz of wall time
                pub.publish(Float64(limit))
                v = speed(s)
                slowest, fastest = min(slowest, v), max(fastest, v)
                time.sleep(0.01)
        self.assertFalse(s.first_stop(since), "stopped: " + s.describe(since))
        # Taken, the crawl would slow the chair to 0.05 m/s within 1 s (its 0.5 m/s^2 stop);
        # the turn into the kitchen alone slows it to about 0.28.
        self.assertGreater(slowest, 0.15, "another node's limit slowed the chair: " +
                           s.describe(since))
        # The controller's own comfort limit (0.8 m/s) holds: the raise changed nothing.
        self.assertLess(fastest, 0.85, "another node's limit sped the chair up")
        self.assertTrue(s.wait(lambda: self.reported("/safety/speed_limit", me, "refused"), 10.0),
                        "the foreign limit was not reported: %s" % self.errors[-5:])
        driving = [h for h in held if h < 1e9]
        if any(x < 1e9 for x in own):  # the field limited the drive: the driver held it too
            self.assertTrue(driving, "the driver never held the supervisor's limit: %s" % held)
        if own:  # another node's crawl (0.05 m/s) is no limit of the driver's
            self.assertGreaterEqual(min(held), min(own) - 1e-3, "the driver held another node's "
                                    "limit: %s (the supervisor's %s)" % (min(held), min(own)))
        self.figures.update({"driver_limit_mps": round(min(driving), 2) if driving else None,
                             "supervisor_limit_mps": round(min(own), 2) if own else None})
        self.figures.update({"speed_mps": round(v0, 2), "slowest_mps": round(slowest, 2),
                             "fastest_mps": round(fastest, 2),
                             "travelled_m": round(s.travelled(t0), 3)})

    # ---- item 2: unloading the supervisor stops the chair -----------------------------------
    def case_supervisor_unloaded(self):
        s = self.s
        s.start_driving(self, START, GOAL, 1.0)
        since = s.mark()
        v0 = speed(s)
        t0 = rospy.get_time()
        unload = rospy.ServiceProxy("/wheelchair/unload_nodelet", NodeletUnload)
        self.assertTrue(unload("/safety").success)
        rest = self.stopped_and_told(since, "supervisor unloaded")
        self.record_stop(t0, since)
        self.figures.update({"speed_mps": round(v0, 2), "at_rest_s": round(rest - t0, 2)})
        self.assertLess(s.travelled(t0), 0.6, "braking distance: " + s.describe(since))
        # No supervisor, no permit: the rider's command cannot drive either.
        go = s.mark()
        s.go_to_place(GOAL)
        s.sim_sleep(4.0)
        self.assertLess(s.travelled(go), 0.03, "drove without a supervisor: " + s.describe(go))
        rospy.loginfo("supervisor unloaded at %.2f m/s: at rest after %.2f s, %.3f m", v0,
                      rest - t0, s.travelled(t0))

    # ---- item 3: no stale motion after a hang -----------------------------------------------
    def hang(self, node):
        s = self.s
        s.start_driving(self, START, GOAL, 1.0)
        since = s.mark()
        pid = pid_of(node)
        os.kill(pid, signal.SIGSTOP)
        try:
            time.sleep(2.0)
        finally:
            os.kill(pid, signal.SIGCONT)
        resumed_wall = time.time()
        while rospy.get_time() <= time_of_mark(since) and time.time() < resumed_wall + 10:
            time.sleep(0.01)
        resumed = rospy.get_time()
        v_resume = speed(s)
        rest = self.stopped_and_told(since, node + " hang")
        after = s.travelled(resumed)
        self.record_stop(resumed, since)
        self.figures.update({"speed_at_resume_mps": round(v_resume, 2),
                             "at_rest_after_resume_s": round(rest - resumed, 2)})
        rospy.loginfo("%s hang: %.2f m/s at the resume, %.3f m after it, at rest %.2f s after",
                      node, v_resume, after, rest - resumed)
        return v_resume, after

    def case_chair_hang(self):
        # The motor side brakes within its 0.1 s watchdog during the hang; after the resume no
        # queued or stale command moves the chair.
        v, after = self.hang("/wheelchair")
        self.assertLess(after, 0.03, "moved after the resume: " + self.s.describe())

    def case_sim_hang(self):
        # The simulated world stood still with the chair moving: after the resume it may only
        # brake (v^2 / 2a at the chair's 1.0 m/s^2 braking, plus 0.1 s of reaction), never drive.
        v, after = self.hang("/simulator")
        self.assertLess(after, v * v / 2.0 + 0.1 * v + 0.03, "drove on after the resume")


    # ---- item 4: a corrupted command stream is one latched stop ------------------------------
    def case_corrupt_frames(self):
        s = self.s
        s.start_driving(self, START, GOAL, 1.0)
        since = s.mark()
        v0, t0 = speed(s), rospy.get_time()
        port = rospy.get_param("~motor_port")
        sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        rng = random.Random(20)
        end = time.time() + 1.0
        while time.time() < end:  # torque-command frames with random payloads (bad CRC)
            frame = b"WC" + bytes([0, 8]) + struct.pack("<I", 0x110) + rng.randbytes(8)
            sock.sendto(frame, ("127.0.0.1", port))
            time.sleep(0.002)
        rest = self.stopped_and_told(since, "corrupt frames")
        self.record_stop(t0, since)
        stops = s.stops(since)
        self.assertEqual(len(stops), 1, "not one stop: %s" % stops)
        self.assertEqual(s.first_stop(since)[1].reason, SafetyStatus.DRIVER_FAULT, stops)
        self.figures.update({"speed_mps": round(v0, 2), "at_rest_s": round(rest - t0, 2),
                             "stops": len(stops)})

    # ---- switch-off while driving (ISO 7176-14) ----------------------------------------------
    def switch_off(self, sig, what):
        s = self.s
        s.start_driving(self, START, GOAL, 1.0)
        pid = pid_of("/wheelchair")
        v0, t0 = speed(s), rospy.get_time()
        os.kill(pid, sig)
        self.assertTrue(s.wait(s.at_rest, 30.0), f"{what}: still moving: " + s.describe())
        rest = rospy.get_time()
        travelled = s.travelled(t0)
        s.sim_sleep(3.0)
        self.assertLess(s.travelled(rest), 0.03, f"{what}: moved again: " + s.describe())
        self.assertFalse(s.collided)
        # The motor controller's brake (>= 2 m/s^2; measured 4) after at most its 0.1 s
        # watchdog, + 3 cm.
        self.assertLess(travelled, 0.1 * v0 + v0 * v0 / 4.0 + 0.03, f"{what}: too far")
        self.figures.update({"speed_mps": round(v0, 2), "at_rest_s": round(rest - t0, 2),
                             "travelled_m": round(travelled, 3),
                             "stop_told": "(the chair process is off: the motors brake)"})
        rospy.loginfo("%s at %.2f m/s: at rest after %.2f s, %.3f m", what, v0, rest - t0,
                      travelled)

    def case_switch_off(self):
        self.switch_off(signal.SIGTERM, "switch-off")

    def case_computer_power_lost(self):
        self.switch_off(signal.SIGKILL, "computer power lost")

    # ---- item 7: single faults after ISO 7176-14 --------------------------------------------
    def motor_fault(self, fault, what):
        s = self.s
        s.start_driving(self, START, GOAL, 1.0)
        since = s.mark()
        v0, t0 = speed(s), rospy.get_time()
        answer = rospy.ServiceProxy("/sim/motor_fault", MotorFault)(fault)
        self.assertTrue(answer.success, answer.message)
        rest = self.stopped_and_told(since, what)
        self.record_stop(t0, since)
        self.figures.update({"speed_mps": round(v0, 2), "at_rest_s": round(rest - t0, 2)})
        # v^2 / 2a at 1 m/s^2 braking + 0.3 s of detection at v, + 5 cm
        self.assertLess(s.travelled(t0), v0 * v0 / 2.0 + 0.3 * v0 + 0.05, what)
        return since

    def case_power_removed(self):
        self.motor_fault("power_off", "power removed")

    def case_frozen_encoder(self):
        # The driver's own check, before the localizer loses the chair (0.32 m at 0.7 m/s when
        # the localizer noticed first): the other wheel turns at most 0.25 rad (r 0.17 m:
        # 4.3 cm), 0.1 s of frames and latching, then the motor controller's brake (>= 2 m/s^2;
        # measured 4), + 3 cm.
        s = self.s
        since = self.motor_fault("freeze_left_encoder", "frozen encoder")
        v0, travelled = self.figures["speed_mps"], self.figures["travelled_m"]
        self.assertLess(travelled, 0.25 * 0.17 + 0.1 * v0 + v0 * v0 / 4.0 + 0.03,
                        "frozen encoder: too far: " + s.describe(since))
        _, stop = s.first_stop(since)
        self.assertEqual(stop.reason, SafetyStatus.DRIVER_FAULT, describe_stop(stop))
        self.assertEqual(stop.sentence, "a wheel sensor failed", describe_stop(stop))

    def case_output_fault(self):
        self.motor_fault("overcurrent_left", "output stage fault")

    def case_command_signal_lost(self):
        s = self.s
        s.start_driving(self, START, GOAL, 1.0)
        since = s.mark()
        v0, t0 = speed(s), rospy.get_time()
        unload = rospy.ServiceProxy("/wheelchair/unload_nodelet", NodeletUnload)
        self.assertTrue(unload("/controller").success)
        rest = self.stopped_and_told(since, "command signal lost")
        self.record_stop(t0, since)
        self.figures.update({"speed_mps": round(v0, 2), "at_rest_s": round(rest - t0, 2)})


def time_of_mark(mark):
    return mark.time if hasattr(mark, "time") else float(mark)


if __name__ == "__main__":
    rostest.rosrun("wheelchair_test", "command_path", CommandPath, sys.argv)
