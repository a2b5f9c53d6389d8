#!/usr/bin/env python3
"""rostest: `snapshot` renders a known map published on /map, and the PNG shows that map.

The map (12 m x 10 m, 5 cm cells) is free inside a 20 cm wall, with a 2 m x 2 m occupied
block at its centre. Viewed top-down at SCALE px/m, rviz must draw the free area as a bright
rectangle of the map's inner size times SCALE, with the dark block at its centre. A robot (one
cyan box, 20 cm high, centred at z = 0 like a chair's base_link) stands at ROBOT_XY: it must be
drawn over the map at the right place, not hidden by it.
"""
import os
import pathlib
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np
import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import OccupancyGrid

WIDTH, HEIGHT, RES, WALL, BLOCK = 12.0, 10.0, 0.05, 0.2, 2.0
SCALE = 40.0  # px / m
BACKGROUND = (48, 48, 48)  # rviz background colour of config/wheelchair.rviz
ROBOT_XY, ROBOT_SIZE = (3.0, 7.0), 0.6  # [m] in the map frame
# Like the chair's URDF: a root link base_footprint that no tf reaches (odom -> base_link is
# the stack's convention), a box in base_link.
ROBOT_URDF = f"""<robot name="box"><link name="base_footprint"/><link name="base_link"><visual>
<geometry><box size="{ROBOT_SIZE} {ROBOT_SIZE} 0.2"/></geometry><material name="cyan">
<color rgba="0 1 1 1"/></material></visual></link><joint name="j" type="fixed">
<parent link="base_footprint"/><child link="base_link"/><origin xyz="0 0 0.17"/></joint></robot>"""


def test_map():
    nx, ny = int(round(WIDTH / RES)), int(round(HEIGHT / RES))
    grid = np.zeros((ny, nx), dtype=np.int8)
    w = int(round(WALL / RES))
    grid[:w, :] = grid[-w:, :] = grid[:, :w] = grid[:, -w:] = 100
    b0x, b0y = int(round((WIDTH - BLOCK) / 2 / RES)), int(round((HEIGHT - BLOCK) / 2 / RES))
    b = int(round(BLOCK / RES))
    grid[b0y:b0y + b, b0x:b0x + b] = 100
    msg = OccupancyGrid()
    msg.header.frame_id = "map"
    msg.header.stamp = rospy.Time.now()
    msg.info.resolution = RES
    msg.info.width, msg.info.height = nx, ny
    msg.info.origin.orientation.w = 1.0
    msg.data = grid.flatten().tolist()
    return msg


def robot_pose():
    """Static tf map -> base_link placing the robot at ROBOT_XY."""
    t = TransformStamped()
    t.header.stamp = rospy.Time.now()
    t.header.frame_id, t.child_frame_id = "map", "base_link"
    t.transform.translation.x, t.transform.translation.y = ROBOT_XY
    t.transform.rotation.w = 1.0
    return t


def read_png(path):
    """RGB array of a PNG, decoded by ImageMagick (no imaging module needed)."""
    ppm = subprocess.run(["/usr/bin/convert", str(path), "-depth", "8", "ppm:-"], check=True,
                         capture_output=True).stdout
    parts = ppm.split(maxsplit=4)  # P6 width height maxval data
    width, height = int(parts[1]), int(parts[2])
    return np.frombuffer(parts[4][: width * height * 3], dtype=np.uint8).reshape(height, width, 3)


def render_area(image):
    """The part of the screen rviz renders into, so that the white Qt panels are not taken for
    free space: the rows and columns that are largely rviz's background colour (the test's view
    leaves a background margin around the map)."""
    background = np.all(image == BACKGROUND, axis=2)
    rows = np.nonzero(background.mean(axis=1) > 0.2)[0]
    cols = np.nonzero(background.mean(axis=0) > 0.2)[0]
    if len(rows) == 0 or len(cols) == 0:
        return image[:0, :0]
    return image[rows.min():rows.max() + 1, cols.min():cols.max() + 1]


def bright_neutral(image):
    """Pixels of a free cell in rviz's map colour scheme: light and grey."""
    return (image.min(axis=2) > 200) & (image.max(axis=2) - image.min(axis=2) < 20)


class SnapshotShowsTheMap(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("snapshot_test")
        cls.publisher = rospy.Publisher("/map", OccupancyGrid, queue_size=1, latch=True)
        cls.publisher.publish(test_map())
        rospy.set_param("/robot_description", ROBOT_URDF)
        cls.broadcaster = tf2_ros.StaticTransformBroadcaster()
        cls.broadcaster.sendTransform(robot_pose())
        cls.tmp = tempfile.TemporaryDirectory()
        cls.png = pathlib.Path(cls.tmp.name) / "map.png"
        started = time.monotonic()
        cls.result = subprocess.run(
            [sys.executable, os.environ["SNAPSHOT"], "--out", str(cls.png), "--seconds", "5",
             "--view", f"{WIDTH / 2},{HEIGHT / 2},{SCALE}"], capture_output=True, text=True, timeout=180)
        cls.seconds = time.monotonic() - started
        print(f"snapshot took {cls.seconds:.1f} s: {cls.result.stdout}{cls.result.stderr}")

    def test_snapshot_succeeds_and_writes_a_png(self):
        self.assertEqual(self.result.returncode, 0, self.result.stderr)
        self.assertTrue(self.png.is_file())
        self.assertEqual(self.png.read_bytes()[:8], b"\x89PNG\r\n\x1a\n")

    def test_png_is_not_blank(self):
        image = read_png(self.png).astype(float)
        self.assertGreater(image.std(), 20.0, "the frame is (nearly) one colour")

    def test_free_space_is_a_bright_rectangle_of_the_map_size(self):
        image = render_area(read_png(self.png).astype(int))
        self.assertGreater(image.size, 0, "no rviz render area (background colour) on the screen")
        bright = bright_neutral(image)
        ys, xs = np.nonzero(bright)
        self.assertGreater(len(xs), 0, "no free-space pixels")
        width_px, height_px = xs.max() - xs.min() + 1, ys.max() - ys.min() + 1
        inner_w, inner_h = (WIDTH - 2 * WALL) * SCALE, (HEIGHT - 2 * WALL) * SCALE
        self.assertAlmostEqual(width_px, inner_w, delta=6)
        self.assertAlmostEqual(height_px, inner_h, delta=6)
        free_px = (WIDTH - 2 * WALL) * (HEIGHT - 2 * WALL) - BLOCK * BLOCK
        self.assertAlmostEqual(bright.sum() / (free_px * SCALE * SCALE), 1.0, delta=0.05)

    def test_occupied_block_is_dark_at_the_centre_of_the_free_space(self):
        image = render_area(read_png(self.png).astype(int))
        self.assertGreater(image.size, 0, "no rviz render area (background colour) on the screen")
        bright = bright_neutral(image)
        ys, xs = np.nonzero(bright)
        cx, cy = (xs.min() + xs.max()) // 2, (ys.min() + ys.max()) // 2
        half = int(BLOCK * SCALE / 2) - 4
        block = image[cy - half:cy + half, cx - half:cx + half]
        self.assertLess(block.max(), 40, "the centre block is not drawn dark")
        wall = image[ys.min() - 3, cx]  # just outside the free space: the wall
        self.assertLess(wall.max(), 40)

    def test_robot_is_drawn_over_the_map_where_it_stands(self):
        image = render_area(read_png(self.png).astype(int))
        ys, xs = np.nonzero(bright_neutral(image))
        # The free space starts at (WALL, WALL): its lower-left corner is (xs.min(), ys.max()).
        px = xs.min() + (ROBOT_XY[0] - WALL) * SCALE
        py = ys.max() - (ROBOT_XY[1] - WALL) * SCALE
        half = int(0.8 * ROBOT_SIZE * SCALE / 2)  # the box's core, clear of its edges
        core = image[int(py) - half:int(py) + half, int(px) - half:int(px) + half]
        cyan = (core[..., 0] < 80) & (core[..., 1] > 150) & (core[..., 2] > 150)
        self.assertGreater(cyan.mean(), 0.8, "the robot is hidden by the map or drawn elsewhere")


if __name__ == "__main__":
    rostest.rosrun("wheelchair_bringup", "snapshot_shows_the_map", SnapshotShowsTheMap)
