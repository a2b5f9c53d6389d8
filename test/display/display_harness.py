"""The rider's display under test: the real `display` node in a real X server (xvfb-run picks a
free one), driven like a person would drive it (xdotool moves and clicks the pointer), seen
through screenshots of the X server (ImageMagick's `import`), and measured in pixels: where the
map, the chair, the highlight are, how tall and how contrasted the status line is.

The display publishes how it draws the map (~view: scale, rotation, centres, map region), so a
world point (the simulator's truth, a place) can be found on the screen independently of what
was drawn there. Test-only code: it lives beside the tests, not in the package."""
import os
import signal
import subprocess
import tempfile
import time

import numpy as np
import rospy
from PIL import Image, ImageFont
from std_msgs.msg import Float64MultiArray, String

FONT_BOLD = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf"

# The themes' colours the tests look for (src/core/theme.cpp).
THEMES = {
    "dark": {"background": (0, 0, 0), "status_text": (255, 255, 255), "floor": (0x2E, 0x2E, 0x2E),
             "wall": (0xA6, 0xA6, 0xA6), "chair_fill": (0xFF, 0x66, 0xCC),
             "highlight_background": (0xFF, 0xD4, 0x00),
             "highlight_frames": [(0xFF, 0xD4, 0x00), (0xFF, 0xFF, 0xFF)],
             "stop_background": (0xD4, 0, 0), "button_background": (255, 255, 255)},
    "light": {"background": (255, 255, 255), "status_text": (0, 0, 0),
              "floor": (0xF5, 0xF5, 0xF5), "wall": (0x1A, 0x1A, 0x1A),
              "chair_fill": (0xC2, 0x18, 0x5B), "highlight_background": (0xFF, 0xD4, 0x00),
              "highlight_frames": [(0, 0, 0), (0xB3, 0x59, 0x00)],
              "stop_background": (0xB0, 0, 0), "button_background": (0, 0, 0)},
}


def luminance(rgb):
    """WCAG relative luminance."""
    c = np.asarray(rgb, dtype=float) / 255.0
    c = np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)
    return 0.2126 * c[..., 0] + 0.7152 * c[..., 1] + 0.0722 * c[..., 2]


def contrast(a, b):
    la, lb = luminance(a), luminance(b)
    return (max(la, lb) + 0.05) / (min(la, lb) + 0.05)


def colour_mask(image, rgb, tolerance=12):
    """Pixels of `image` (H x W x 3) within `tolerance` of `rgb` in every channel."""
    return np.all(np.abs(image.astype(int) - np.asarray(rgb, dtype=int)) <= tolerance, axis=2)


class View:
    """The display's map view: world (map frame, m) <-> screen (px, y down)."""

    def __init__(self, values):
        self.values = tuple(values)
        (self.scale, self.rotation, wx, wy, sx, sy, mx, my, mw, mh) = values
        self.world_centre = np.array([wx, wy])
        self.screen_centre = np.array([sx, sy])
        self.map_region = (int(mx), int(my), int(mw), int(mh))

    def to_screen(self, x, y):
        c, s = np.cos(self.rotation), np.sin(self.rotation)
        d = np.array([x, y]) - self.world_centre
        q = np.array([c * d[0] - s * d[1], s * d[0] + c * d[1]])
        return self.screen_centre + self.scale * np.array([q[0], -q[1]])

    def to_world(self, u, v):
        d = (np.array([u, v]) - self.screen_centre) / self.scale
        d = np.array([d[0], -d[1]])
        c, s = np.cos(-self.rotation), np.sin(-self.rotation)
        return self.world_centre + np.array([c * d[0] - s * d[1], s * d[0] + c * d[1]])


class Display:
    """One display node at `size` (w, h) under its own Xvfb; stop() ends both."""

    def __init__(self, name, size, places_file, params=None, remaps=None, out_dir=None):
        self.name, self.size = name, size
        self.env_file = tempfile.mktemp(prefix=f"display_{name}_", suffix=".env")
        self.out_dir = out_dir or tempfile.mkdtemp(prefix=f"display_{name}_")
        self.status, self.said, self.view, self.views = "", [], None, []
        self.statuses = []
        self.subs = [
            rospy.Subscriber(f"/{name}/status", String, self._on_status),
            rospy.Subscriber(f"/{name}/said", String, lambda m: self.said.append(m.data)),
            rospy.Subscriber(f"/{name}/view", Float64MultiArray, self._on_view),
        ]
        args = [f"__name:={name}", f"_places_file:={places_file}", "_fullscreen:=true"]
        args += [f"_{k}:={v}" for k, v in (params or {}).items()]
        args += [f"{a}:={b}" for a, b in (remaps or {}).items()]
        inner = (f'echo "$DISPLAY $XAUTHORITY" > {self.env_file}; '
                 f"exec rosrun wheelchair_display display {' '.join(args)}")
        self.log = open(os.path.join(self.out_dir, "display.log"), "w")
        # Its own session: stop() ends xvfb-run, Xvfb and the node, and nothing else.
        self.process = subprocess.Popen(
            ["xvfb-run", "-a", "-s", f"-screen 0 {size[0]}x{size[1]}x24", "bash", "-c", inner],
            stdout=self.log, stderr=subprocess.STDOUT, start_new_session=True)
        self.x_env = None

    def _on_status(self, msg):
        self.status = msg.data
        self.statuses.append(msg.data)

    def _on_view(self, msg):
        self.view = View(msg.data)
        self.views.append((time.monotonic(), self.view))
        del self.views[:-200]

    def views_since(self, since):
        """The views published from monotonic time `since` on, and the one current before it: a
        screenshot taken meanwhile shows a frame drawn with one of them (while the chair drives,
        the view follows it frame by frame)."""
        before = [v for t, v in self.views if t < since][-1:]
        return before + [v for t, v in self.views if t >= since]

    def click_for_view(self, x, y, timeout=30.0, settle=0.5):
        """Clicks at (x, y) where the click changes how the map is drawn (a room opened, the
        overview again) and waits until the display has drawn the new view and kept it for
        `settle` s: the next click's screen position is then the one of the frame the rider
        sees, however long the loaded machine takes to draw it. False if no new view came."""
        before = self.view.values if self.view else None
        clicked = time.monotonic()
        self.click(x, y)
        deadline = clicked + timeout
        while time.monotonic() < deadline and not rospy.is_shutdown():
            views = [(t, v) for t, v in self.views if t >= clicked]
            if views and views[-1][1].values != before and time.monotonic() - views[-1][0] >= settle:
                return True
            time.sleep(0.05)
        return False

    def wait_view(self, values, timeout=30.0, settle=0.5):
        """True once the display draws the map with the view `values` (View.values) and has
        kept it for `settle` s (it follows the HMI's state, which it may learn after the test)."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline and not rospy.is_shutdown():
            if self.views and self.views[-1][1].values == values and \
                    time.monotonic() - self.views[-1][0] >= settle:
                return True
            time.sleep(0.05)
        return False

    def wait_up(self, timeout=30.0):
        """True once the X server is known and the node has drawn its first view."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.x_env is None and os.path.exists(self.env_file):
                parts = open(self.env_file).read().split()
                if len(parts) == 2:
                    self.x_env = dict(os.environ, DISPLAY=parts[0], XAUTHORITY=parts[1])
            if self.x_env and self.view is not None and self.status:
                return True
            if self.process.poll() is not None:
                return False
            time.sleep(0.1)
        return False

    def wait_status(self, predicate, timeout=30.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline and not rospy.is_shutdown():
            if predicate(self.status):
                return True
            time.sleep(0.05)
        return predicate(self.status)

    def screenshot(self, path, settle=0.4):
        """The whole X screen now (after `settle` s for the next frames) as an RGB array; saved."""
        time.sleep(settle)
        subprocess.run(["import", "-window", "root", path], env=self.x_env, check=True,
                       timeout=20)
        return np.asarray(Image.open(path).convert("RGB"))

    def xdotool(self, *args):
        subprocess.run(["xdotool", *[str(a) for a in args]], env=self.x_env, check=True,
                       timeout=10)

    def move(self, x, y):
        self.xdotool("mousemove", int(round(x)), int(round(y)))

    def click(self, x, y):
        self.move(x, y)
        time.sleep(0.15)
        self.xdotool("click", 1)

    def dwell(self, x, y, seconds, jitter=3):
        """Rests the pointer at (x, y) for `seconds`, moving a few pixels like a head mouse."""
        end = time.monotonic() + seconds
        k = 0
        while time.monotonic() < end:
            self.move(x + jitter * ((k % 3) - 1), y + jitter * (((k + 1) % 3) - 1))
            k += 1
            time.sleep(0.1)

    def stop(self):
        for s in self.subs:
            s.unregister()
        if self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGTERM)
            try:
                self.process.wait(10)
            except subprocess.TimeoutExpired:
                os.killpg(self.process.pid, signal.SIGKILL)
        self.log.close()


# ---- what the pixels say -------------------------------------------------------------------

def map_shows_map(image, view, grid, theme, samples=400, seed=1):
    """How the screen shows sampled interior wall and free cells of `grid` (load_map): the
    shares of wall cells drawn in the wall colour and in the floor colour, and of free cells in
    the floor colour and in the wall colour. Names, frames and the chair cover some floor, so a
    right map shows walls as walls, floor mostly as floor, and almost never one as the other."""
    rng = np.random.default_rng(seed)
    x0, y0, w, h = view.map_region
    shares = {}
    for kind in ("occupied", "free"):
        mask = grid[kind]
        interior = mask.copy()
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                interior &= np.roll(np.roll(mask, dy, 0), dx, 1)
        iy, ix = np.nonzero(interior)
        counts = {"wall": 0, "floor": 0}
        total = 0
        for k in rng.permutation(len(ix)):
            wx = grid["origin"][0] + (ix[k] + 0.5) * grid["resolution"]
            wy = grid["origin"][1] + (iy[k] + 0.5) * grid["resolution"]
            u, v = view.to_screen(wx, wy)
            if not (x0 + 2 <= u < x0 + w - 2 and y0 + 2 <= v < y0 + h - 2):
                continue
            total += 1
            pixel = image[int(v):int(v) + 1, int(u):int(u) + 1]
            for name in counts:
                counts[name] += bool(colour_mask(pixel, theme[name], tolerance=6)[0, 0])
            if total >= samples:
                break
        shares[kind] = {name: c / max(1, total) for name, c in counts.items()}
    return shares


def load_map(yaml_path):
    """The map_server map as boolean grids (row 0 at the bottom), its origin and resolution."""
    import yaml
    with open(yaml_path) as f:
        meta = yaml.safe_load(f)
    image = np.asarray(Image.open(os.path.join(os.path.dirname(yaml_path), meta["image"])).convert("L"))
    p = (255.0 - image) / 255.0
    grid = {"occupied": p > meta["occupied_thresh"], "free": p < meta["free_thresh"]}
    grid = {k: v[::-1] for k, v in grid.items()}
    grid["origin"] = meta["origin"][:2]
    grid["resolution"] = meta["resolution"]
    return grid


def inside_convex(corners, px, py, margin):
    """Which of the points (px, py) lie inside the convex polygon `corners` (screen px), at least
    `margin` px from every edge (a negative margin grows the polygon)."""
    area2 = sum(corners[i - 1][0] * corners[i][1] - corners[i][0] * corners[i - 1][1]
                for i in range(len(corners)))
    inside = np.ones(np.shape(px), dtype=bool)
    for i in range(len(corners)):
        a, b = corners[i - 1], corners[i]
        edge = b - a
        cross = (edge[0] * (py - a[1]) - edge[1] * (px - a[0])) / np.linalg.norm(edge)
        inside &= (cross if area2 > 0 else -cross) >= margin
    return inside


def footprint_offset(image, view, pose, footprint, theme, window=90):
    """[px] how far the centre of the chair-coloured pixels lies from the centre of where the
    display should fill it if the chair stood at `pose` (x, y, yaw: the simulator's truth): the
    footprint polygon less the heading arrow drawn inside it (map_painter.cpp's drawChair). And
    the share of that expected fill drawn in the chair's colour."""
    x, y, yaw = pose
    c, s = np.cos(yaw), np.sin(yaw)
    corners = np.array([view.to_screen(x + c * px - s * py, y + s * px + c * py)
                        for px, py in footprint])
    centre = view.to_screen(x, y)
    heading = yaw + view.rotation
    ahead, side = np.array([np.cos(heading), -np.sin(heading)]), np.array([np.sin(heading),
                                                                             np.cos(heading)])
    size = max(12.0, 0.5 * view.scale)
    arrow = np.array([centre + ahead * size * 0.55, centre - ahead * size * 0.15 + side * size * 0.3,
                      centre - ahead * size * 0.15 - side * size * 0.3])
    middle = corners.mean(axis=0)
    u0, v0 = np.maximum(0, (middle - window).astype(int))
    u1, v1 = (middle + window).astype(int)
    crop = image[v0:v1, u0:u1]
    yy, xx = np.mgrid[v0:v1, u0:u1]
    px, py = xx[:crop.shape[0], :crop.shape[1]] + 0.5, yy[:crop.shape[0], :crop.shape[1]] + 0.5
    expected = inside_convex(corners, px, py, 2.0) & ~inside_convex(arrow, px, py, -2.0)
    drawn = colour_mask(crop, theme["chair_fill"], tolerance=20)
    if drawn.sum() == 0 or expected.sum() == 0:
        return float("inf"), 0.0
    drawn_centre = np.array([px[drawn].mean(), py[drawn].mean()])
    expected_centre = np.array([px[expected].mean(), py[expected].mean()])
    return (float(np.linalg.norm(drawn_centre - expected_centre)),
            float(drawn[expected].mean()))


def status_band(image, view):
    """The status line's pixels: everything above the map region, left of the STOP area."""
    x0, y0, w, h = view.map_region
    return image[:y0, : x0 + w]


def status_text_measures(band, first_letter, theme, inset=14):
    """(cap height of the sentence's first letter [px], the same capital's cap height set in
    DejaVu Sans Bold at 48 px, the contrast of the text against its background)."""
    inner = band[inset:-inset, inset:-inset]
    background = np.asarray(theme["background"])
    ink = np.abs(inner.astype(int) - background).sum(axis=2) > 90
    # The first line: the first run of inked rows (lines are apart by the line spacing).
    inked_rows = np.nonzero(ink.any(axis=1))[0]
    if len(inked_rows) == 0:
        return 0, 0, 1.0
    last = inked_rows[0]
    while last + 1 < ink.shape[0] and ink[last + 1].any():
        last += 1
    first_line = np.zeros_like(ink)
    first_line[inked_rows[0]:last + 1] = ink[inked_rows[0]:last + 1]
    cols = np.nonzero(first_line.any(axis=0))[0]
    # The first glyph: the ink connected to the leftmost inked pixel (8-neighbours).
    ys = np.nonzero(first_line[:, cols[0]])[0]
    seen = np.zeros_like(ink)
    stack = [(int(ys[0]), int(cols[0]))]
    seen[stack[0]] = True
    rows = []
    while stack:
        y, x = stack.pop()
        rows.append(y)
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                yy, xx = y + dy, x + dx
                if 0 <= yy < ink.shape[0] and 0 <= xx < ink.shape[1] and \
                        first_line[yy, xx] and not seen[yy, xx]:
                    seen[yy, xx] = True
                    stack.append((yy, xx))
    measured = max(rows) - min(rows) + 1
    font = ImageFont.truetype(FONT_BOLD, 48)
    left, top, right, bottom = font.getbbox(first_letter)
    reference = bottom - top
    # Contrast: the text's own colour (the most common far-from-background colour) vs the band's.
    far = inner[ink]
    colours, counts = np.unique(far.reshape(-1, 3), axis=0, return_counts=True)
    text_colour = colours[np.argmax(counts)]
    values, counts = np.unique(band.reshape(-1, 3), axis=0, return_counts=True)
    band_colour = values[np.argmax(counts)]
    return measured, reference, contrast(text_colour, band_colour)
