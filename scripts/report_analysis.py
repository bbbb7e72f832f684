"""Selections and comparisons over the benchmark rows, shared by the plots,
targets, guidance and sections of the performance report: our runs and the
peers' per scene, baselines, Pareto fronts, time-target pairs, stack rows,
throughput rows, worker speed-ups and scaling slopes."""
import math
import statistics

from report_data import PEERS, SCENE_ORDER, is_ours, is_stiff, number
from report_format import finite, label, setting


def ours(runs, scene, include_stand=False, pipeline=None):
    return [r for r in runs if r["scene"] == scene and is_ours(r) and (include_stand or r["part"] != "stand")
            and (pipeline is None or r["pipeline"] == pipeline)]


def peers(runs, scene):
    return [r for r in runs if r["scene"] == scene and not is_ours(r)]


def find(runs, scene, knob, value=None, pipeline=None):
    for r in ours(runs, scene, pipeline=pipeline):
        if r["part"] == "world" and r["knob"] == knob and (value is None or r["value"] == value):
            return r
    return None


def baseline(runs, scene, pipeline):
    return find(runs, scene, "baseline", pipeline=pipeline)


def other(pipeline):
    return "fx2d" if pipeline == "soft" else "soft"


def default_pipeline(*tables):
    for rows in tables:
        for r in rows:
            if r.get("default_pipeline"):
                return r["default_pipeline"]
    return "fx2d"  # reports made before the soft step existed


def pareto(points):
    """Cheapest-first points whose error beats every cheaper point."""
    front, best = [], float("inf")
    for p in sorted(points, key=lambda r: r["ms"]):
        if finite(p["err"]) and p["err"] < best:
            front.append(p)
            best = p["err"]
    return front


def at_error(our_runs, error):
    """Our runs whose main error is equal or better than `error`."""
    return [r for r in our_runs if finite(r["err"]) and r["err"] <= error]


def cheapest_at(our_runs, error, key="ms"):
    ok = at_error(our_runs, error)
    return min(ok, key=lambda r: r[key]) if ok else None


# Our runs at a peer run's error that are timed again beside it in paired
# rounds: the cheapest few by the sweep's own timing, and the cheapest of
# each of the cheapest few settings (pipeline, substeps and iterations).
PAIRED_CANDIDATES = 3


def setting_of(run):
    return run["pipeline"], run["substeps"], run["iterations"]


def candidates_at(our_runs, error):
    """The sweep times each run once: a spell of slowness can put a cheap
    setting behind several knobs' runs of a dearer one that cost alike, so
    the cheapest run of each of the cheapest settings is timed again too."""
    ranked = sorted(at_error(our_runs, error), key=lambda r: r["ms"])
    picked = ranked[:PAIRED_CANDIDATES]
    settings = []
    for r in ranked:
        if len(settings) == PAIRED_CANDIDATES:
            break
        if setting_of(r) not in settings:
            settings.append(setting_of(r))
            if r not in picked:
                picked.append(r)
    return picked


def round_ratio(mine, peer, column):
    """Median over the paired rounds of each round's own time ratio mine /
    peer (column 0 wall, 1 CPU), the rounds' count and the lowest and highest
    of those ratios; None unpaired."""
    both = sorted(set(mine.get("paired_rounds", {})) & set(peer.get("paired_rounds", {})))
    if not both:
        return None
    a, b = mine["paired_rounds"], peer["paired_rounds"]
    ratios = [a[k][column] / b[k][column] for k in both]
    return statistics.median(ratios), len(both), min(ratios), max(ratios)


def time_target_rows(runs, scene):
    """Per peer run: our cheapest run (either pipeline) at equal or better
    error, and the ratio: from paired rounds when the run has them (the
    candidate with the lowest median ratio), else from the sweep's times."""
    rows = []
    mine = ours(runs, scene)
    for p in [r for r in peers(runs, scene) if r["engine"] in PEERS]:
        best = cheapest_at(mine, p["err"])
        best_cpu = cheapest_at(mine, p["err"], "cpu")
        ratio = best["ms"] / p["ms"] if best else float("inf")
        ratio_cpu = best_cpu["cpu"] / p["cpu"] if best_cpu else float("inf")
        rounds, spread = 0, None
        paired = [(c, round_ratio(c, p, 0), round_ratio(c, p, 1)) for c in candidates_at(mine, p["err"])]
        paired = [t for t in paired if t[1] and t[2]]
        if paired:
            best, (ratio, rounds, low, high), _ = min(paired, key=lambda t: t[1][0])
            ratio_cpu = min(t[2][0] for t in paired)
            spread = (low, high)
        rows.append({"peer": label(p), "peer_ms": p["ms"], "peer_err": p["err"],
                     "ours": setting(best) if best else "not reached",
                     "ours_ms": best["ms"] if best else float("nan"),
                     "ours_err": best["err"] if best else float("nan"), "ratio": ratio, "ratio_cpu": ratio_cpu,
                     "rounds": rounds, "spread": spread})
    return rows


def time_target_scenes(runs):
    return [s for s in scene_names(runs) if ours(runs, s) and any(r["engine"] in PEERS for r in peers(runs, s))]


def scene_order(name):
    return (SCENE_ORDER.index(name) if name in SCENE_ORDER else len(SCENE_ORDER), name)


def scene_names(runs):
    return sorted({r["scene"] for r in runs}, key=scene_order)


def least_squares_slope(points):
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else float("nan")


def ratio(a, b):
    if not (finite(a) and finite(b)):
        return float("nan")
    if b == 0:
        return 1.0 if a == 0 else float("inf")
    return a / b


def gas_rows(scaling):
    """The elastic-gas scaling runs (files written before the scene column are all gas)."""
    return [r for r in scaling if r.get("scene", "gas") in ("gas", "", None)]


def throughput_rows(scaling, scene, engine, workers="1"):
    rows = [r for r in scaling if r.get("scene") == scene and r["engine"] == engine and r.get("workers", "1") == workers]
    return sorted(rows, key=lambda r: number(r["bodies"]))


def peak_kib_per_body(scaling, scenes, engine, min_bodies=1e4):
    """(scene, bodies, peak resident memory above the empty process in kB a body) of each 1-worker
    throughput row of at least min_bodies bodies, scene by scene in size order."""
    return [(r["scene"], r["bodies"],
             (number(r["vmhwm_kib"]) - number(r["vmhwm_start_kib"])) / number(r["bodies"]))
            for sc in scenes for r in throughput_rows(scaling, sc, engine)
            if number(r["bodies"]) >= min_bodies and r.get("vmhwm_start_kib")]


def peak_kib_beside_peer(scaling, scenes, peer="box2d_v3"):
    """peak_kib_per_body of ours, each with the peer's kB a body at the same scene and size (None
    where the peer did not run it): (scene, bodies, ours, peer)."""
    theirs = {(scene, b): x for scene, b, x in peak_kib_per_body(scaling, scenes, peer)}
    return [(scene, b, x, theirs.get((scene, b))) for scene, b, x in peak_kib_per_body(scaling, scenes, "collision2d")]


def worker_speedup_rounds(scaling, scene, engine="collision2d"):
    """(bodies, [time with 1 worker / time with 2, one per round]) for each size run both ways,
    ascending: each round's own ratio (its 1-worker run and the 2-worker run right after it), so
    a machine that slows down between rounds does not skew it. A size whose rounds do not pair
    up (one failed) gets the ratio of its two medians alone."""
    one = {r["bodies"]: r for r in throughput_rows(scaling, scene, engine, "1")}
    two = {r["bodies"]: r for r in throughput_rows(scaling, scene, engine, "2")}
    rounds = []
    for b in one.keys() & two.keys():
        # median_runs keeps each size's times in round order; a round that failed leaves them unpaired.
        t1, t2 = one[b]["round_times"], two[b]["round_times"]
        ratios = [x / y for x, y in zip(t1, t2) if y > 0] if len(t1) == len(t2) else []
        if not ratios and number(two[b]["ms_per_step"]) > 0:
            ratios = [number(one[b]["ms_per_step"]) / number(two[b]["ms_per_step"])]
        if ratios:
            rounds.append((number(b), ratios))
    return sorted(rounds, key=lambda x: x[0])


def worker_speedups(scaling, scene, engine="collision2d"):
    """(bodies, median over the rounds of the speed-up of 2 workers over 1), ascending."""
    return [(b, statistics.median(ratios)) for b, ratios in worker_speedup_rounds(scaling, scene, engine)]


def round_speedups(rows, engine="collision2d"):
    """For worlds run in rounds of a 1-worker run and the 2-worker run after it (paced.csv: stepped
    on a clock; busy.csv: beside a busy core), in scene, size and period order: (scene, bodies,
    period in ms (0: back to back), median ms a frame on 1 worker, on 2, [each round's speed-up])."""
    times = {}
    for r in rows:
        if r["engine"] == engine and r.get("workers") in ("1", "2"):
            key = (r["scene"], number(r["bodies"]), number(r["period_ms"]))
            times.setdefault(key, {"1": [], "2": []})[r["workers"]].append(number(r["ms_per_step"]))
    out = []
    for (scene, bodies, period), t in sorted(times.items()):
        ratios = [x / y for x, y in zip(t["1"], t["2"]) if y > 0]
        if ratios:
            out.append((scene, bodies, period, statistics.median(t["1"]), statistics.median(t["2"]), ratios))
    return out


def stack_rows(stacks, scene, pipeline=None, engine="collision2d", seconds=None, stiff=False):
    """The stack bench's row of an engine at a checkpoint (the longest by default); ours at the
    defaults, or with stiff=True the stiff soft-step row (CSV variant "stiff")."""
    rows = [r for r in stacks if r["scene"] == scene and r["engine"] == engine
            and (pipeline is None or r["pipeline"] == pipeline) and is_stiff(r) == stiff]
    if seconds is None and rows:
        seconds = max(r["seconds"] for r in rows)
    rows = [r for r in rows if r["seconds"] == seconds]
    return rows[0] if rows else None


def scaling_slope(scaling, engine, scenes=("gas",), workers="1"):
    pts = [(number(r["bodies"]), number(r["ms_per_step"])) for r in scaling if r["engine"] == engine
           and r.get("scene", "gas") in scenes and r.get("workers", "1") == workers]
    pts = [p for p in pts if finite(p[1]) and p[1] > 0]
    return least_squares_slope(pts) if len(pts) >= 2 else float("nan")
