"""The test worlds (test/worlds: maps, named places, doors) wherever the package is: the source
tree beside this file, or the installed wheelchair_test share directory."""
import pathlib

import yaml

_SOURCE = pathlib.Path(__file__).resolve().parents[3] / "worlds"


def worlds_dir():
    if _SOURCE.is_dir():
        return _SOURCE
    import rospkg

    return pathlib.Path(rospkg.RosPack().get_path("wheelchair_test")) / "worlds"


def places(world="flat"):
    """{name: {name, room, x, y, yaw}} of a world's named places."""
    path = worlds_dir() / f"{world}.places.yaml"
    with open(path) as f:
        return {p["name"]: p for p in yaml.safe_load(f)["places"]}


def place(name, world="flat"):
    """(x, y, yaw) of a named place of a test world; KeyError naming the known places."""
    known = places(world)
    if name not in known:
        raise KeyError(f"no place named '{name}' in {world} (there are: {', '.join(known)})")
    p = known[name]
    return p["x"], p["y"], p.get("yaw", 0.0)
