#!/usr/bin/python3
"""The settings tables as a user meets them: `dynparam set` with a value out of
range is refused (the old value stays, `dynparam get` shows it, a WARN names
the field, value and range), every WorldConfig field survives SetWorld,
SaveWorld, LoadScene and LoadWorld, and a snapshot naming retired settings
loads with a WARN.
"""
import ast
import os
import subprocess
import tempfile
import threading
import unittest

import rospy
import rostest
from geometry_msgs.msg import Vector3
from rosgraph_msgs.msg import Log
from collision2d.msg import WorldConfig
from collision2d.srv import GetWorld, LoadScene, LoadWorld, SaveWorld, SetWorld

SERVICE_WAIT_S = 30.0
WARN_WAIT_S = 10.0
NODE = "/collision2d/world"


def dynparam(*args):
    """Runs the real dynparam tool; its output as text."""
    return subprocess.run(["rosrun", "dynamic_reconfigure", "dynparam"] + list(args), check=True,
                          capture_output=True, text=True, timeout=SERVICE_WAIT_S).stdout


def dynparam_get():
    return ast.literal_eval(dynparam("get", NODE).strip())


def off_default(value, slot_type):
    """Another valid value of a WorldConfig field (uint8: toggles 0..2 and the solver mode 0..1)."""
    if slot_type == "float64":
        return 0.25 if value == 0.0 else 0.75 * value
    if slot_type in ("int32", "uint32"):
        return value + 3
    if slot_type == "bool":
        return not value
    if slot_type == "uint8":
        return (value + 1) % 2
    if slot_type == "geometry_msgs/Vector3":
        return Vector3(x=value.x + 0.25, y=0.75 * value.y, z=0.0)
    raise AssertionError("no rule for a field of type " + slot_type)


class Settings(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_settings")
        for name in ("get_world", "set_world", "save_world", "load_world", "load_scene"):
            rospy.wait_for_service(name, timeout=SERVICE_WAIT_S)
        cls.get_world = rospy.ServiceProxy("get_world", GetWorld)
        cls.warnings = []
        cls.lock = threading.Lock()
        # Every node publishes its log on /rosout (rosout only aggregates it).
        rospy.Subscriber("/rosout", Log, cls.on_log)

    @classmethod
    def on_log(cls, log):
        if log.level == Log.WARN and log.name == NODE:
            with cls.lock:
                cls.warnings.append(log.msg)

    def wait_for_warning(self, *parts):
        deadline = rospy.Time.now() + rospy.Duration(WARN_WAIT_S)
        while rospy.Time.now() < deadline and not rospy.is_shutdown():
            with self.lock:
                if any(all(part in w for part in parts) for w in self.warnings):
                    return
            rospy.sleep(0.1)
        self.fail("no WARN containing %s; seen: %s" % (parts, self.warnings))

    def test_dynparam_refuses_a_world_value_out_of_range(self):
        dt = self.get_world().state.settings.dt
        dynparam("set", NODE, "world_dt", "-1")
        self.assertEqual(dynparam_get()["world_dt"], dt)
        self.assertEqual(self.get_world().state.settings.dt, dt)
        self.wait_for_warning("world_dt = -1", "(0, inf)")
        # A valid value goes through.
        dynparam("set", NODE, "world_dt", "0.01")
        self.assertEqual(self.get_world().state.settings.dt, 0.01)
        self.assertEqual(dynparam_get()["world_dt"], 0.01)

    def test_dynparam_refuses_a_solver_value_out_of_range(self):
        before = dynparam_get()["solver_restitution"]
        dynparam("set", NODE, "solver_restitution", "1.5")
        self.assertEqual(dynparam_get()["solver_restitution"], before)
        self.wait_for_warning("solver_restitution = 1.5", "[0, 1]")
        dynparam("set", NODE, "world_substeps", "0")
        self.assertGreaterEqual(dynparam_get()["world_substeps"], 1)
        self.wait_for_warning("world_substeps = 0", "[1, inf)")

    def test_every_world_field_survives_save_and_load(self):
        settings = self.get_world().state.settings
        changed = WorldConfig()
        for name, slot_type in zip(WorldConfig.__slots__, WorldConfig._slot_types):
            setattr(changed, name, off_default(getattr(settings, name), slot_type))
        set_response = rospy.ServiceProxy("set_world", SetWorld)(bodies=[], settings=changed)
        self.assertTrue(set_response.success, set_response.message)
        path = os.path.join(tempfile.mkdtemp(), "settings.snapshot.yaml")
        saved = rospy.ServiceProxy("save_world", SaveWorld)(path=path)
        self.assertTrue(saved.success, saved.message)
        demo = rospy.ServiceProxy("load_scene", LoadScene)(scene="demo")
        self.assertTrue(demo.success, demo.message)
        loaded = rospy.ServiceProxy("load_world", LoadWorld)(path=path)
        self.assertTrue(loaded.success, loaded.message)
        back = self.get_world().state.settings
        for name in WorldConfig.__slots__:
            self.assertNotEqual(getattr(changed, name), getattr(settings, name), name)
            self.assertEqual(getattr(back, name), getattr(changed, name), name)
        # dynamic_reconfigure shows the loaded settings too.
        shown = dynparam_get()
        self.assertEqual(shown["world_warm_start_before_integration"], changed.warm_start_before_integration)
        self.assertEqual(shown["world_sleep_auto_min_bodies"], changed.sleep_auto_min_bodies)
        self.assertEqual(shown["world_toi_displacement_fraction"], changed.toi_displacement_fraction)

    def test_a_snapshot_naming_retired_settings_loads_with_a_warn(self):
        path = os.path.join(tempfile.mkdtemp(), "old.snapshot.yaml")
        saved = rospy.ServiceProxy("save_world", SaveWorld)(path=path)
        self.assertTrue(saved.success, saved.message)
        before = self.get_world().state.settings
        with open(path) as f:
            text = f.read()
        self.assertIn("\nsettings:\n", text)
        # As an earlier version wrote it: the retired warm-start knobs among the settings.
        retired = "  warm_start_factor: 0.9\n  warm_start_every_substep: false\n"
        text = text.replace("\nsettings:\n", "\nsettings:\n" + retired, 1)
        with open(path, "w") as f:
            f.write(text)
        loaded = rospy.ServiceProxy("load_world", LoadWorld)(path=path)
        self.assertTrue(loaded.success, loaded.message)
        self.wait_for_warning("settings.warm_start_factor is retired and ignored")
        self.wait_for_warning("settings.warm_start_every_substep is retired and ignored")
        self.assertEqual(self.get_world().state.settings, before)


if __name__ == "__main__":
    rostest.rosrun("collision2d", "settings", Settings)
