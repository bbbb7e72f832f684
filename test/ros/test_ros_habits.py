#!/usr/bin/python3
"""ROS habits of the world node, through the real tools: the README's rosrun
line in the README's workspace layout, rosconsole lines on /rosout and on
stdout, StepWorld answers that fit a terminal, reads that never wait for a
step, and printable messages."""
import math
import os
import re
import subprocess
import tempfile
import threading
import time
import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Log

from collision2d.msg import Body, SolverSettings
from collision2d.srv import AddBody, GetWorld, LoadScene, ResolveContacts, StepWorld
from std_srvs.srv import Trigger

NS = "/collision2d"
NODE = NS + "/world"
SERVICE_WAIT_S = 30.0
COMMAND_TIMEOUT_S = 120.0
LOG_WAIT_S = 10.0
README = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "README.md")
ROSRUN_EXAMPLE = re.compile(r"^`?(rosrun collision2d collision2d_cli [^`\n]*)`?\.?$", re.MULTILINE)
# A screenful: what `rosservice call step_world` may print by default.
SCREEN_LINES = 60
# A step long enough that a read 0.5 s into it finds it running, on any machine: its frame
# count comes from timing a step of this many frames (the launch file raises the node's
# ~max_frames_per_call to allow it).
CALIBRATION_FRAMES = 2000
LONG_STEP_S = 4.0


def run_without_terminal(command):
    """`command` in bash with no terminal: stdin from /dev/null, own session."""
    return subprocess.run(["bash", "-c", command], stdin=subprocess.DEVNULL, capture_output=True, text=True,
                          start_new_session=True, timeout=COMMAND_TIMEOUT_S)


class RosoutRecorder:
    """Every /rosout line of the world node from now on."""

    def __init__(self):
        self.lines = []
        self.cond = threading.Condition()
        self.sub = rospy.Subscriber("/rosout", Log, self.on_log)

    def on_log(self, msg):
        if msg.name == NODE:
            with self.cond:
                self.lines.append(msg)
                self.cond.notify_all()

    def wait_for(self, level, *words):
        def match():
            return [m for m in self.lines if m.level == level and all(w in m.msg for w in words)]
        with self.cond:
            self.cond.wait_for(match, timeout=LOG_WAIT_S)
            return match()

    def close(self):
        self.sub.unregister()


class RosHabits(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        for name in ("step_world", "get_world", "load_scene", "add_body", "reset_world", "resolve_contacts"):
            rospy.wait_for_service("%s/%s" % (NS, name), timeout=SERVICE_WAIT_S)
        cls.step = rospy.ServiceProxy(NS + "/step_world", StepWorld)
        cls.get_world = rospy.ServiceProxy(NS + "/get_world", GetWorld)
        cls.load_scene = rospy.ServiceProxy(NS + "/load_scene", LoadScene)
        cls.add_body = rospy.ServiceProxy(NS + "/add_body", AddBody)
        cls.reset_world = rospy.ServiceProxy(NS + "/reset_world", Trigger)
        cls.resolve = rospy.ServiceProxy(NS + "/resolve_contacts", ResolveContacts)

    def setUp(self):
        self.rosout = RosoutRecorder()
        # The subscription connects asynchronously; a line sent before would be lost.
        deadline = time.time() + LOG_WAIT_S
        while self.rosout.sub.get_num_connections() == 0 and time.time() < deadline:
            time.sleep(0.05)
        self.assertGreater(self.rosout.sub.get_num_connections(), 0, "no connection to the node's /rosout")

    def tearDown(self):
        self.rosout.close()

    def test_readme_rosrun_lines_run_without_a_terminal(self):
        with open(README) as readme:
            lines = ROSRUN_EXAMPLE.findall(readme.read())
        self.assertGreaterEqual(len(lines), 2, "the README's rosrun examples were not found")
        for line in lines:
            run = run_without_terminal(line)
            output = run.stdout + run.stderr
            self.assertEqual(run.returncode, 0, "%s\n->\n%s" % (line, output))
            self.assertIn("contacts:", run.stdout)
            self.assertNotIn("loop", output)
            self.assertNotIn("non-unique", output)
        # No program below the package folder that rosrun searches: only the devel copy runs.
        found = run_without_terminal("find -L \"$(rospack find collision2d)\" -name collision2d_cli")
        self.assertEqual(found.stdout.strip(), "", found.stdout + found.stderr)
        self.assertNotIn("loop", found.stderr)

    def fresh_node_output(self, *params):
        """Starts a world node of its own with these private parameters and
        returns whether it printed its start summary, and what it printed."""
        scenes = os.path.join(run_without_terminal("rospack find collision2d").stdout.strip(), "config", "scenes")
        # rosconsole writes INFO to stdout, which is block-buffered into a pipe unless asked otherwise.
        env = dict(os.environ, ROSCONSOLE_STDOUT_LINE_BUFFERED="1")
        process = subprocess.Popen(
            ["rosrun", "collision2d", "world_node", "__ns:=/habits_fresh", "_scene:=pyramid", "_scenes_dir:=" + scenes]
            + list(params),
            stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
            start_new_session=True, env=env)
        lines = []
        summary = threading.Event()

        def read():
            for line in process.stdout:
                lines.append(line)
                if "services:" in line:
                    summary.set()
        reader = threading.Thread(target=read, daemon=True)
        reader.start()
        try:
            summary.wait(SERVICE_WAIT_S)
        finally:
            process.terminate()
            process.wait(timeout=SERVICE_WAIT_S)
        return summary.is_set(), "".join(lines)

    def test_start_summary_names_scene_settings_and_services(self):
        started, text = self.fresh_node_output()
        self.assertTrue(started, text)
        self.assertIn("INFO", text)
        self.assertIn("scene 'pyramid'", text)
        self.assertIn("bodies", text)
        self.assertIn("substeps", text)
        self.assertIn("/habits_fresh/step_world", text)
        self.assertIn("/habits_fresh/set_body_state", text)

    def test_a_rate_that_cannot_tick_is_refused_with_a_warn(self):
        for rate in ("inf", "nan", "-5.0"):
            started, text = self.fresh_node_output("_rate:=" + rate)
            self.assertTrue(started, text)
            self.assertIn("WARN", text)
            self.assertIn("~rate = ", text)
            self.assertIn("stepping on request", text)

    def test_a_parameter_of_the_wrong_type_is_named_in_a_warn(self):
        started, text = self.fresh_node_output("_rate:=fast", "_max_bodies:=many")
        self.assertTrue(started, text)
        self.assertIn("~rate must be a number; using 0", text)
        self.assertIn("~max_bodies must be an integer; using 5000", text)
        self.assertIn("(steps on request)", text)

    def test_refused_request_is_a_warn_naming_service_body_and_field(self):
        body = Body(id=0, shape=Body.DISK, mass=-float("nan"), radius=0.5)
        body.pose.x = 100.0
        answer = self.add_body(body=body)
        self.assertFalse(answer.success)
        warns = self.rosout.wait_for(Log.WARN, "add_body refused", "mass")
        self.assertTrue(warns, "no WARN for the refused add_body")
        self.assertIn(answer.message, warns[0].msg)

    def test_refused_resolve_contacts_is_a_warn_too(self):
        body = Body(id=7, shape=Body.DISK, mass=-1.0, radius=0.5)
        answer = self.resolve(bodies=[body], settings=SolverSettings(use_node_settings=True))
        self.assertFalse(answer.success)
        self.assertIn("mass", answer.message)
        warns = self.rosout.wait_for(Log.WARN, "resolve_contacts refused", "mass")
        self.assertTrue(warns, "no WARN for the refused resolve_contacts")
        self.assertIn(answer.message, warns[0].msg)

    def test_loads_resets_are_info_and_steps_debug(self):
        self.assertTrue(self.load_scene(scene="pyramid").success)
        self.assertTrue(self.rosout.wait_for(Log.INFO, "loaded scene 'pyramid'"), "no INFO for the load")
        self.assertTrue(self.reset_world().success)
        self.assertTrue(self.rosout.wait_for(Log.INFO, "reset to scene 'pyramid'"), "no INFO for the reset")
        # The per-step line is DEBUG on its own logger: off by default, on through set_logger_level.
        self.assertTrue(self.step(frames=1).success)
        time.sleep(0.5)
        self.assertFalse([m for m in self.rosout.lines if "stepped 1 frames" in m.msg])
        level = run_without_terminal("rosservice call %s/set_logger_level ros.collision2d.step debug" % NODE)
        self.assertEqual(level.returncode, 0, level.stdout + level.stderr)
        self.assertTrue(self.step(frames=2).success)
        self.assertTrue(self.rosout.wait_for(Log.DEBUG, "stepped 2 frames"), "no DEBUG line for the step")

    def test_step_answer_fits_a_terminal_unless_the_state_is_asked_for(self):
        self.assertTrue(self.load_scene(scene="demo").success)
        before = self.get_world().state
        run = run_without_terminal("rosservice call %s/step_world '{frames: 60}'" % NS)
        self.assertEqual(run.returncode, 0, run.stderr)
        lines = run.stdout.splitlines()
        self.assertLessEqual(len(lines), SCREEN_LINES, run.stdout)
        self.assertIn("frame_count: %d" % (before.frame_count + 60), run.stdout)
        self.assertIn("state: []", run.stdout)
        self.assertIn("success: True", run.stdout)
        full = run_without_terminal("rosservice call %s/step_world '{frames: 1, return_state: true}'" % NS)
        self.assertEqual(full.returncode, 0, full.stderr)
        self.assertGreater(len(full.stdout.splitlines()), 10 * len(before.bodies), "no bodies in the state")
        answer = self.step(frames=1, return_state=True)
        self.assertEqual(len(answer.state), 1)
        self.assertEqual(answer.state[0].frame_count, answer.frame_count)
        self.assertEqual(len(answer.state[0].bodies), answer.body_count)

    def test_load_answer_fits_a_terminal_unless_the_state_is_asked_for(self):
        run = run_without_terminal("rosservice call %s/load_scene '{scene: pyramid}'" % NS)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertLessEqual(len(run.stdout.splitlines()), SCREEN_LINES, run.stdout)
        self.assertIn("state: []", run.stdout)
        self.assertIn("success: True", run.stdout)
        answer = self.load_scene(scene="pyramid", return_state=True)
        self.assertEqual(len(answer.state), 1)
        self.assertEqual(answer.state[0].frame_count, answer.frame_count)
        self.assertEqual(len(answer.state[0].bodies), answer.body_count)
        self.assertIn("body_count: %d" % answer.body_count, run.stdout)

    def test_get_world_during_a_long_step_answers_at_once_with_the_last_state(self):
        self.assertTrue(self.load_scene(scene="demo").success)
        step = rospy.ServiceProxy(NS + "/step_world", StepWorld)
        self.assertTrue(step(frames=CALIBRATION_FRAMES).success)  # the scene settles (and may sleep)
        started = time.time()
        self.assertTrue(step(frames=CALIBRATION_FRAMES).success)
        frame_s = (time.time() - started) / CALIBRATION_FRAMES
        most = rospy.get_param(NODE + "/max_frames_per_call")
        long_frames = min(most, max(CALIBRATION_FRAMES, int(math.ceil(LONG_STEP_S / frame_s))))
        before = self.get_world().state.frame_count
        results = {}

        def long_step():
            started = time.time()
            results["step"] = step(frames=long_frames)
            results["step_s"] = time.time() - started

        stepper = threading.Thread(target=long_step)
        stepper.start()
        time.sleep(0.5)  # the step is under way
        started = time.time()
        during = rospy.ServiceProxy(NS + "/get_world", GetWorld)().state
        read_s = time.time() - started
        step_running = stepper.is_alive()
        # A second step waits for the first: steps stay serialized.
        second = step(frames=1)
        stepper.join(COMMAND_TIMEOUT_S)
        rospy.loginfo("get_world took %.3f s during a %d-frame step of %.2f s", read_s, long_frames,
                      results.get("step_s", math.nan))
        self.assertTrue(step_running, "the step ended before get_world was answered: test is vacuous")
        self.assertEqual(during.frame_count, before)
        self.assertLess(read_s, 0.25 * results["step_s"])
        self.assertTrue(results["step"].success, results["step"].message)
        self.assertTrue(second.success, second.message)
        self.assertEqual(second.frame_count, before + long_frames + 1)

    def test_messages_are_printable_text(self):
        with tempfile.NamedTemporaryFile(suffix=".yaml", delete=False) as garbage:
            # A key of raw bytes: invalid UTF-8, a control character and a terminal escape.
            garbage.write(b"name: demo\n\xff\xfe\xc3\x28\x01\x1b[31mbad: 1\n")
        try:
            answer = self.load_scene(scene=garbage.name)
        finally:
            os.unlink(garbage.name)
        self.assertFalse(answer.success)
        self.assertNotIn("\ufffd", answer.message)
        self.assertIn("\\xFF", answer.message)
        self.assertTrue(all(c.isprintable() or c in "\n\t" for c in answer.message), repr(answer.message))
        body = Body(id=0, shape=Body.DISK, mass=1.0, radius=-float("nan"))
        refused = self.add_body(body=body)
        self.assertFalse(refused.success)
        self.assertIn("radius = nan", refused.message)
        self.assertNotIn("-nan", refused.message)


if __name__ == "__main__":
    rospy.init_node("test_ros_habits", anonymous=True)
    rostest.rosrun("collision2d", "ros_habits", RosHabits)
