#!/usr/bin/python3
"""Measures rospy service round trips to a running world node, with a default
ServiceProxy (a new connection per call) and a persistent one, as quoted in
docs/ros_interface.md. Start the node first, e.g.
    roslaunch collision2d collision2d.launch scene:=empty
then: test/ros/service_latency.py [calls]   (default 300 calls per case)"""
import statistics
import sys
import time

import rospy

from collision2d.msg import Body, SolverSettings
from collision2d.srv import GetWorld, ResolveContacts

NS = "/collision2d"
BODIES = 100


def resolve_request():
    """BODIES disks of radius 0.5 in a row, each overlapping the next by 1 cm."""
    bodies = []
    for i in range(BODIES):
        body = Body(id=i, shape=Body.DISK, mass=1.0, radius=0.5)
        body.pose.x = 0.99 * i
        body.twist.linear.x = 1.0 if i % 2 == 0 else -1.0
        bodies.append(body)
    settings = SolverSettings(restitution=0.5, friction=0.3, iterations=64, tolerance=1e-9, bias_factor=0.2,
                              slop=0.001)
    return ResolveContacts._request_class(bodies=bodies, settings=settings)


def median_ms(proxy, request, calls):
    proxy(request)  # connect (persistent) and warm up
    times = []
    for _ in range(calls):
        start = time.perf_counter()
        answer = proxy(request)
        times.append(time.perf_counter() - start)
        assert answer.success, answer.message
    return 1e3 * statistics.median(times)


def main():
    calls = int(sys.argv[1]) if len(sys.argv) > 1 else 300
    rospy.init_node("service_latency", anonymous=True)
    cases = [("resolve_contacts, %d bodies" % BODIES, NS + "/resolve_contacts", ResolveContacts, resolve_request()),
             ("get_world", NS + "/get_world", GetWorld, GetWorld._request_class())]
    for label, name, service_type, request in cases:
        rospy.wait_for_service(name, timeout=30.0)
        for persistent in (False, True):
            proxy = rospy.ServiceProxy(name, service_type, persistent=persistent)
            ms = median_ms(proxy, request, calls)
            proxy.close()
            print("%-32s %-10s median %.3f ms over %d calls" %
                  (label, "persistent" if persistent else "default", ms, calls))


if __name__ == "__main__":
    main()
