#!/usr/bin/env python3
"""The protective field scales with speed (issue 20): the chair drives the 21 m straight of
`symmetric` at the controller's speed limit `~speed` (0.3, 0.8 or 1.5 m/s); once it drives at
that speed a person appears 5 cm inside the edge of the stop zone that speed needs (the
chair's front + its controlled stop, integrated here from the chair's stopping figures
/safety/field/*, their defaults otherwise + the margin).
The chair stops for the person with the reason told to the rider, and the simulator's contact
check stays clear. With the old fixed 1.2 m field the person at 0.8 and 1.5 m/s is first seen
too late and the chair runs into them."""
import sys
import unittest

import rospy
import rostest
from wheelchair_test.harness import Rider, point_ahead

START = (1.5, 5.0, 0.0)  # room a, facing the corridor
GOAL = (22.0, 5.0, 0.0)  # room b, 20.5 m straight ahead
RADIUS = 0.15  # [m] a person seen from above
INSIDE = 0.05  # [m] the person's front this far inside the stop zone's edge
FIELD = {"reaction_time": 0.3, "brake_decel": 0.5, "brake_jerk": 1.0, "drive_accel": 0.35,
         "margin": 0.2, "front_offset": 0.30}  # the supervisor's defaults (protective_field.h)


def stop_zone(v, f, dt=1e-4):
    """The stop zone's length along the path from the axle centre [m] at speed v: the front,
    the margin, and the controlled stop integrated step by step (worst case: still
    accelerating for the reaction time, then the jerk-limited brake to rest)."""
    s, a, t = 0.0, f["drive_accel"], 0.0
    while t < f["reaction_time"]:
        s, v, t = s + v * dt, v + a * dt, t + dt
    while v > 0.0:
        a = max(-f["brake_decel"], a - f["brake_jerk"] * dt)
        s, v = s + v * dt, v + a * dt
    return f["front_offset"] + s + f["margin"]


class Field(unittest.TestCase):
    def test_person_at_the_edge_of_the_stop_zone_is_not_touched(self):
        speed = rospy.get_param("~speed")
        where = rospy.get_param("~field_namespace", "/safety/field")  # another: the defaults
        field = {k: rospy.get_param(f"{where}/{k}", v) for k, v in FIELD.items()}
        s = Rider()
        self.assertEqual(s.wait_ready(), "")
        self.assertTrue(s.initialize(*START), "not localized: " + s.describe())
        t_go = s.mark()
        s.send_goal(*GOAL)
        self.assertTrue(s.wait(lambda: s.truth is not None and s.truth[4] >= 0.97 * speed, 120.0),
                        f"the chair never reached {speed} m/s: " + s.describe(t_go))
        self.assertFalse(s.first_stop(t_go), "stopped on the way: " + s.describe(t_go))
        plan = s.plans[-1]
        _, x, y, _, v, _ = s.truth
        edge = stop_zone(v, field)
        person = point_ahead(plan, x, y, edge - INSIDE + RADIUS)
        self.assertIsNotNone(person, "plan too short for the test")
        t_person, stop, gap = s.stops_for_person(self, person, RADIUS, field["front_offset"])
        self.assertGreater(gap, 0.0, "no gap left")
        self.assertTrue(s.wait(lambda: s.announced("in the way", t_person), 10.0),
                        "the rider was not told: " + s.describe(t_person))
        rospy.loginfo("field: %.2f m/s, person %.2f m ahead of the axle (stop zone %.2f m), "
                      "stopped with %.2f m between the chair's front and the person (%s)",
                      v, edge - INSIDE + RADIUS, edge, gap, stop.detail)


if __name__ == "__main__":
    rospy.init_node("test_field")
    rostest.rosrun("wheelchair_test", "field", Field, sys.argv)
