#!/usr/bin/env python3
"""Prints the runs that the time target times again in paired rounds, one
scene per line (tab-separated: the scene, then the runs' keys): every peer
run of the target, and for each, our cheapest runs at its error.

The sweep times each run once, minutes apart from the others, and this
machine's speed drifts within minutes; our cheapest run, the fastest of
dozens, tends to be one timed in a fast spell. scripts/performance_report.sh
times these runs again with the sweep bench's `paired` part, every run once
a round, and the target takes the median of each round's own ratio.

    report_pairs.py RUNS_CSV
"""
import sys

from report_analysis import candidates_at, ours, peers, time_target_scenes
from report_data import PEERS, prepare, read_csv, run_key


def paired_keys(runs, scene):
    keys = []
    mine = ours(runs, scene)
    for p in [r for r in peers(runs, scene) if r["engine"] in PEERS]:
        for r in [p] + candidates_at(mine, p["err"]):
            if run_key(r) not in keys:
                keys.append(run_key(r))
    return keys


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    runs = prepare(read_csv(sys.argv[1]))
    for scene in time_target_scenes(runs):
        keys = paired_keys(runs, scene)
        if len(keys) > 1:
            print("\t".join([scene] + keys))


if __name__ == "__main__":
    main()
