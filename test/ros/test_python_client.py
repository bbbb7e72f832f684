#!/usr/bin/python3
"""A rospy client of the collision2d services, as a Python user would write it.

Checks the physics on what comes back: momentum and the Newton target of a
head-on impact, a bad request's message, a step published on world_state, and
runtime tuning through dynamic_reconfigure.
"""
import math
import threading
import unittest

import dynamic_reconfigure.client
import rospy
import rostest
from collision2d.msg import Body, SolverSettings, WorldConfig, WorldState
from collision2d.srv import GetWorld, LoadScene, ResolveContacts, StepWorld

SERVICE_WAIT_S = 30.0


def disk(body_id, x, vx, mass=1.0, radius=0.5):
    body = Body(id=body_id, shape=Body.DISK, type=Body.DYNAMIC, mass=mass, radius=radius)
    body.pose.x = x
    body.twist.linear.x = vx
    return body


def settings(restitution, friction=0.0):
    return SolverSettings(restitution=restitution, friction=friction, iterations=200, tolerance=1e-10,
                          bias_factor=0.2, slop=1e-3, mode=SolverSettings.ITERATIVE)


class PythonClient(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_python_client")
        for name in ("resolve_contacts", "step_world", "load_scene", "get_world"):
            rospy.wait_for_service(name, timeout=SERVICE_WAIT_S)
        cls.resolve = rospy.ServiceProxy("resolve_contacts", ResolveContacts)

    def test_head_on_impact_meets_newton_and_keeps_momentum(self):
        e = 0.5
        light, heavy = disk(1, 0.0, 1.0), disk(2, 0.95, -1.0, mass=3.0)
        response = self.resolve(bodies=[light, heavy], settings=settings(e))
        self.assertTrue(response.success, response.message)
        self.assertEqual(len(response.contacts), 1)
        contact = response.contacts[0]
        self.assertEqual((contact.body_a, contact.body_b), (1, 2))
        self.assertGreater(contact.normal_impulse, 0.0)
        v1, v2 = (b.twist.linear.x for b in response.bodies)
        # Momentum 1 * 1 + 3 * (-1) = -2 kg m/s before and after.
        self.assertAlmostEqual(1.0 * v1 + 3.0 * v2, -2.0, places=9)
        # Approach at 2 m/s: separation at e * 2 m/s.
        self.assertAlmostEqual(v2 - v1, e * 2.0, places=7)
        # The impulse changed the light disk's momentum by exactly itself.
        self.assertAlmostEqual(contact.normal_impulse, 1.0 - v1, places=9)
        self.assertLess(response.report.kinetic_energy_after, response.report.kinetic_energy_before)

    def test_bad_request_names_body_and_field(self):
        bad = disk(9, 3.0, 0.0, mass=float("nan"))
        response = self.resolve(bodies=[disk(1, 0.0, 0.0), bad], settings=settings(0.5))
        self.assertFalse(response.success)
        self.assertIn("bodies[1] (id 9): mass = nan is not finite", response.message)
        self.assertEqual(len(response.bodies), 0)

    def test_step_is_published(self):
        received = []
        done = threading.Event()

        def on_state(state):
            received.append(state.frame_count)
            if state.frame_count == 5:
                done.set()

        loaded = rospy.ServiceProxy("load_scene", LoadScene)(scene="bouncing_disks")
        self.assertTrue(loaded.success, loaded.message)
        subscriber = rospy.Subscriber("world_state", WorldState, on_state)
        try:
            stepped = rospy.ServiceProxy("step_world", StepWorld)(frames=5, dt=0.0, return_state=True)
            self.assertTrue(stepped.success, stepped.message)
            self.assertEqual(stepped.frame_count, 5)
            self.assertEqual([s.frame_count for s in stepped.state], [5])
            self.assertTrue(math.isclose(stepped.sim_time, 5 * stepped.state[0].settings.dt, rel_tol=1e-12))
            self.assertTrue(done.wait(SERVICE_WAIT_S), "world_state never showed frame 5: %s" % received)
        finally:
            subscriber.unregister()

    def test_free_running_world_steps_by_itself(self):
        # /free_run/world runs at ~rate 50 Hz: frames arrive without any step_world call.
        first = rospy.wait_for_message("/free_run/world_state", WorldState, timeout=SERVICE_WAIT_S)
        later = first
        deadline = rospy.Time.now() + rospy.Duration(SERVICE_WAIT_S)
        while later.frame_count < first.frame_count + 5 and rospy.Time.now() < deadline:
            later = rospy.wait_for_message("/free_run/world_state", WorldState, timeout=SERVICE_WAIT_S)
        self.assertGreaterEqual(later.frame_count, first.frame_count + 5)
        # Each tick is one frame of the world's dt, whatever the wall time.
        self.assertAlmostEqual(later.sim_time, later.frame_count * later.settings.dt, places=9)
        self.assertEqual(later.scene, "bouncing_disks")

    def test_dynamic_reconfigure_tunes_solver_and_world(self):
        reconfigure = dynamic_reconfigure.client.Client("world", timeout=SERVICE_WAIT_S)
        loaded = rospy.ServiceProxy("load_scene", LoadScene)(scene="resting_box", return_state=True)
        self.assertTrue(loaded.success, loaded.message)
        # After a load the world group shows the scene's settings.
        shown = reconfigure.get_configuration(timeout=SERVICE_WAIT_S)
        settings = loaded.state[0].settings
        self.assertEqual(shown["world_substeps"], settings.substeps)
        self.assertAlmostEqual(shown["world_dt"], settings.dt, places=12)
        self.assertEqual(shown["world_solver_mode"], settings.solver_mode)
        self.assertEqual(shown["world_position_iterations"], settings.position_iterations)
        original = shown["solver_restitution"]
        try:
            reconfigure.update_configuration({"solver_restitution": 1.0, "world_substeps": 7,
                                              "world_solver_mode": WorldConfig.SOLVER_EXACT,
                                              "world_position_iterations": 3})
            # ResolveContacts with the node's settings is now perfectly elastic.
            request = SolverSettings(use_node_settings=True)
            response = self.resolve(bodies=[disk(1, 0.0, 1.0), disk(2, 0.95, -1.0)], settings=request)
            self.assertTrue(response.success, response.message)
            v1, v2 = (b.twist.linear.x for b in response.bodies)
            self.assertAlmostEqual(v2 - v1, 2.0, places=7)
            world = rospy.ServiceProxy("get_world", GetWorld)()
            self.assertEqual(world.state.settings.substeps, 7)
            self.assertEqual(world.state.settings.solver_mode, WorldConfig.SOLVER_EXACT)
            self.assertEqual(world.state.settings.position_iterations, 3)
        finally:
            reconfigure.update_configuration({"solver_restitution": original})


if __name__ == "__main__":
    rostest.rosrun("collision2d", "python_client", PythonClient)
