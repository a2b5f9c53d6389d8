"""The chair in the simulator loop, started with rosrun only: the simulator playing laser and
motors behind the CAN bus (CAN frames over UDP) and the one-process chair
(`rosrun wheelchair_bringup wheelchair`). `ports` = (driver, motors) UDP ports of the bus:
every run passes its own, so parallel runs never share a bus."""


def simulator(processes, world, ports, initial, name="simulator", options=None, **params):
    """`rosrun wheelchair_sim simulator` on `world` (a map YAML) at `initial` (x, y, yaw);
    `params`: further private parameters (speed, laser_rate, ...)."""
    x, y, yaw = initial
    arguments = [f"_world:={world}", "_motor_bus:=udp", f"_udp_local_port:={ports[1]}",
                 f"_udp_remote_port:={ports[0]}", f"_initial_x:={x}", f"_initial_y:={y}",
                 f"_initial_yaw:={yaw}"] + [f"_{key}:={value}" for key, value in params.items()]
    return processes.rosrun(name, "wheelchair_sim", "simulator", *arguments, **(options or {}))


def chair(processes, config=None, ports=None, name="wheelchair", overrides=None, node_name=None,
          options=None):
    """`rosrun wheelchair_bringup wheelchair [config]` (default: chair_sim.yaml). `ports`: the
    base driver's UDP ports as per-run overrides; `overrides`: {"<nodelet>/<key>": value} (the
    `wheelchair` node's private parameters win over the file); `node_name`: another node name
    (__name:=)."""
    arguments = [str(config)] if config is not None else []
    if node_name:
        arguments.append(f"__name:={node_name}")
    merged = dict(overrides or {})
    if ports is not None:
        merged.update({"base_driver/udp_local_port": ports[0],
                       "base_driver/udp_remote_port": ports[1]})
    arguments += [f"_{key}:={value}" for key, value in merged.items()]
    return processes.rosrun(name, "wheelchair_bringup", "wheelchair", *arguments,
                            **(options or {}))
