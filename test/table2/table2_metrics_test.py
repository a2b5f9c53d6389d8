#!/usr/bin/python3
"""Unit test of the Table 2 metrics against hand-computed values (no ROS needed)."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import table2_metrics as m  # noqa: E402


class Table2Metrics(unittest.TestCase):
    def test_distance_to_a_segment_interior_and_beyond_its_ends(self):
        self.assertAlmostEqual(m.point_segment_distance((0.5, 0.3), (0, 0), (1, 0)), 0.3)
        self.assertAlmostEqual(m.point_segment_distance((2.0, 0.0), (0, 0), (1, 0)), 1.0)
        self.assertAlmostEqual(m.point_segment_distance((-3, 4), (0, 0), (1, 0)), 5.0)
        self.assertAlmostEqual(m.point_segment_distance((1, 1), (0, 0), (0, 0)), math.sqrt(2))

    def test_distance_to_an_l_shaped_path_takes_the_nearest_leg(self):
        path = [(0, 0), (2, 0), (2, 2)]
        self.assertAlmostEqual(m.distance_to_path((1.0, 0.1), path), 0.1)
        self.assertAlmostEqual(m.distance_to_path((1.8, 1.0), path), 0.2)
        self.assertAlmostEqual(m.distance_to_path((2.3, -0.4), path), 0.5)

    def test_mse_in_square_centimetres(self):
        path = [(0, 0), (10, 0)]
        samples = [(1, 0.01), (2, -0.03), (3, 0.0), (4, 0.02)]  # 1, 9, 0, 4 cm^2
        self.assertAlmostEqual(m.mse_cm2(samples, path), 14.0 / 4)
        with self.assertRaises(ValueError):
            m.mse_cm2([], path)

    def test_mean_and_sample_std_reproduce_the_papers_table(self):
        for key in ("mse_rc", "mse_re"):
            mean, std = m.mean_std(m.PAPER_TABLE2[key])
            self.assertAlmostEqual(mean, m.PAPER_TABLE2["mean"][key], delta=0.1)  # the paper rounds
            self.assertAlmostEqual(std, m.PAPER_TABLE2["std"][key], delta=0.1)  # the paper rounds

    def test_goal_error_wraps_the_heading(self):
        pos, yaw = m.goal_error((1.0, 2.0, math.pi - 0.05), (1.03, 2.04, -math.pi + 0.05))
        self.assertAlmostEqual(pos, 0.05)
        self.assertAlmostEqual(yaw, 0.10)

    def test_window_keeps_the_samples_inside(self):
        samples = [(t, 0.0, 0.0) for t in (0.0, 1.0, 2.0, 3.0)]
        self.assertEqual([s[0] for s in m.in_window(samples, 1.0, 2.0)], [1.0, 2.0])


if __name__ == "__main__":
    import rosunit
    rosunit.unitrun("wheelchair_test", "table2_metrics", Table2Metrics)
