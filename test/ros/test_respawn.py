#!/usr/bin/python3
"""The world node killed hard (SIGKILL) comes back with its last saved frame.

respawn.test starts launch/collision2d.launch (respawn on) with an autosave
period. The test edits and steps the world, remembers the state the step that
completed the last period returned, kills the node's process (pid from the
node's own XML-RPC getPid, found through the master), waits for roslaunch to
start a new process and checks that get_world serves exactly that state.
"""
import os
import signal
import time
import unittest
import xmlrpc.client

import rosgraph
import rospy
import rostest
from collision2d.srv import GetWorld, RemoveBody, StepWorld

SERVICE_WAIT_S = 30.0
RESPAWN_WAIT_S = 60.0
POLL_S = 0.1
FRAMES_PER_CALL = 4
CALLS = 7  # 28 frames: the period-10 autosaves happen at frames 10 and 20


def node_pid(node_name):
    """The pid the node reports through its XML-RPC API, or None while it is down."""
    try:
        uri = rosgraph.Master(rospy.get_name()).lookupNode(node_name)
        code, _, pid = xmlrpc.client.ServerProxy(uri).getPid(rospy.get_name())
        return pid if code == 1 else None
    except (OSError, rosgraph.MasterError, xmlrpc.client.Error):
        return None


def saved_part(state):
    """What a snapshot keeps: all but the header, the last substep's contacts
    and the active effects, which a restored world has not computed yet."""
    return (state.frame_count, state.sim_time, state.scene, state.bodies, state.settings)


class Respawn(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_respawn")
        cls.node = rospy.get_param("~world_node")
        cls.period = rospy.get_param("~autosave_period")
        cls.snapshot = rospy.get_param("~snapshot_path")
        for name in ("step_world", "get_world", "remove_body"):
            rospy.wait_for_service("/collision2d/" + name, timeout=SERVICE_WAIT_S)
        cls.step = rospy.ServiceProxy("/collision2d/step_world", StepWorld)
        cls.get_world = rospy.ServiceProxy("/collision2d/get_world", GetWorld)
        cls.remove_body = rospy.ServiceProxy("/collision2d/remove_body", RemoveBody)

    @classmethod
    def tearDownClass(cls):
        if os.path.exists(cls.snapshot):
            os.remove(cls.snapshot)

    def wait_for_new_process(self, old_pid):
        deadline = time.monotonic() + RESPAWN_WAIT_S
        while time.monotonic() < deadline:
            pid = node_pid(self.node)
            if pid is not None and pid != old_pid:
                return pid
            time.sleep(POLL_S)
        self.fail("%s was not respawned within %.0f s" % (self.node, RESPAWN_WAIT_S))

    def test_killed_node_comes_back_at_the_last_saved_frame(self):
        # An id gap, so the restore must keep ids rather than renumber.
        removed = self.remove_body(id=0)
        self.assertTrue(removed.success, removed.message)
        last_saved = None
        after_saved = None  # the state one call after the last save
        for _ in range(CALLS):
            response = self.step(frames=FRAMES_PER_CALL, dt=0.0, return_state=True)
            self.assertTrue(response.success, response.message)
            if last_saved is not None and after_saved is None:
                after_saved = response.state[0]
            if response.frame_count % self.period == 0:
                last_saved = response.state[0]
                after_saved = None
        self.assertIsNotNone(last_saved)
        before_kill = self.get_world().state
        self.assertEqual(before_kill.frame_count, CALLS * FRAMES_PER_CALL)
        self.assertGreater(before_kill.frame_count, last_saved.frame_count, "nothing to lose: test is vacuous")
        self.assertNotEqual(saved_part(before_kill), saved_part(last_saved))

        old_pid = node_pid(self.node)
        self.assertIsNotNone(old_pid)
        os.kill(old_pid, signal.SIGKILL)
        new_pid = self.wait_for_new_process(old_pid)
        rospy.loginfo("world node %d killed, respawned as %d", old_pid, new_pid)
        rospy.wait_for_service("/collision2d/get_world", timeout=SERVICE_WAIT_S)

        restored = self.get_world().state
        self.assertEqual(restored.frame_count, last_saved.frame_count)
        self.assertEqual(restored.sim_time, last_saved.sim_time)
        self.assertEqual([b.id for b in restored.bodies], [b.id for b in last_saved.bodies])
        self.assertNotIn(0, [b.id for b in restored.bodies])
        self.assertEqual(saved_part(restored), saved_part(last_saved))

        # The respawned world steps on from the restored frame exactly as the
        # killed one did: the snapshot kept the warm-start impulses and sleep.
        self.assertIsNotNone(after_saved)
        response = self.step(frames=FRAMES_PER_CALL, dt=0.0, return_state=True)
        self.assertTrue(response.success, response.message)
        self.assertEqual(response.frame_count, last_saved.frame_count + FRAMES_PER_CALL)
        self.assertEqual(response.state[0].bodies, after_saved.bodies)


if __name__ == "__main__":
    rostest.rosrun("collision2d", "respawn", Respawn)
