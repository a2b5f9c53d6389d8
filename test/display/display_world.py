"""The test world as the display tests see it: flat's places and rooms, the chair's footprint,
and the typed-status topics the display is remapped to while the stack still publishes strings
on /safety/status and /kld/localized (the redesign switches them to the typed messages; then
these remaps go)."""
import os

import yaml

from wheelchair_test.harness import worlds_dir

WORLDS = str(worlds_dir())

START = (3.0, 2.2, 0.0)  # living_centre
ROOM_PAD = 0.6  # the display's default room_pad [m]
FOOTPRINT = [(0.30, 0.31), (-0.80, 0.31), (-0.80, -0.31), (0.30, -0.31)]  # chair.yaml
SAFETY_TOPIC = "/display_test/safety_status"
REMAPS = {"safety/status": SAFETY_TOPIC,
          "localization/status": "/display_test/localization_status"}


def places():
    with open(f"{WORLDS}/flat.places.yaml") as f:
        return yaml.safe_load(f)["places"]


def room_box(room):
    """The display's area of `room`: the box around its places grown by ROOM_PAD."""
    xs = [p["x"] for p in places() if p["room"] == room]
    ys = [p["y"] for p in places() if p["room"] == room]
    return min(xs) - ROOM_PAD, min(ys) - ROOM_PAD, max(xs) + ROOM_PAD, max(ys) + ROOM_PAD


def room_point(room):
    """A point inside `room`'s area near its lower edge, clear of its centre's name plate."""
    x0, y0, x1, y1 = room_box(room)
    return (x0 + x1) / 2, y0 + 0.3


def place_xy(name):
    p = next(p for p in places() if p["name"] == name)
    return p["x"], p["y"]


def place_pose(name):
    p = next(p for p in places() if p["name"] == name)
    return p["x"], p["y"], p["yaw"]


def go_button(view, height):
    """The Go button's rectangle (x, y, w, h): the layout's, right of the prompt bar."""
    x0, y0, w, h = view.map_region
    left_w = x0 + w
    pad = max(8, round(0.012 * height))
    prompt_y = y0 + h
    gw = max(220, round(0.3 * left_w))
    return left_w - gw - pad, prompt_y + pad, gw, height - prompt_y - 2 * pad


def back_plate(view):
    """A point on the "All rooms" plate (top left of the map region)."""
    x0, y0, w, h = view.map_region
    return x0 + 40, y0 + 30


def test_output(name, folder=None):
    """The folder for a test's screenshots and logs (`folder`, else $ROS_HOME/<name>), and in it
    a copy of flat's places file for the display (the carer's tools may edit it; the world
    stays as it is)."""
    out = folder or os.path.join(os.environ.get("ROS_HOME", "/tmp"), name)
    os.makedirs(out, exist_ok=True)
    places_copy = os.path.join(out, "flat.places.yaml")
    with open(f"{WORLDS}/flat.places.yaml") as f, open(places_copy, "w") as g:
        g.write(f.read())
    return out, places_copy
