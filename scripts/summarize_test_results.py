#!/usr/bin/python3
"""Count passed and failed test cases in a catkin test_results folder.

Prints "N passed, M failed" as the last line; exits 1 when M > 0 or when no
test ran, so a silent or empty suite cannot pass.

Counting rules (one count per real test case):
- gtest (gtest-*.xml) and the results of rostest's test nodes (rosunit-*.xml)
  count every test case; a case with <failure> or <error> fails, a skipped or
  disabled one is neither.
- rostest-*.xml holds one wrapper case per test node ("test<name>"), which
  only restates rosunit-<name>.xml. A wrapper counts only when it fails and
  rosunit-<name>.xml does not already explain it (node crashed, timed out or
  wrote no results).
- A file that is not valid XML, and each error or failure a suite reports
  beyond those its test cases carry (a crash before any case ran, a failed
  unittest subTest under rosunit), count as failures.
"""
import os
import sys
import xml.etree.ElementTree as ElementTree

ROSTEST_PREFIX = "rostest-"
ROSUNIT_PREFIX = "rosunit-"
WRAPPER_CASE_PREFIX = "test"
SKIPPED_RESULTS = ("skipped", "suppressed")


class Tally:
    def __init__(self):
        self.passed = 0
        self.failed = 0
        self.skipped = 0
        self.failures = []

    def fail(self, what):
        self.failed += 1
        self.failures.append(what)


def case_failed(case):
    return case.find("failure") is not None or case.find("error") is not None


def case_skipped(case):
    return (case.find("skipped") is not None
            or case.get("status") == "notrun"
            or case.get("result") in SKIPPED_RESULTS)


def case_label(path, case):
    return "%s: %s.%s" % (os.path.basename(path), case.get("classname", "?"),
                          case.get("name", "?"))


def count_cases(path, root, tally):
    for case in root.iter("testcase"):
        if case_failed(case):
            tally.fail(case_label(path, case))
        elif case_skipped(case):
            tally.skipped += 1
        else:
            tally.passed += 1
    # A suite can report errors that no case carries: a crash before any case
    # ran, or a failed unittest subTest, which rosunit counts in the suite
    # but writes under a passing case. Those would otherwise vanish.
    for suite in root.iter("testsuite"):
        reported = int(suite.get("errors", 0)) + int(suite.get("failures", 0))
        attributed = sum(1 for case in suite.findall("testcase") if case_failed(case))
        for _ in range(reported - attributed):
            tally.fail("%s: suite %s reports an error outside its test cases"
                       % (os.path.basename(path), suite.get("name", "?")))


def node_results_have_failures(folder, test_name):
    path = os.path.join(folder, ROSUNIT_PREFIX + test_name + ".xml")
    try:
        root = ElementTree.parse(path).getroot()
    except (OSError, ElementTree.ParseError):
        return False
    return any(case_failed(case) for case in root.iter("testcase"))


def count_rostest_wrappers(path, root, tally):
    folder = os.path.dirname(path)
    for case in root.iter("testcase"):
        if not case_failed(case):
            continue
        name = case.get("name", "")
        if name.startswith(WRAPPER_CASE_PREFIX):
            name = name[len(WRAPPER_CASE_PREFIX):]
        if not node_results_have_failures(folder, name):
            tally.fail(case_label(path, case))


def count_file(path, tally):
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as error:
        tally.fail("%s: unreadable (%s)" % (path, error))
        return
    if root.tag not in ("testsuite", "testsuites"):
        return
    if os.path.basename(path).startswith(ROSTEST_PREFIX):
        count_rostest_wrappers(path, root, tally)
    else:
        count_cases(path, root, tally)


def result_files(results_dir):
    for folder, _, names in sorted(os.walk(results_dir)):
        for name in sorted(names):
            if name.endswith(".xml"):
                yield os.path.join(folder, name)


def main(argv):
    if len(argv) != 2:
        sys.stderr.write("usage: %s <test_results folder>\n" % argv[0])
        return 2
    tally = Tally()
    for path in result_files(argv[1]):
        count_file(path, tally)
    for failure in tally.failures:
        print("FAILED " + failure)
    if tally.skipped:
        print("%d skipped or disabled" % tally.skipped)
    if tally.passed + tally.failed == 0:
        print("no test ran")
    print("%d passed, %d failed" % (tally.passed, tally.failed))
    return 1 if tally.failed or tally.passed == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
