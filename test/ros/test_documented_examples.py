#!/usr/bin/python3
"""Runs the command-line examples of docs/ros_interface.md, exactly as written.

Every ```bash block of the document that calls a service or dynparam is run
in order against the node (started as the document says). A block must exit 0;
a block marked `# expect: success: False` must be answered with
success: False, any other block with no success: False.
"""
import os
import re
import subprocess
import unittest

import rospy
import rostest

DOC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "ros_interface.md")
BLOCK = re.compile(r"^```bash\n(.*?)^```", re.MULTILINE | re.DOTALL)
FAILURE_MARK = "# expect: success: False"
COMMAND_TIMEOUT_S = 60.0
SERVICE_WAIT_S = 30.0


def runnable_blocks(text):
    return [b for b in BLOCK.findall(text) if "rosservice call" in b or "dynparam" in b]


class DocumentedExamples(unittest.TestCase):
    def test_examples_run_as_documented(self):
        rospy.wait_for_service("/collision2d/resolve_contacts", timeout=SERVICE_WAIT_S)
        with open(DOC) as doc:
            blocks = runnable_blocks(doc.read())
        # The document shows both services, the world services and tuning.
        self.assertGreaterEqual(len(blocks), 5)
        for block in blocks:
            with self.subTest(block=block.splitlines()[0]):
                run = subprocess.run(["bash", "-e", "-c", block], capture_output=True, text=True,
                                     timeout=COMMAND_TIMEOUT_S)
                output = run.stdout + run.stderr
                self.assertEqual(run.returncode, 0, "%s\n->\n%s" % (block, output))
                if FAILURE_MARK in block:
                    self.assertIn("success: False", output, block)
                    self.assertNotIn("success: True", output, block)
                else:
                    self.assertNotIn("success: False", output, "%s\n->\n%s" % (block, output))


if __name__ == "__main__":
    rospy.init_node("test_documented_examples", anonymous=True)
    rostest.rosrun("collision2d", "documented_examples", DocumentedExamples)
