"""Unit tests of the throughput part's speed-up of 2 workers over 1
(report_analysis.worker_speedup_rounds, report_targets.throughput_target_rows,
report_guidance.guidance_workers and guidance_memory), on a clock and
beside a busy core (report_analysis.round_speedups, report_sections.paced_table
and busy_table):
run by scripts/test.sh with the other test_*.py files."""
import unittest

from report_analysis import round_speedups, worker_speedup_rounds
from report_data import median_runs
from report_guidance import guidance_memory, guidance_workers
from report_sections import busy_table, paced_table
from report_targets import throughput_target_rows


def row(engine, workers, bodies, ms):
    return {"engine": engine, "scene": "pyramid", "bodies": str(bodies), "workers": str(workers), "frames": "10",
            "ms_per_step": str(ms), "cpu_ms_per_step": str(ms), "vmhwm_kib": "1000", "vmhwm_start_kib": "100"}


class WorkerSpeedupTest(unittest.TestCase):
    def setUp(self):
        # Ours in three rounds, each 1 worker then 2; Box2D v3 in one, as
        # the reports ran it before it joined the rounds.
        ours = [(40.0, 20.0), (60.0, 40.0), (44.0, 22.0)]
        rows = []
        for one, two in ours:
            rows += [row("collision2d", 1, 9870, one), row("collision2d", 2, 9870, two)]
        rows += [row("box2d_v3", 1, 9870, 26.0), row("box2d_v3", 2, 9870, 13.0)]
        self.scaling = median_runs(rows)

    def test_each_engine_pairs_its_own_rounds(self):
        self.assertEqual(worker_speedup_rounds(self.scaling, "pyramid"), [(9870, [2.0, 1.5, 2.0])])
        self.assertEqual(worker_speedup_rounds(self.scaling, "pyramid", "box2d_v3"), [(9870, [2.0])])

    def test_the_target_row_judges_ours_and_shows_the_peer(self):
        (target,) = [r for r in throughput_target_rows(self.scaling, [], "soft") if r[0].startswith("2 workers")]
        self.assertIn("pyramid 9870: 2x (1.5 - 2, 3 rounds)", target[1])
        self.assertIn("(Box2D v3, one round: pyramid 9870: 2x)", target[1])
        self.assertEqual(target[2], "met")

    def test_the_peer_in_the_same_rounds_shows_its_median_and_range(self):
        rows = []
        for one, two in [(40.0, 20.0), (60.0, 40.0), (44.0, 22.0)]:
            rows += [row("collision2d", 1, 9870, one), row("collision2d", 2, 9870, two)]
            rows += [row("box2d_v3", 1, 9870, one / 2), row("box2d_v3", 2, 9870, two / 3)]
        (target,) = [r for r in throughput_target_rows(median_runs(rows), [], "soft") if r[0].startswith("2 workers")]
        self.assertIn("(Box2D v3, 3 rounds: pyramid 9870: 3x (2.25 - 3))", target[1])

    def test_without_the_peer_at_two_workers_the_row_names_ours_only(self):
        scaling = [r for r in self.scaling if not (r["engine"] == "box2d_v3" and r["workers"] == "2")]
        (target,) = [r for r in throughput_target_rows(scaling, [], "soft") if r[0].startswith("2 workers")]
        self.assertNotIn("Box2D v3", target[1])


class WorkersGuidanceTest(unittest.TestCase):
    def test_it_names_the_worlds_a_second_worker_paid_in(self):
        rows = [row("collision2d", 1, 990, 1.0), row("collision2d", 2, 990, 1.1),
                row("collision2d", 1, 9870, 13.0), row("collision2d", 2, 9870, 8.0)]
        line = guidance_workers(median_runs(rows))
        self.assertIn("pyramid 990 bodies 0.909x, 9870 bodies 1.62x", line)
        self.assertIn("paid (1.2x or more) in: pyramid 9870; not in: pyramid 990", line)
        self.assertIn("keep 1 worker below some 10000 bodies", line)

    def test_where_none_paid_it_says_keep_one(self):
        rows = [row("collision2d", 1, 990, 1.0), row("collision2d", 2, 990, 0.95)]
        line = guidance_workers(median_runs(rows))
        self.assertIn("in: none; not in: pyramid 990", line)
        self.assertIn("So keep 1 worker.", line)

    def test_without_throughput_rounds_there_is_no_line(self):
        self.assertIsNone(guidance_workers([]))


class MemoryGuidanceTest(unittest.TestCase):
    def test_it_spans_the_cheapest_and_costliest_large_worlds(self):
        def peak(engine, scene, bodies, kib):
            return dict(row(engine, 1, bodies, 1.0), scene=scene, vmhwm_kib=str(100 + kib * bodies))
        rows = [peak("collision2d", "pyramid", 9870, 5.0), peak("collision2d", "pyramid", 99681, 4.5),
                peak("collision2d", "rain", 100000, 1.5), peak("box2d_v3", "rain", 100000, 1.0),
                peak("collision2d", "rain", 1000, 9.0)]  # under 1e4 bodies: not counted
        line = guidance_memory(median_runs(rows))
        self.assertIn("pyramid 99681 4.5 kB, rain 100000 1.5 kB (Box2D v3 1)", line)
        self.assertIn("Plan on 1.5 to 4.5 kB a body (rain 100000 to pyramid 99681)", line)
        self.assertNotIn("9870", line)

    def test_without_large_worlds_there_is_no_line(self):
        self.assertIsNone(guidance_memory(median_runs([row("collision2d", 1, 990, 1.0)])))



def paced_row(scene, workers, period, ms):
    return dict(row("collision2d", workers, 9870, ms), scene=scene, period_ms=str(period))


class PacedTest(unittest.TestCase):
    def setUp(self):
        # Two rounds, each 1 worker then 2, at two periods, as the script runs them.
        self.paced = []
        for one, two in [(12.0, 6.0), (11.0, 8.0)]:
            for period in (16.667, 100):
                self.paced += [paced_row("pyramid", 1, period, one), paced_row("pyramid", 2, period, two)]

    def test_each_round_is_paired_with_its_own_two_worker_run(self):
        self.assertEqual(round_speedups(self.paced),
                         [("pyramid", 9870, 16.667, 11.5, 7.0, [2.0, 11.0 / 8.0]),
                          ("pyramid", 9870, 100, 11.5, 7.0, [2.0, 11.0 / 8.0])])

    def test_the_table_and_the_guidance_give_the_median_speed_up(self):
        self.assertIn("| pyramid | 9870 | 100 | 11.5 | 7 | 1.69x (1.38 - 2) |", paced_table(self.paced))
        line = guidance_workers(median_runs([row("collision2d", 1, 9870, 13.0), row("collision2d", 2, 9870, 8.0)]),
                                self.paced)
        self.assertIn("one frame every 16.7, 100 ms", line)
        self.assertIn("pyramid 9870 1.69x, 1.69x", line)

    def test_without_paced_runs_nothing_is_said(self):
        self.assertEqual(paced_table([]), "")
        line = guidance_workers(median_runs([row("collision2d", 1, 9870, 13.0), row("collision2d", 2, 9870, 8.0)]))
        self.assertNotIn("clock", line)


def busy_row(engine, scene, workers, ms):
    return dict(row(engine, workers, 9870, ms), scene=scene, period_ms="0", busy_cpu="0")


class BusyTest(unittest.TestCase):
    def setUp(self):
        # Three rounds, each engine 1 worker then 2, as the script runs them beside the busy loop.
        self.busy = []
        for ours, v3 in [((10.0, 11.0), (5.0, 5.0)), ((10.0, 10.5), (5.0, 6.0)), ((12.0, 10.0), (5.0, 4.0))]:
            self.busy += [busy_row("collision2d", "pyramid", 1, ours[0]),
                          busy_row("collision2d", "pyramid", 2, ours[1]),
                          busy_row("box2d_v3", "pyramid", 1, v3[0]), busy_row("box2d_v3", "pyramid", 2, v3[1])]
        self.scaling = median_runs([row("collision2d", 1, 9870, 13.0), row("collision2d", 2, 9870, 8.0)])

    def test_each_engine_pairs_its_own_rounds(self):
        (ours,) = round_speedups(self.busy)
        self.assertEqual(ours[:3], ("pyramid", 9870, 0))
        self.assertEqual(ours[5], [10.0 / 11.0, 10.0 / 10.5, 1.2])
        (v3,) = round_speedups(self.busy, "box2d_v3")
        self.assertEqual(v3[5], [1.0, 5.0 / 6.0, 1.25])

    def test_the_table_names_the_busy_core_and_both_engines(self):
        text = busy_table(self.busy)
        self.assertIn("kept core 0 busy", text)
        self.assertIn("3 rounds", text)
        self.assertIn("| pyramid | 9870 | ours | 10 | 10.5 | 0.952x (0.909 - 1.2) |", text)
        self.assertIn("| pyramid | 9870 | Box2D v3 | 5 | 5 | 1x (0.833 - 1.25) |", text)

    def test_the_guidance_gives_the_measured_medians_and_their_verdict(self):
        line = guidance_workers(self.scaling, (), self.busy)
        self.assertIn("a shell loop on core 0): pyramid 9870 0.952x (Box2D v3: pyramid 9870 1x)", line)
        self.assertIn("a second worker pays only on a core of its own", line)
        faster = [dict(r, ms_per_step="5") if r["engine"] == "collision2d" and r["workers"] == "2" else r
                  for r in self.busy]
        self.assertIn("still paid (1.2x or more) in: pyramid 9870", guidance_workers(self.scaling, (), faster))

    def test_without_busy_runs_nothing_is_said(self):
        self.assertEqual(busy_table([]), "")
        self.assertNotIn("busy", guidance_workers(self.scaling))


if __name__ == "__main__":
    unittest.main()
