"""A ROS master of the run's own, on a free port, and parameters set through its XML-RPC API
(no rosparam tool needed: an installed chair's root may have none)."""
import os
import time
import xmlrpc.client

from .processes import ProcessError, free_port

CALLER = "/wheelchair_harness"


def master_online(uri):
    """True if a master answers at `uri`."""
    try:
        code, _, _ = xmlrpc.client.ServerProxy(uri).getPid(CALLER)
        return code == 1
    except (OSError, xmlrpc.client.Error):
        return False


def set_param(uri, name, value):
    """Sets parameter `name` on the master at `uri` (e.g. /use_sim_time before any node starts:
    a node reads it once, at its start)."""
    code, message, _ = xmlrpc.client.ServerProxy(uri).setParam(CALLER, name, value)
    if code != 1:
        raise ProcessError(f"the master at {uri} refused {name}: {message}")


def start_master(processes, port=None, rosout=False, use_sim_time=None, export=False,
                 timeout=60.0):
    """`rosmaster --core` on `port` (default: a free one) as process "rosmaster", waits until it
    answers, optionally starts rosout and sets /use_sim_time. The children of `processes` get
    ROS_MASTER_URI (so do this process's later nodes with export=True). Returns the URI."""
    port = port or free_port()
    uri = f"http://localhost:{port}"
    processes.env = dict(processes.env if processes.env is not None else os.environ,
                         ROS_MASTER_URI=uri)
    if export:
        os.environ["ROS_MASTER_URI"] = uri
    processes.start("rosmaster", ["rosmaster", "--core", "-p", str(port)], interrupt=False)
    processes.wait_for(f"the ROS master at {uri}", lambda: master_online(uri), timeout,
                       watch=["rosmaster"], period=0.2)
    if use_sim_time is not None:
        set_param(uri, "/use_sim_time", bool(use_sim_time))
    if rosout:
        processes.rosrun("rosout", "rosout", "rosout", "__name:=rosout")
    return uri


def wait_for_service(name, timeout, processes=None, watch=()):
    """Waits for a ROS service of this process's master (rospy); raises ProcessError on timeout
    or when one of `watch` ended."""
    import rospy

    deadline = time.monotonic() + timeout
    while True:
        if processes is not None and watch:
            processes.check(*watch)
        try:
            rospy.wait_for_service(name, timeout=0.2)
            return
        except rospy.ROSException:
            if time.monotonic() > deadline:
                raise ProcessError(f"timed out after {timeout:.0f} s waiting for service {name}")
