#!/usr/bin/python3
"""Body frames looked up through tf2, /clock read as any sim-time node would,
and a body dragged through the interactive marker feedback topic as rviz
drags it."""
import math
import time
import unittest

import rospy
import rostest
import tf2_ros
from rosgraph_msgs.msg import Clock
from visualization_msgs.msg import InteractiveMarkerFeedback, InteractiveMarkerInit

from collision2d.msg import Body, WorldState
from collision2d.srv import GetWorld, LoadScene, SetBodyState, SetWorld, StepWorld
from std_srvs.srv import Trigger

NS = "/collision2d"
SERVICE_WAIT_S = 30.0
TF_WAIT_S = 10.0
STEP_ATTEMPTS = 3
CLOCK_LISTEN_S = 1.5
DRAG_STEP_X = 0.1     # m per pose update
DRAG_PERIOD_S = 0.05  # between pose updates: 2 m/s
DRAG_UPDATES = 6


def proxy(name, service_type):
    rospy.wait_for_service(name, timeout=SERVICE_WAIT_S)
    return rospy.ServiceProxy(name, service_type)


def body_of(state, body_id):
    return next(b for b in state.bodies if b.id == body_id)


def wait_until(condition, timeout):
    deadline = time.time() + timeout
    while time.time() < deadline:
        value = condition()
        if value:
            return value
        time.sleep(0.05)
    return condition()


def latest_transform(buffer, state, frame):
    """The latest transform parent -> frame if it carries the state's stamp (tf2 keeps microseconds)."""
    if not buffer.can_transform(state.header.frame_id, frame, rospy.Time(0)):
        return None
    transform = buffer.lookup_transform(state.header.frame_id, frame, rospy.Time(0))
    if abs(transform.header.stamp.to_sec() - state.header.stamp.to_sec()) > 1e-6:
        return None
    return transform


class TfClockDrag(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.step = proxy(NS + "/step_world", StepWorld)
        cls.get_world = proxy(NS + "/get_world", GetWorld)
        cls.load_scene = proxy(NS + "/load_scene", LoadScene)
        cls.set_world = proxy(NS + "/set_world", SetWorld)
        cls.set_body_state = proxy(NS + "/set_body_state", SetBodyState)

    def test_body_frames_are_on_tf(self):
        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer)
        # /tf is not latched: the frames come with the next change after the listener connected.
        self.assertTrue(wait_until(lambda: listener.tf_sub.get_num_connections() > 0, SERVICE_WAIT_S))
        self.assertTrue(self.load_scene(scene="demo").success)
        self.assertTrue(self.step(frames=30).success)
        state = self.get_world().state
        # The publisher adds the listener just after the subscriber counts it
        # connected, so the first changes can pass it by: step again until one arrives.
        for _ in range(STEP_ATTEMPTS - 1):
            if wait_until(lambda: latest_transform(buffer, state, "body_%d" % state.bodies[0].id), TF_WAIT_S):
                break
            self.assertTrue(self.step(frames=1).success)
            state = self.get_world().state
        for body in state.bodies[:3] + state.bodies[-1:]:
            frame = "body_%d" % body.id
            # load_scene published the frames too; wait for the step's (the world does not step in between).
            transform = wait_until(lambda: latest_transform(buffer, state, frame), TF_WAIT_S)
            self.assertTrue(transform, "no transform %s -> %s stamped %.6f s" %
                            (state.header.frame_id, frame, state.header.stamp.to_sec()))
            self.assertAlmostEqual(transform.transform.translation.x, body.pose.x, places=9)
            self.assertAlmostEqual(transform.transform.translation.y, body.pose.y, places=9)
            rotation = transform.transform.rotation
            yaw = 2.0 * math.atan2(rotation.z, rotation.w)
            self.assertAlmostEqual(math.remainder(yaw - body.pose.theta, 2 * math.pi), 0.0, places=9)

    def test_clock_is_sim_time_and_never_runs_backwards(self):
        stamps = []
        states = []
        clock_sub = rospy.Subscriber("/clock", Clock, lambda m: stamps.append(m.clock))
        state_sub = rospy.Subscriber("/clocked/world_state", WorldState, states.append)
        try:
            self.assertTrue(wait_until(lambda: len(stamps) > 10, SERVICE_WAIT_S), "nothing on /clock")
            # The two subscribers connect apart: wait for the state too.
            first = wait_until(lambda: next((s for s in list(states) if s.scene == "bouncing_disks"), None),
                               SERVICE_WAIT_S)
            self.assertTrue(first, "nothing on /clocked/world_state")
            # Until the first reset, the clock is the world's own time.
            self.assertAlmostEqual(first.header.stamp.to_sec(), first.sim_time, delta=1e-4)
            time.sleep(CLOCK_LISTEN_S)
            self.assertTrue(proxy("/clocked/reset_world", Trigger)().success)
            time.sleep(CLOCK_LISTEN_S)
            self.assertTrue(proxy("/clocked/load_scene", LoadScene)(scene="pyramid").success)
            time.sleep(CLOCK_LISTEN_S)
        finally:
            clock_sub.unregister()
            state_sub.unregister()
        seconds = [s.to_sec() for s in stamps]
        self.assertGreater(len(seconds), 3 * 60 * CLOCK_LISTEN_S * 0.5, "/clock did not follow the free run")
        backwards = [(a, b) for a, b in zip(seconds, seconds[1:]) if b < a]
        self.assertEqual(backwards, [], "/clock ran backwards")
        # The world restarted twice, the clock did not: it covers all of the run.
        self.assertGreater(seconds[-1] - seconds[0], 2.5 * CLOCK_LISTEN_S * 0.5)
        restarted = [s for s in states if s.sim_time < first.sim_time]
        self.assertTrue(restarted, "the world's own time never restarted: test is vacuous")
        self.assertTrue(all(s.header.stamp.to_sec() >= first.header.stamp.to_sec() for s in restarted))

    def test_dragging_a_body_holds_it_and_releases_it_with_the_drag_velocity(self):
        disk = Body(id=0, shape=Body.DISK, type=Body.DYNAMIC, mass=1.0, radius=0.5)
        disk.pose.y = 5.0
        self.assertTrue(self.set_world(bodies=[disk], keep_settings=True).success)
        body_id = self.get_world().state.bodies[0].id
        name = str(body_id)

        def marker_shown():
            init = rospy.wait_for_message(NS + "/drag/update_full", InteractiveMarkerInit, timeout=TF_WAIT_S)
            return [m for m in init.markers if m.name == name and abs(m.pose.position.y - 5.0) < 1e-9]
        self.assertTrue(wait_until(marker_shown, SERVICE_WAIT_S), "no interactive marker for body " + name)

        feedback = rospy.Publisher(NS + "/drag/feedback", InteractiveMarkerFeedback, queue_size=10)
        self.assertTrue(wait_until(lambda: feedback.get_num_connections() > 0, SERVICE_WAIT_S))

        def send(event, x):
            msg = InteractiveMarkerFeedback(client_id="/rviz/InteractiveMarkers", marker_name=name,
                                            control_name="move", event_type=event)
            msg.header.frame_id = "map"
            msg.header.stamp = rospy.Time.now()
            msg.pose.position.x = x
            msg.pose.position.y = 5.0
            msg.pose.orientation.w = 1.0
            feedback.publish(msg)

        send(InteractiveMarkerFeedback.MOUSE_DOWN, 0.0)
        held = wait_until(lambda: body_of(self.get_world().state, body_id).type == Body.KINEMATIC, TF_WAIT_S)
        self.assertTrue(held, "the pressed body is not held as KINEMATIC")
        x = 0.0
        for _ in range(DRAG_UPDATES):
            time.sleep(DRAG_PERIOD_S)
            x += DRAG_STEP_X
            send(InteractiveMarkerFeedback.POSE_UPDATE, x)
        moved = wait_until(lambda: abs(body_of(self.get_world().state, body_id).pose.x - x) < 1e-9, TF_WAIT_S)
        self.assertTrue(moved, "the dragged body did not follow the drag")
        self.assertEqual(body_of(self.get_world().state, body_id).type, Body.KINEMATIC)
        send(InteractiveMarkerFeedback.MOUSE_UP, x)
        released = wait_until(lambda: body_of(self.get_world().state, body_id).type == Body.DYNAMIC, TF_WAIT_S)
        self.assertTrue(released, "the released body is not DYNAMIC again")
        body = body_of(self.get_world().state, body_id)
        drag_speed = DRAG_STEP_X / DRAG_PERIOD_S
        self.assertAlmostEqual(body.pose.x, x, places=9)
        self.assertGreater(body.twist.linear.x, 0.5 * drag_speed)
        self.assertLess(body.twist.linear.x, 1.5 * drag_speed)
        self.assertAlmostEqual(body.twist.linear.y, 0.0, places=9)
        # Thrown: it flies on in +x.
        self.assertTrue(self.step(frames=30).success)
        self.assertGreater(body_of(self.get_world().state, body_id).pose.x, x + 0.2 * drag_speed * 0.5)

    def test_set_body_state_refuses_bad_requests_and_leaves_the_world(self):
        self.assertTrue(self.load_scene(scene="demo").success)
        before = self.get_world().state
        body_id = before.bodies[0].id
        bad = SetBodyState._request_class(id=body_id, hold=True)
        bad.pose.x = float("nan")
        answer = self.set_body_state(bad)
        self.assertFalse(answer.success)
        self.assertIn("id %d" % body_id, answer.message)
        self.assertIn("pose.x = nan", answer.message)
        unknown = self.set_body_state(id=100000)
        self.assertFalse(unknown.success)
        self.assertIn("id 100000", unknown.message)
        after = self.get_world().state
        self.assertEqual(after.bodies, before.bodies)
        self.assertEqual(after.frame_count, before.frame_count)


if __name__ == "__main__":
    rospy.init_node("test_tf_clock_drag", anonymous=True)
    rostest.rosrun("collision2d", "tf_clock_drag", TfClockDrag)
