"""Unit tests of the time target's paired rounds (report_pairs.py,
report_data.attach_paired, report_analysis.time_target_rows): run by
scripts/test.sh as `python3 -m unittest discover -s scripts -p 'test_*.py'`."""
import statistics
import unittest

from report_analysis import time_target_rows
from report_data import attach_paired, prepare, run_key
from report_pairs import paired_keys


def run(part, engine, variant, knob, value, ms, err, pipeline="soft", substeps="1", iterations="2"):
    ours = engine == "collision2d"
    return {"part": part, "scene": "s", "engine": engine, "variant": variant, "pipeline": pipeline if ours else "",
            "knob": knob, "value": value, "substeps": substeps, "iterations": iterations,
            "ms_per_step": str(ms), "cpu_ms_per_step": str(ms), "error": str(err), "max_penetration_m": "0",
            "solver_mode": "iterative" if ours else "", "slop": "0.005"}


def rounds(key, times):
    return [{"scene": "s", "round": str(k), "key": key, "ms_per_step": str(t), "cpu_ms_per_step": str(t)}
            for k, t in enumerate(times)]


class PairedRoundsTest(unittest.TestCase):
    def setUp(self):
        # The peer, and four runs of ours at or below its error (one above it).
        self.peer = run("peers", "chipmunk", "defaults", "defaults", "", 1.0, 0.01, substeps="", iterations="")
        self.fast = run("world", "collision2d", "matched", "substeps", "1", 0.5, 0.001)
        self.slow = run("world", "collision2d", "matched", "substeps", "2", 0.6, 0.001, substeps="2")
        self.third = run("world", "collision2d", "matched", "substeps", "4", 0.7, 0.01, substeps="4")
        self.fourth = run("world", "collision2d", "matched", "substeps", "8", 0.8, 0.0, substeps="8")
        self.inaccurate = run("world", "collision2d", "matched", "iterations", "1", 0.1, 0.5)
        self.runs = prepare([self.peer, self.fast, self.slow, self.third, self.fourth, self.inaccurate])

    def test_keys_name_the_peer_and_our_three_cheapest_at_its_error(self):
        self.assertEqual(run_key(self.peer), "peers|chipmunk|defaults||defaults|||")
        self.assertEqual(paired_keys(self.runs, "s"),
                         [run_key(r) for r in [self.peer, self.fast, self.slow, self.third]])

    def test_the_cheapest_settings_are_timed_again_too(self):
        # Three knobs' runs of the 2-substep setting were timed cheaper than
        # the 1-substep one: the latter is timed again all the same.
        knobs = [run("world", "collision2d", "matched", knob, "x", 0.4, 0.001, substeps="2")
                 for knob in ["contact_hertz", "warm_starting", "speculative_margin"]]
        runs = prepare([self.peer, self.fast, self.slow, self.third, self.fourth] + knobs)
        keys = paired_keys(runs, "s")
        self.assertEqual(keys[:4], [run_key(r) for r in [self.peer] + knobs])
        self.assertEqual(keys[4:], [run_key(r) for r in [self.fast, self.third]])

    def test_without_rounds_the_sweep_times_decide(self):
        attach_paired(self.runs, [])
        (row,) = time_target_rows(self.runs, "s")
        self.assertEqual(row["rounds"], 0)
        self.assertAlmostEqual(row["ratio"], self.fast["ms"] / self.peer["ms"])

    def test_the_median_of_each_rounds_own_ratio_and_the_best_candidate(self):
        # The peer's speed drifts from round to round. `slow` keeps pace with
        # it; `fast` drifts out of phase, cheap only in the rounds where the
        # peer is slow.
        peer = [1.0, 3.0, 1.0, 3.0, 3.0]
        slow = [0.6, 1.8, 0.6, 1.8, 1.8]
        fast = [0.9, 0.9, 2.7, 2.7, 0.9]
        paired = rounds(run_key(self.peer), peer) + rounds(run_key(self.fast), fast) + rounds(run_key(self.slow), slow)
        attach_paired(self.runs, paired)
        (row,) = time_target_rows(self.runs, "s")
        per_round = {name: statistics.median(t / p for t, p in zip(times, peer))
                     for name, times in [("slow", slow), ("fast", fast)]}
        self.assertLess(per_round["slow"], per_round["fast"])
        self.assertEqual(row["rounds"], len(peer))
        self.assertAlmostEqual(row["ratio"], per_round["slow"])
        self.assertAlmostEqual(row["ratio_cpu"], per_round["slow"])
        low, high = row["spread"]
        self.assertAlmostEqual(low, min(t / p for t, p in zip(slow, peer)))
        self.assertAlmostEqual(high, max(t / p for t, p in zip(slow, peer)))
        self.assertIn("2x2", row["ours"])
        # A ratio of the medians would have picked `fast`, at a third.
        self.assertLess(statistics.median(fast) / statistics.median(peer), per_round["slow"])


if __name__ == "__main__":
    unittest.main()
