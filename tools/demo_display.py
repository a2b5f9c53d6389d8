"""The rider's display in `./wheelchair demo` (steps of tools/demo.py): the real display node
(`rosrun wheelchair_display display`, 1024x768, dark theme) under its own Xvfb beside the running
chair, photographed (ImageMagick's `import`, through test/display/display_harness.py's Display)
while the HMI scans, while the chair drives, when it arrived and when the rider stopped a drive
with the switch: out/demo/display_{scanning,driving,arrived,stopped}.png."""
import pathlib
import sys
import time

import rospy
from wheelchair_msgs.msg import HmiState

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "test" / "display"))
from display_harness import Display  # noqa: E402

SIZE = (1024, 768)
STOP_GOAL = "sofa"  # after the drive: the rider stops the drive there with the switch


class DemoDisplayError(Exception):
    pass


def _shoot(demo, name):
    path = demo.out / f"display_{name}.png"
    demo.display.screenshot(str(path))
    demo.facts.setdefault("display_shots", []).append((name, path.name, demo.display.status))
    return f"{path.name} ('{demo.display.status}')"


def _wait_status(demo, predicate, what, timeout=60.0):
    if not demo.display.wait_status(predicate, timeout):
        raise DemoDisplayError(f"the display never said {what} (it says '{demo.display.status}'; "
                               f"log: {demo.display.out_dir}/display.log)")


def start_display(demo):
    """The display on the world's places file, as the chair's HMI reads it."""
    places_file = ROOT / "test" / "worlds" / f"{demo.args.world}.places.yaml"
    out = demo.logs / "display"
    out.mkdir(parents=True, exist_ok=True)
    demo.display = Display("display", SIZE, str(places_file), {"theme": "dark"}, out_dir=str(out))
    demo.hmi_state = None
    demo.hmi_sub = rospy.Subscriber("/hmi/state", HmiState,
                                    lambda m: setattr(demo, "hmi_state", m))
    if not demo.display.wait_up(60.0):
        raise DemoDisplayError(f"the display did not start (log: {out}/display.log)")
    return f"the rider's display at {SIZE[0]}x{SIZE[1]} under Xvfb: '{demo.display.status}'"


def shot_scanning(demo):
    """While the HMI scans the rooms (after localization: 'Choose where to go.')."""
    _wait_status(demo, lambda t: t == "Choose where to go.", "'Choose where to go.'")
    if not demo.rider.wait(lambda: demo.hmi_state is not None and
                           demo.hmi_state.state == HmiState.SCANNING_ROOMS, 30.0):
        raise DemoDisplayError(f"the HMI does not scan the rooms: {demo.hmi_state}")
    return _shoot(demo, "scanning")


def shot_driving(demo):
    """Once the chair drives to the chosen place."""
    _wait_status(demo, lambda t: t.startswith("Driving to"), "'Driving to ...'")
    since = demo.facts["go_time"]
    demo.rider.wait(lambda: demo.rider.travelled(since) > 0.5, 60.0)
    return _shoot(demo, "driving")


def shot_arrived(demo):
    _wait_status(demo, lambda t: t.startswith("Arrived"), "'Arrived ...'", 30.0)
    return _shoot(demo, "arrived")


def shot_stopped(demo):
    """A drive to STOP_GOAL through the HMI's service, stopped by one switch press."""
    rider = demo.rider
    since = rider.mark()
    accepted, message = rider.go_to_place(STOP_GOAL)
    if not accepted:
        raise DemoDisplayError(f"go_to_place {STOP_GOAL}: {message}")
    _wait_status(demo, lambda t: t.startswith("Driving to"), "'Driving to ...'")
    rider.wait(lambda: rider.travelled(since) > 0.3, 60.0)
    rider.press()
    _wait_status(demo, lambda t: t == "Stopped: you pressed stop.", "'Stopped: you pressed stop.'",
                 20.0)
    rider.wait(rider.at_rest, 20.0)
    return _shoot(demo, "stopped")


def stop_display(demo):
    if getattr(demo, "display", None) is not None:
        demo.display.stop()
        demo.display = None


def report_lines(demo):
    """Markdown lines: each screenshot with what the display said."""
    lines = []
    for name, file, status in demo.facts.get("display_shots", []):
        lines += [f"Rider's display, {name}: \"{status}\"", "", f"![display {name}]({file})", ""]
    return lines
