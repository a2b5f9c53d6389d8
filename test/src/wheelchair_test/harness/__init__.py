"""The one harness of the system tests, the demo, the report and the benches.

  processes  Processes: start (own process group, own log), check, stop and reap; free ports;
             niceness of a process and its session
  master     start_master (a master of the run's own on a free port), set_param (XML-RPC)
  stack      simulator / chair: the chair in the simulator loop with rosrun
  worlds     the test worlds' named places
  rider      Rider: a pose estimate, a goal (pose, named place, one-switch presses) and its
             outcome, what a rider and a carer see, the simulator's truth (rospy)

Import it as `wheelchair_test.harness` (catkin_python_setup: any sourced workspace), or from a
checkout by path: sys.path.insert(0, "<repo>/test/src"). The rider needs rospy and the
workspace's messages; the rest only the standard library (and PyYAML).
"""
from .master import master_online, set_param, start_master, wait_for_service
from .processes import ProcessError, Processes, free_port, free_udp_ports, set_niceness
from .worlds import place, places, worlds_dir
from . import stack


def __getattr__(name):
    # The rider imports rospy and the messages: only when asked for.
    if name in ("Rider", "RiderError", "Mark", "describe_stop", "yaw_of", "angle_diff",
                "point_ahead"):
        from . import rider

        return getattr(rider, name)
    raise AttributeError(name)
