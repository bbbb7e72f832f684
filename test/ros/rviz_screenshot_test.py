#!/usr/bin/python3
"""rostest node: a real rviz, on a virtual display with software OpenGL, draws
the demo world. scripts/rviz_screenshot.sh steps the demo to a known frame,
photographs rviz and checks body-coloured pixels where the world state says
the bodies are (and none where there is no body); this test fails with the
checker's report when it does not."""

import os
import subprocess
import sys
import unittest

import rostest

PKG = "collision2d"
HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "..", "scripts", "rviz_screenshot.sh")
# One second of the demo: the box thrown at the pyramid has just hit it.
FRAMES = 60
# Below the rostest time-limit in rviz_screenshot.test, so a hang is reported here.
TIMEOUT_S = 200


class RvizDrawsTheWorld(unittest.TestCase):
    def test_bodies_are_drawn_where_the_world_has_them(self):
        ros_home = os.environ.get("ROS_HOME", os.path.expanduser("~/.ros"))
        screenshot = os.path.join(ros_home, "collision2d_rviz_screenshot.png")
        script = subprocess.Popen([SCRIPT, "--frames", str(FRAMES), screenshot], stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT, universal_newlines=True)
        try:
            output, _ = script.communicate(timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            script.terminate()  # the script stops its Xvfb, master and nodes on SIGTERM
            output, _ = script.communicate()
            self.fail("rviz_screenshot.sh did not finish in %d s:\n%s" % (TIMEOUT_S, output))
        sys.stdout.write(output)
        self.assertEqual(script.returncode, 0,
                         "rviz did not draw the world (screenshot %s):\n%s" % (screenshot, output))


if __name__ == "__main__":
    rostest.rosrun(PKG, "rviz_screenshot", RvizDrawsTheWorld)
