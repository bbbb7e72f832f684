#!/usr/bin/env python3
"""Writes docs/performance.md and the PNG plots from the benchmark CSVs.

Called by scripts/performance_report.sh after the measurements; reads
runs.csv, paired.csv, solver.csv, scaling.csv, stacks.csv and, when the
run made them, paced.csv and busy.csv from --perf-dir. Only the standard library and gnuplot are used. Every number in the report comes from those
CSVs: nothing here is typed in by hand.

Ours runs in two pipelines (the `pipeline` column: soft = the soft step,
fx2d = the Fx2D order); `default_pipeline` names the one a default
WorldSettings uses in the build measured, so the report follows whichever
is the default.
"""
import argparse
import os
import tempfile

# The report's parts are the report_*.py modules beside this script: run as a
# script, its own folder is first on sys.path, so they import from any cwd.
from report_data import PARETO_SCENES, attach_paired, median_runs, prepare, prepare_stacks, read_csv
from report_analysis import default_pipeline
from report_plots import plot_pareto, plot_scaling, plot_throughput, plot_workers
from report_document import render


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--perf-dir", required=True)
    parser.add_argument("--doc", required=True)
    parser.add_argument("--elapsed", default="?")
    parser.add_argument("--quick", action="store_true")
    # Re-rendering saved CSVs: the commit, date, kernel and load average of the run that measured them.
    parser.add_argument("--commit", default="")
    parser.add_argument("--date", default="", help="YYYY-MM-DD the CSVs were measured (default: today)")
    parser.add_argument("--kernel", default="", help="the kernel release they were measured on (default: this one)")
    parser.add_argument("--load", default="")
    parser.add_argument("--pinned-cpu", default="", help="the core the single-threaded runs were pinned to")
    args = parser.parse_args()

    runs = prepare(read_csv(os.path.join(args.perf_dir, "runs.csv")))
    attach_paired(runs, read_csv(os.path.join(args.perf_dir, "paired.csv")))
    solver = read_csv(os.path.join(args.perf_dir, "solver.csv"))
    scaling = median_runs(read_csv(os.path.join(args.perf_dir, "scaling.csv")))
    stacks = prepare_stacks(read_csv(os.path.join(args.perf_dir, "stacks.csv")))
    paced = read_csv(os.path.join(args.perf_dir, "paced.csv"))  # [] for a run before it was measured
    busy = read_csv(os.path.join(args.perf_dir, "busy.csv"))  # [] likewise, or with one core
    world_has_exact = any(r["solver_mode"] == "exact" for r in runs)
    default = default_pipeline(runs, stacks)

    plots = []
    with tempfile.TemporaryDirectory() as work:
        for scene in PARETO_SCENES:
            png = os.path.join(args.perf_dir, f"pareto_{scene}.png")
            if plot_pareto(runs, scene, png, work, default):
                plots.append(f"![{scene}](perf/pareto_{scene}.png)")
        scaling_png = plot_scaling(scaling, os.path.join(args.perf_dir, "scaling.png"), work)
        if plot_throughput(scaling, os.path.join(args.perf_dir, "throughput.png"), work):
            plots_extra = ["![throughput](perf/throughput.png)"]
        else:
            plots_extra = []
        if plot_workers(scaling, os.path.join(args.perf_dir, "workers.png"), work):
            plots_extra.append("![workers](perf/workers.png)")

    doc = render(args, runs, solver, scaling, stacks, world_has_exact, plots, scaling_png, default, plots_extra,
                 paced, busy)
    with open(args.doc, "w") as f:
        f.write(doc)


if __name__ == "__main__":
    main()
