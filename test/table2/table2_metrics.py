"""The paper's Table 2 figures (section 5.4), ROS-free.

Definitions (the paper says only "Mean Square Error between the reference input and ..."):
- the reference input is the planned path (/plan, base_link = axle centre P poses), taken as the
  polyline through its poses;
- MSEre (control tracking): the mean over the true trajectory's samples (/sim/ground_truth,
  50 Hz of simulated time) of the squared distance from the sample to the nearest point of the
  polyline, in cm^2;
- MSErc (localization): the same over the localizer's estimates (/kld_pose, one per filter
  update);
- samples count while the chair drives the path: from the controller's first `tracking`
  status to `goal_reached` (standing still at the ends adds no information).
The distance to the nearest point (cross-track error) rather than a time-aligned one: the
controller retimes its reference (speed governor), so a time-aligned error would measure the
schedule, not the path.
"""
import math


def point_segment_distance(p, a, b):
    """Euclidean distance from point p to the segment a-b (2-tuples)."""
    ax, ay = a
    dx, dy = b[0] - ax, b[1] - ay
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0.0 else ((p[0] - ax) * dx + (p[1] - ay) * dy) / length2
    t = min(1.0, max(0.0, t))
    return math.hypot(p[0] - (ax + t * dx), p[1] - (ay + t * dy))


def distance_to_path(p, path):
    """Distance from p to the nearest point of the polyline `path` (list of (x, y))."""
    if not path:
        raise ValueError("empty reference path")
    if len(path) == 1:
        return math.hypot(p[0] - path[0][0], p[1] - path[0][1])
    return min(point_segment_distance(p, path[i], path[i + 1]) for i in range(len(path) - 1))


def mse_cm2(samples, path):
    """Mean squared distance [cm^2] of the (x, y) samples [m] to the polyline path [m]."""
    if not samples:
        raise ValueError("no trajectory samples")
    return sum((100.0 * distance_to_path(s, path)) ** 2 for s in samples) / len(samples)


def mean_std(values):
    """Mean and sample standard deviation (n - 1, as the paper's Std row is read)."""
    n = len(values)
    if n == 0:
        return float("nan"), float("nan")
    mean = sum(values) / n
    if n == 1:
        return mean, 0.0
    return mean, math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1))


def angle_diff(a, b):
    """a - b wrapped to (-pi, pi]."""
    d = math.fmod(a - b, 2.0 * math.pi)
    if d > math.pi:
        d -= 2.0 * math.pi
    elif d <= -math.pi:
        d += 2.0 * math.pi
    return d


def goal_error(final, goal):
    """(position error [m], |heading error| [rad]) of the final pose (x, y, yaw) to the goal."""
    return (math.hypot(final[0] - goal[0], final[1] - goal[1]),
            abs(angle_diff(final[2], goal[2])))


def in_window(stamped, start, end):
    """The (t, x, y, ...) samples with start <= t <= end."""
    return [s for s in stamped if start <= s[0] <= end]


# The paper's Table 2 (cm^2) for the report and the test's limits.
PAPER_TABLE2 = {
    "mse_rc": [6, 3.7, 3.8, 3.9, 5.7, 11.5, 6.5, 5.2, 6, 5.5],
    "mse_re": [11, 13.1, 5.1, 5.1, 8.6, 28.1, 21.7, 3.2, 8.2, 8.5],
    "mean": {"mse_rc": 5.8, "mse_re": 11.2},
    "std": {"mse_rc": 2.2, "mse_re": 7.9},
}
# The paper's Table 1: KLD true pose vs best estimate (cm).
PAPER_TABLE1 = [
    {"iterations": 1, "true": (225, 250), "estimate": (220, 265), "error": 15.8},
    {"iterations": 3, "true": (225, 250), "estimate": (195, 265), "error": 33.5},
    {"iterations": 10, "true": (585, 540), "estimate": (590.3, 527.8), "error": 13.2},
    {"iterations": 20, "true": (540, 910), "estimate": (553.8, 908.8), "error": 13.6},
]
