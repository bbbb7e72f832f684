#!/usr/bin/env python3
"""Writes docs/performance.md and the PNG plots from the benchmark CSVs.

Called by scripts/performance_report.sh after the measurements; reads
runs.csv, solver.csv, scaling.csv and stacks.csv from --perf-dir. Only the standard
library and gnuplot are used. Every number in the report comes from those
CSVs: nothing here is typed in by hand.

Ours runs in two pipelines (the `pipeline` column: soft = the soft step,
fx2d = the Fx2D order); `default_pipeline` names the one a default
WorldSettings uses in the build measured, so the report follows whichever
is the default.
"""
import argparse
import csv
import datetime
import math
import os
import platform
import statistics
import subprocess
import tempfile

HEADLINE = ["pyramid", "column", "elastic_gas"]
PARETO_SCENES = ["pyramid", "column", "elastic_gas", "newtons_cradle", "bouncing_disks", "incline",
                 "incline_slide"]
SCENE_ORDER = ["pyramid", "column", "elastic_gas", "newtons_cradle", "bouncing_disks", "incline", "incline_slide",
               "bullet_wall", "bullet_wall_1e4"]
PIPELINES = ["soft", "fx2d"]
PIPELINE_NAMES = {"soft": "soft step", "fx2d": "Fx2D"}
PIPELINE_PHRASES = {"soft": "the soft step", "fx2d": "the Fx2D pipeline"}
PEER_NAMES = {"box2d": "Box2D 2.4.1", "chipmunk": "Chipmunk 7", "box2d_v3": "Box2D v3"}
TIME_TARGET = 0.75          # our time / a peer run's at equal or better accuracy
DRIFT_TARGET_M = 1e-3       # stacks stand 60 s with drift below this
SLOPE_TARGET = 1.1          # log time vs log n
PLOT_FLOOR = 1e-9           # zero errors are drawn here on the log axes
PEERS = ["box2d", "chipmunk"]
# Box2D v3 joins only when the script was given a build of it (sweep, stacks,
# scaling). The time target stays against PEERS; the stacks' time target is
# against Box2D v3.
OPTIONAL_PEERS = ["box2d_v3"]
STACK_SCENES = ["stack_pyramid_20", "stack_column_20", "stack_pyramid_60", "stack_pyramid_100"]
STACK_DRIFT_TARGET_M = {"stack_pyramid_100": 1e-2}  # the others: DRIFT_TARGET_M
STACK_PENETRATION_TARGET_M = 5e-3
STACK_TIME_TARGET = 2.0     # our CPU ms/frame / Box2D v3's on each stack
STACK_TARGET_SECONDS = 60.0
BOUNCE_TARGET = 1e-3        # |measured e - e| at the defaults
INCLINE_TARGET = 1e-6       # m/s^2 at the defaults
GAS_TARGET = 1e-6           # relative kinetic energy drift over the gas run at the defaults
GAS_TARGET_SECONDS = 10.0
FAST_BULLET = "bullet_wall_1e4"
ERROR_UNITS = {"drift_m": "drift after settling (m)", "energy_error": "relative energy error",
               "bounce_error": "|measured e - e|", "incline_accel_error": "acceleration error (m/s^2)",
               "tunnelled": "tunnelled (1 = yes)"}
# How a knob of ours reads in a setting's label ({} is its value).
KNOB_LABELS = {"warm_starting": "warm {}", "time_of_impact": "TOI {}", "position_iterations": "{} position passes",
               "position_block": "position block {}", "warm_start_every_substep": "warm every substep {}",
               "warm_start_factor": "warm factor {}", "exact_position_correction": "exact position correction {}",
               "contact_hertz": "{} Hz", "contact_damping_ratio": "damping ratio {}",
               "contact_push_speed": "push {} m/s", "speculative_margin": "margin {} m", "sleeping": "sleeping {}"}
# Plot colours: ours per pipeline (all points, front), the peers.
COLOURS = {"soft": ("#f1b6da", "#c51b7d"), "fx2d": ("#9ecae1", "#08519c"), "box2d": "#ff7f00",
           "chipmunk": "#238b45", "box2d_v3": "#6a3d9a"}


# ---------------------------------------------------------------------------
# Reading

def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def median_runs(rows):
    """One row per (engine, scene, bodies, workers): the run of median time."""
    groups = {}
    for r in rows:
        groups.setdefault((r["engine"], r.get("scene"), r["bodies"], r.get("workers", "1")), []).append(r)
    picked = []
    for runs in groups.values():
        in_order = [number(r["ms_per_step"]) for r in runs]  # one per round, as the script ran them
        runs = sorted(runs, key=lambda r: number(r["ms_per_step"]))
        picked.append(dict(runs[(len(runs) - 1) // 2], rounds=len(runs), round_times=in_order))
    return picked


def throughput_rounds(scaling):
    """How many rounds ours ran at each throughput size (the script alternates 1 and 2 workers)."""
    return max((r["rounds"] for r in scaling if r["engine"] == "collision2d" and r.get("workers", "1") == "2"),
               default=1)


def finite(x):
    return not (math.isnan(x) or math.isinf(x))


def fmt(x, digits=3):
    if isinstance(x, str):
        return x
    if x is None or math.isnan(x):
        return "-"
    if math.isinf(x):
        return "inf"
    if x == 0:
        return "0"
    return f"{x:.{digits}g}"


def over(ratio):
    """A miss ratio (> 1) with the digits it needs not to read as 1: 1.002, not 1."""
    digits = 3
    while fmt(ratio, digits) == "1" and digits < 6:
        digits += 1
    return fmt(ratio, digits)


def mm(x):
    """A length in metres, written in millimetres."""
    return fmt(x * 1e3) + " mm" if finite(x) else fmt(x)


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(fmt(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def is_ours(run):
    return run["engine"] == "collision2d"


def setting(run):
    """The setting of a run: ours with its pipeline first, a peer's variant."""
    if not is_ours(run) and run["variant"] == "defaults":
        return "defaults"
    if run["engine"] in OPTIONAL_PEERS:
        return f"{run['substeps']} substeps"  # Box2D v3 has no iteration count
    label = f"{run['substeps']}x{run['iterations']}"
    if not is_ours(run):
        return label
    extras = []
    knob, value = run["knob"], run["value"]
    if knob == "slop":
        extras.append(f"slop {run['slop']}")
    elif knob in KNOB_LABELS:
        extras.append(KNOB_LABELS[knob].format(value))
    elif knob in ("compliance", "precise"):
        extras.append(value)
    if (knob == "warm_before_integration" and value.endswith(" on")) or (
            knob == "stand" and value.endswith("warm before integration")):
        extras.append("warm before integration")
    if run["solver_mode"] == "exact":
        extras.append("exact")
    return f"{PIPELINE_NAMES[run['pipeline']]} {label}" + (" " + ", ".join(extras) if extras else "")


def label(run):
    if is_ours(run):
        return "ours " + setting(run)
    return f"{PEER_NAMES.get(run['engine'], run['engine'])} {setting(run)}"


# ---------------------------------------------------------------------------
# Analysis

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


def cheapest_at(our_runs, error, key="ms"):
    ok = [r for r in our_runs if finite(r["err"]) and r["err"] <= error]
    return min(ok, key=lambda r: r[key]) if ok else None


def time_target_rows(runs, scene):
    """Per peer run: our cheapest run (either pipeline) at equal or better error, and the ratio."""
    rows = []
    mine = ours(runs, scene)
    for p in [r for r in peers(runs, scene) if r["engine"] in PEERS]:
        best = cheapest_at(mine, p["err"])
        best_cpu = cheapest_at(mine, p["err"], "cpu")
        ratio = best["ms"] / p["ms"] if best else float("inf")
        ratio_cpu = best_cpu["cpu"] / p["cpu"] if best_cpu else float("inf")
        rows.append({"peer": label(p), "peer_ms": p["ms"], "peer_err": p["err"],
                     "ours": setting(best) if best else "not reached",
                     "ours_ms": best["ms"] if best else float("nan"),
                     "ours_err": best["err"] if best else float("nan"), "ratio": ratio, "ratio_cpu": ratio_cpu})
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


def verdict(value, target, strict=True):
    """met, or missed by value / target (a value of 0 against a 0 target is met)."""
    if not finite(value):
        return "not measured" if math.isnan(value) else "missed"
    ok = value < target if strict else value <= target
    if ok:
        return "met"
    return f"missed by {over(value / target)}x" if target > 0 else "missed"


def ratio(a, b):
    if not (finite(a) and finite(b)):
        return float("nan")
    if b == 0:
        return 1.0 if a == 0 else float("inf")
    return a / b


# ---------------------------------------------------------------------------
# Plots

def gnuplot(script, workdir):
    path = os.path.join(workdir, "plot.gp")
    with open(path, "w") as f:
        f.write(script)
    subprocess.run(["gnuplot", path], check=True)


def write_points(path, points):
    with open(path, "w") as f:
        for p in points:
            f.write(f"{p['ms']:.9g} {max(p['err'], PLOT_FLOOR):.9g}\n")


def plot_pareto(runs, scene, png, workdir, default):
    """Ours as two series (all settings and the Pareto front per pipeline,
    the defaults marked), the peers as points."""
    if not ours(runs, scene):
        return False
    series = []  # (file stem, points, gnuplot style, title)
    for pipeline in sorted(PIPELINES, key=lambda p: p != default):
        mine = ours(runs, scene, pipeline=pipeline)
        if not mine:
            continue
        light, dark = COLOURS[pipeline]
        name = PIPELINE_NAMES[pipeline]
        tag = " (default pipeline)" if pipeline == default else ""
        base = baseline(runs, scene, pipeline)
        series.append((f"{pipeline}_all", mine, f"points pt 7 ps 0.7 lc rgb '{light}'",
                       f"ours {name}{tag}: all settings"))
        series.append((f"{pipeline}_front", pareto(mine), f"linespoints pt 7 ps 0.9 lw 2 lc rgb '{dark}'",
                       f"ours {name}: Pareto front"))
        if base:
            series.append((f"{pipeline}_defaults", [base], f"points pt 6 ps 2.4 lw 2 lc rgb '{dark}'",
                           f"ours {name}: defaults {base['substeps']}x{base['iterations']}"))
    shapes = {"box2d": (5, 4), "chipmunk": (9, 8), "box2d_v3": (13, 12)}
    for engine in PEERS + OPTIONAL_PEERS:
        for variant, shape, size in [("defaults", 0, 1.6), ("matched", 1, 1.3)]:
            points = [r for r in peers(runs, scene) if r["engine"] == engine and r["variant"] == variant]
            if points:
                series.append((f"{engine}_{variant}", points,
                               f"points pt {shapes[engine][shape]} ps {size} lc rgb '{COLOURS[engine]}'",
                               f"{PEER_NAMES[engine]} {variant}"))
    for stem, points, _, _ in series:
        write_points(os.path.join(workdir, stem + ".dat"), points)
    mine = ours(runs, scene)
    ylabel = ERROR_UNITS.get(mine[0]["error_name"], mine[0]["error_name"])
    plot = ", \\\n     ".join(f"'{workdir}/{stem}.dat' with {style} title '{title}'"
                             for stem, _, style, title in series)
    gnuplot(f"""set terminal pngcairo size 960,760 noenhanced
set output '{png}'
set title '{scene}: accuracy against time per frame (lower left is better)'
set logscale xy
set xlabel 'wall time per frame (ms, median)'
set ylabel '{ylabel} (below {PLOT_FLOOR:g}, 0 included: drawn at {PLOT_FLOOR:g})'
set grid
set key below horizontal maxcols 3 width -4
plot {plot}
""", workdir)
    return True


def gas_rows(scaling):
    """The elastic-gas scaling runs (files written before the scene column are all gas)."""
    return [r for r in scaling if r.get("scene", "gas") in ("gas", "", None)]


def points_line(workdir, name, points, title, style=""):
    """Writes (x, y) points to workdir/name.dat; returns their gnuplot plot clause."""
    with open(os.path.join(workdir, name + ".dat"), "w") as f:
        for x, y in points:
            f.write(f"{x} {y}\n")
    return f"'{workdir}/{name}.dat' with linespoints pt 7 lw 2 {style} title '{title}'"


def plot_time_against_bodies(series, png, title, xlabel, workdir):
    """One log-log line per (name, rows, label, style) of time per frame against bodies."""
    lines = []
    for name, rows, label, style in series:
        if not rows:
            continue
        lines.append(points_line(workdir, name, [(r["bodies"], r["ms_per_step"]) for r in rows], label, style))
    if not lines:
        return False
    gnuplot(f"""set terminal pngcairo size 800,560 noenhanced
set output '{png}'
set title '{title}'
set logscale xy
set xlabel '{xlabel}'
set ylabel 'wall time per frame (ms, median)'
set grid
set key left top
plot {", ".join(lines)}, x/100.0 * 0.1 dt 2 lc rgb 'gray' title 'slope 1 (reference)'
""", workdir)
    return True


def plot_scaling(scaling, png, workdir):
    scaling = gas_rows(scaling)
    series = [(engine + "_scaling", [r for r in scaling if r["engine"] == engine], engine, "")
              for engine in ["collision2d"] + PEERS + OPTIONAL_PEERS]
    return plot_time_against_bodies(series, png, "Scaling: elastic gas of n disks (ours at its defaults, peers at theirs)",
                                    "bodies", workdir)


THROUGHPUT_SCENES = ["pyramid", "rain"]
WORKER_SPEEDUP_TARGET = 1.7
WORKER_SPEEDUP_MIN_BODIES = 5000
MEMORY_TARGET_KIB_PER_BODY = 1.0
# "Per-frame cost follows what moves", read as: a settled world's frame, and
# one where a single body moves, cost at most this fraction of the same world
# awake.
RESTING_FRACTION_TARGET = 0.01


def throughput_rows(scaling, scene, engine, workers="1"):
    rows = [r for r in scaling if r.get("scene") == scene and r["engine"] == engine and r.get("workers", "1") == workers]
    return sorted(rows, key=lambda r: number(r["bodies"]))


def plot_throughput(scaling, png, workdir):
    series = []
    for scene in THROUGHPUT_SCENES:
        for engine, workers in [("collision2d", "1"), ("collision2d", "2"), ("box2d_v3", "1")]:
            label = f"{scene}: {'ours' if engine == 'collision2d' else 'Box2D v3'}" + \
                (f", {workers} worker{'s' if workers != '1' else ''}" if engine == "collision2d" else "")
            series.append((f"{scene}_{engine}_{workers}", throughput_rows(scaling, scene, engine, workers), label,
                           "dt 1" if scene == "pyramid" else "dt 3"))
    return plot_time_against_bodies(series, png, "Throughput: time per frame against bodies (4 substeps, sleeping off)",
                                    "dynamic bodies", workdir)


def worker_speedups(scaling, scene):
    """(bodies, time with 1 worker / time with 2) for each size run both ways, ascending: the
    median over the rounds of each round's own ratio (its 1-worker run and the 2-worker run right
    after it), so a machine that slows down between rounds does not skew it."""
    one = {r["bodies"]: r for r in throughput_rows(scaling, scene, "collision2d", "1")}
    two = {r["bodies"]: r for r in throughput_rows(scaling, scene, "collision2d", "2")}
    speedups = []
    for b in one.keys() & two.keys():
        # median_runs keeps each size's times in round order; a round that failed leaves them unpaired.
        t1, t2 = one[b]["round_times"], two[b]["round_times"]
        ratios = [x / y for x, y in zip(t1, t2) if y > 0] if len(t1) == len(t2) else []
        if ratios:
            speedups.append((number(b), statistics.median(ratios)))
        elif number(two[b]["ms_per_step"]) > 0:
            speedups.append((number(b), number(one[b]["ms_per_step"]) / number(two[b]["ms_per_step"])))
    return sorted(speedups)


def plot_workers(scaling, png, workdir):
    lines = []
    for scene in THROUGHPUT_SCENES:
        pts = worker_speedups(scaling, scene)
        if not pts:
            continue
        lines.append(points_line(workdir, f"speedup_{scene}", pts, scene))
    if not lines:
        return False
    gnuplot(f"""set terminal pngcairo size 800,480 noenhanced
set output '{png}'
set title 'Ours: speed-up of 2 workers over 1 (wall time per frame)'
set logscale x
set xlabel 'dynamic bodies'
set ylabel 'time with 1 worker / time with 2'
set yrange [0:2.2]
set grid
set key left top
plot {", ".join(lines)}, {WORKER_SPEEDUP_TARGET} dt 2 lc rgb 'gray' title 'target {WORKER_SPEEDUP_TARGET}'
""", workdir)
    return True


def throughput_target_rows(scaling, stacks, default):
    rows = []
    big = stack_rows(stacks, "stack_pyramid_100", default, seconds=max((r["seconds"] for r in stacks), default=0))
    if big and finite(big["cpu_ms_over_box2d_v3"]):
        rows.append(["base-100 pyramid, 1 worker: ms/frame <= 1x Box2D v3's",
                     f"CPU {fmt(big['cpu_ms_over_box2d_v3'])}x ({fmt(big['cpu_ms_per_frame'])} ms)",
                     verdict(big["cpu_ms_over_box2d_v3"], 1.0, strict=False)])
    else:
        rows.append(["base-100 pyramid, 1 worker: ms/frame <= 1x Box2D v3's", "Box2D v3 not in this run",
                     "not measured"])
    speedups = [(scene, int(b), x) for scene in THROUGHPUT_SCENES for b, x in worker_speedups(scaling, scene)
                if b >= WORKER_SPEEDUP_MIN_BODIES]
    if speedups:
        worst = min(speedups, key=lambda x: x[2])
        rows.append([f"2 workers >= {WORKER_SPEEDUP_TARGET}x faster than 1 at >= {WORKER_SPEEDUP_MIN_BODIES} bodies",
                     ", ".join(f"{sc} {b}: {fmt(x)}x" for sc, b, x in speedups),
                     "met" if worst[2] >= WORKER_SPEEDUP_TARGET else
                     f"missed by {over(WORKER_SPEEDUP_TARGET / worst[2])}x ({worst[0]} {worst[1]})"])
    slope = scaling_slope(scaling, "collision2d", scenes=tuple(THROUGHPUT_SCENES))
    rows.append([f"slope of log time against log bodies <= {SLOPE_TARGET} (pyramid and rain, 1 worker)",
                 f"{fmt(slope)}", "met" if finite(slope) and slope <= SLOPE_TARGET else
                 f"missed by {fmt(slope - SLOPE_TARGET)}" if finite(slope) else "not measured"])
    def peak_per_body(engine):
        return [(r["scene"], r["bodies"], (number(r["vmhwm_kib"]) - number(r["vmhwm_start_kib"])) / number(r["bodies"]))
                for sc in THROUGHPUT_SCENES for r in throughput_rows(scaling, sc, engine)
                if number(r["bodies"]) >= 1e4 and r.get("vmhwm_start_kib")]
    mem = peak_per_body("collision2d")
    peer = {(sc, b): x for sc, b, x in peak_per_body("box2d_v3")}
    if mem:
        worst = max(mem, key=lambda x: x[2])
        rows.append([f"peak memory above the empty process <= {fmt(MEMORY_TARGET_KIB_PER_BODY)} kB per body "
                     "(1e4 bodies and up)",
                     ", ".join(f"{sc} {b}: {fmt(x)} kB" + (f" (Box2D v3 {fmt(peer[(sc, b)])} kB)" if (sc, b) in peer
                                                            else "") for sc, b, x in mem),
                     "met" if worst[2] <= MEMORY_TARGET_KIB_PER_BODY else
                     f"missed by {over(worst[2] / MEMORY_TARGET_KIB_PER_BODY)}x ({worst[0]} {worst[1]})"])
    rows.extend(resting_target_rows(scaling))
    rows.append(["identical trajectories for 1, 2 and 4 workers",
                 "checked by the unit test WorldGoldenRuns.WorkersDoNotChangeTrajectories (every bit of five "
                 "golden runs)", "tested, not measured here"])
    return rows


def resting_target_rows(scaling):
    awake = {r["bodies"]: number(r["ms_per_step"]) for r in throughput_rows(scaling, "pyramid", "collision2d")}
    rows = []
    for scene, what in [("resting", "a settled world (resting pyramid)"),
                        ("stirred", "a world where one body moves (stirred: the resting pyramid and one kinematic disk)")]:
        settled = {r["bodies"]: number(r["ms_per_step"]) for r in throughput_rows(scaling, scene, "collision2d")}
        peer = {r["bodies"]: number(r["ms_per_step"]) for r in throughput_rows(scaling, scene, "box2d_v3")}
        both = [(b, settled[b] / awake[b]) for b in settled if b in awake and awake[b] > 0]
        if not both:
            continue
        worst = max(both, key=lambda x: x[1])
        measured = ", ".join(f"{b} bodies: {fmt(settled[b])} ms, {fmt(awake[b])} ms awake ({fmt(x)})" +
                             (f", Box2D v3 {fmt(peer[b])} ms" if b in peer else "") for b, x in both)
        rows.append([f"{what} costs <= {fmt(RESTING_FRACTION_TARGET)} of the same world awake", measured,
                     "met" if worst[1] <= RESTING_FRACTION_TARGET else
                     f"missed by {over(worst[1] / RESTING_FRACTION_TARGET)}x ({worst[0]} bodies)"])
    return rows


def throughput_section(scaling, stacks, default):
    runs = [r for r in scaling if r.get("scene") in THROUGHPUT_SCENES + ["resting", "stirred"]]
    if not runs:
        return "Not measured in this run.\n"
    rows = [[r["scene"], r["engine"], r["workers"], r["bodies"], r["frames"], number(r["ms_per_step"]),
             number(r["ms_per_step"]) * 1e3 / number(r["bodies"]),
             (number(r["vmhwm_kib"]) - number(r["vmhwm_start_kib"])) / number(r["bodies"])]
            for r in sorted(runs, key=lambda r: (r["scene"], r["engine"], r["workers"], number(r["bodies"])))]
    return (table(["target", "measured", "verdict"], throughput_target_rows(scaling, stacks, default)) + "\n" +
            table(["scene", "engine", "workers", "bodies", "timed frames", "ms/frame (wall)", "us per body",
                   "peak memory above start (kB/body)"], rows))


# ---------------------------------------------------------------------------
# Report sections

def prepare(runs):
    for r in runs:
        r["ms"] = number(r["ms_per_step"])
        r["cpu"] = number(r["cpu_ms_per_step"])
        r["err"] = number(r["error"])
        r["pen"] = number(r["max_penetration_m"])
        # Runs made before the soft step existed are all Fx2D.
        r["pipeline"] = r.get("pipeline") or ("fx2d" if is_ours(r) else "")
    return runs


def prepare_stacks(stacks):
    for r in stacks:
        r["pipeline"] = r.get("pipeline") or ("fx2d" if is_ours(r) else "")
        for key in ["ms_per_frame", "cpu_ms_per_frame", "ms_over_box2d_v3", "cpu_ms_over_box2d_v3", "seconds",
                    "drift_m", "max_penetration_m"]:
            r[key] = number(r[key])
    return stacks


def has_v3(runs, stacks, scaling):
    return any(r["engine"] == "box2d_v3" for r in list(runs) + list(stacks) + list(scaling))


def machine_section(args, runs, stacks, scaling, default):
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    commit = args.commit
    try:
        commit = commit or subprocess.run(["git", "-C", os.path.dirname(os.path.abspath(__file__)), "rev-parse",
                                           "--short", "HEAD"], capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = "unknown"
    load = args.load or ", ".join(f"{x:.1f}" for x in os.getloadavg())
    today = datetime.date.today().isoformat()
    grid = "quick (--quick: thinned grids, stacks to 10 s, stands to 20 s)" if args.quick else "full"
    v3 = ("**Box2D v3 was included** in this run as a third peer (built from a checkout outside this repository, "
          "given through `COLLISION2D_BOX2D_V3_DIR`)" if has_v3(runs, stacks, scaling) else
          "**Box2D v3 was not included** in this run (the script was not given `COLLISION2D_BOX2D_V3_DIR`), so "
          "there are no ratios to it")
    return (f"- Machine: {model}, {os.cpu_count()} logical cores, {platform.system()} {platform.release()}; "
            f"load average at report time {load} (the cores were shared with other work, see *Timing*).\n"
            f"- Measured {today} at commit `{commit}` (plus any uncommitted changes in the tree), {grid} grids, "
            f"all measurements in one run of `scripts/performance_report.sh` taking {args.elapsed} s.\n"
            f"- Peers: Box2D 2.4.1 and Chipmunk 7 in every part; {v3}.\n"
            f"- Ours in both pipelines, each run naming its own: the **soft step** (`soft_step: true`) and the "
            f"**Fx2D** order (`soft_step: false`). The default in the build measured: the "
            f"**{PIPELINE_PHRASES[default].replace('the ', '', 1)}**.\n")


# -- Guidance -----------------------------------------------------------------

def both(runs, scene, default, fn):
    """fn(run) for the default pipeline's baseline, then the other's, as text."""
    parts = []
    for p in [default, other(default)]:
        b = baseline(runs, scene, p)
        if b:
            parts.append(f"{PIPELINE_NAMES[p]} {fn(b)}")
    return " against ".join(parts)


def better_pipeline(a, b):
    """The pipeline of the run with the lower error (the cheaper on a tie)."""
    if a is None or b is None:
        return (a or b)["pipeline"] if (a or b) else None
    ea, eb = a["err"], b["err"]
    if ea == eb or (not finite(ea) and not finite(eb)):
        return a["pipeline"] if a["ms"] <= b["ms"] else b["pipeline"]
    if not finite(ea):
        return b["pipeline"]
    if not finite(eb):
        return a["pipeline"]
    return a["pipeline"] if ea < eb else b["pipeline"]


def stack_rows(stacks, scene, pipeline=None, engine="collision2d", seconds=None):
    rows = [r for r in stacks if r["scene"] == scene and r["engine"] == engine
            and (pipeline is None or r["pipeline"] == pipeline)]
    if seconds is None and rows:
        seconds = max(r["seconds"] for r in rows)
    rows = [r for r in rows if r["seconds"] == seconds]
    return rows[0] if rows else None


def guidance_pipeline(runs, stacks, default):
    """Which pipeline wins where, at the defaults, over every scene of the sweep."""
    wins = {p: [] for p in PIPELINES}
    for scene in scene_names(runs):
        a, b = baseline(runs, scene, "soft"), baseline(runs, scene, "fx2d")
        if a and b and finite(a["err"]) and finite(b["err"]) and a["err"] != b["err"]:
            wins[better_pipeline(a, b)].append(scene)
    stack_wins = {p: [] for p in PIPELINES}
    for scene in STACK_SCENES:
        a, b = stack_rows(stacks, scene, "soft"), stack_rows(stacks, scene, "fx2d")
        if a and b and a["drift_m"] != b["drift_m"]:
            stack_wins["soft" if a["drift_m"] < b["drift_m"] else "fx2d"].append(scene)
    line = (f"- **Which pipeline.** The default here is {PIPELINE_PHRASES[default]}. At the defaults "
            f"(4 substeps x 2 iterations) the soft step had the lower main error on "
            f"{len(wins['soft'])} of the sweep's scenes ({', '.join(wins['soft']) or 'none'}) and Fx2D on "
            f"{len(wins['fx2d'])} ({', '.join(wins['fx2d']) or 'none'}); scenes not named tied")
    if any(stack_wins.values()):
        line += (f"; on the Box2D v3 comparison stacks the soft step drifted less on {len(stack_wins['soft'])} "
                 f"of {len(stack_wins['soft']) + len(stack_wins['fx2d'])}")
    cheaper = [s for s in scene_names(runs)
               if baseline(runs, s, "soft") and baseline(runs, s, "fx2d")
               and baseline(runs, s, "soft")["cpu"] < baseline(runs, s, "fx2d")["cpu"]]
    measured = [s for s in scene_names(runs) if baseline(runs, s, "soft") and baseline(runs, s, "fx2d")]
    if measured:
        line += (f". The soft step's defaults cost less CPU time than Fx2D's on {len(cheaper)} of "
                 f"{len(measured)} scenes (it finds contacts once a frame instead of every substep)")
    # Whether velocity_iterations changed anything in the soft step of this build.
    pairs = [(r, baseline(runs, r["scene"], "soft")) for r in runs
             if r["part"] == "world" and r["pipeline"] == "soft" and r["knob"] == "iterations"]
    pairs = [(r, b) for r, b in pairs if b]
    if pairs and all(r["err"] == b["err"] and r["pen"] == b["pen"] for r, b in pairs):
        line += (f". In this build `velocity_iterations` did not change any result of the soft step ({len(pairs)} "
                 f"runs at other iteration counts matched their defaults exactly): it solves each substep once and "
                 f"relaxes once, so tune it with the substeps and the contact knobs")
    return line + ". Per use:"


def guidance_stacks(runs, stacks, default):
    parts = []
    scenes = [s for s in STACK_SCENES if stack_rows(stacks, s, "soft") or stack_rows(stacks, s, "fx2d")]
    for scene in scenes:
        cells = []
        for p in PIPELINES:
            r = stack_rows(stacks, scene, p)
            if r:
                cells.append(f"{PIPELINE_NAMES[p]} drift {mm(r['drift_m'])}, penetration "
                             f"{mm(r['max_penetration_m'])}, {fmt(r['cpu_ms_per_frame'])} ms")
        if cells:
            parts.append(f"  - {scene.replace('stack_', '')}: " + "; ".join(cells))
    soft_better = []
    for scene in scenes:
        a, b = stack_rows(stacks, scene, "soft"), stack_rows(stacks, scene, "fx2d")
        if a and b and a["drift_m"] < b["drift_m"]:
            soft_better.append(scene)
    pick = "soft" if len(soft_better) * 2 > len(scenes) else "fx2d"
    won = soft_better if pick == "soft" else [s for s in scenes if s not in soft_better]
    lost = [s for s in scenes if s not in won]
    line = (f"- **Stacks.** Use {PIPELINE_PHRASES[pick]}: at the defaults over "
            f"{fmt(max((r['seconds'] for r in stacks), default=float('nan')))} s it drifted less on "
            f"{len(won)} of {len(scenes)} stacks of the Box2D v3 comparison"
            + (f" (not on {', '.join(lost)}, where {PIPELINE_PHRASES[other(pick)]} drifted less)" if lost else "")
            + "; drift from 1 s, largest penetration and CPU time per frame:"
            if scenes else "- **Stacks.** No stack bench rows in this run")
    lines = [line] + parts
    # The cheapest long stand under 1 mm, and the steadiest, per pipeline.
    for scene in ["column", "pyramid"]:
        stand = [r for r in runs if r["part"] == "stand" and r["scene"] == scene]
        cells = []
        for p in PIPELINES:
            mine = [r for r in stand if r["pipeline"] == p and finite(r["err"])]
            if not mine:
                continue
            under = cheapest_at(mine, DRIFT_TARGET_M, "cpu")
            steadiest = min(mine, key=lambda r: (r["err"], r["cpu"]))
            cell = f"{PIPELINE_NAMES[p]}: "
            cell += (f"cheapest under 1 mm {setting(under)} ({mm(under['err'])}, {fmt(under['cpu'])} ms)"
                     if under else "no setting under 1 mm")
            cell += f", steadiest {setting(steadiest)} ({mm(steadiest['err'])}, {fmt(steadiest['cpu'])} ms)"
            cells.append(cell)
        if cells:
            seconds = fmt(max(number(r["seconds"]) for r in stand))
            lines.append(f"  - The sweep's base-20 {scene} over {seconds} s: " + "; ".join(cells) + ".")
    soft_pen = [stack_rows(stacks, s, "soft") for s in scenes]
    fx_pen = [stack_rows(stacks, s, "fx2d") for s in scenes]
    if all(soft_pen) and all(fx_pen) and soft_pen and fx_pen:
        deeper = sum(1 for a, b in zip(soft_pen, fx_pen) if a["max_penetration_m"] > b["max_penetration_m"])
        lines.append(f"  - The soft step's contacts carry weight by compressing: it rested deeper than Fx2D on "
                     f"{deeper} of {len(scenes)} stacks; where penetration matters more than drift, raise "
                     f"`contact_hertz` with the substeps (it is capped at a quarter of the substep rate).")
    exact = [r for r in [find(runs, "column", "solver_mode", "exact", p) for p in PIPELINES] if r]
    tail = "  - Let large resting scenes sleep (Auto sleeps worlds of 256+ bodies)"
    if exact:
        tail = ("  - The exact solver mode on the 20-box column: " +
                "; ".join(f"{PIPELINE_NAMES[r['pipeline']]} drift {mm(r['err'])} at {fmt(r['cpu'])} ms a frame"
                          for r in exact) +
                " (too costly for large clusters: the pyramid is not run exact). Let large resting scenes sleep "
                "(Auto sleeps worlds of 256+ bodies)")
    lines.append(tail + ".")
    return "\n".join(lines)


def guidance_fast(runs, default):
    line = "- **Fast bodies.** "
    cells = []
    for scene, speed in [("bullet_wall", "500 m/s"), (FAST_BULLET, "1e4 m/s")]:
        for p in PIPELINES:
            b = baseline(runs, scene, p)
            off = find(runs, scene, "time_of_impact", "off", p)
            if b:
                cell = (f"{PIPELINE_NAMES[p][0].upper() + PIPELINE_NAMES[p][1:]} at {speed}: "
                        f"{'tunnels' if b['err'] > 0 else 'stops at the wall'} "
                        f"at the defaults")
                if off:
                    cell += f", {'tunnels' if off['err'] > 0 else 'still stops'} with time of impact Off"
                margin = find(runs, scene, "speculative_margin", None, p)
                if margin:
                    cell += (f", {'tunnels' if margin['err'] > 0 else 'stops'} with speculative margin "
                             f"{margin['value']} m")
                cells.append(cell)
    if not cells:
        return None
    advice = []
    for p in PIPELINES:
        off = [find(runs, s, "time_of_impact", "off", p) for s in ["bullet_wall", FAST_BULLET]]
        if any(r and r["err"] > 0 for r in off):
            advice.append(f"keep time of impact on Auto (or On) in {PIPELINE_PHRASES[p]}")
    margin = [find(runs, s, "speculative_margin", None, "soft") for s in ["bullet_wall", FAST_BULLET]]
    if any(r and r["err"] > 0 for r in margin):
        advice.append("keep a speculative margin in the soft step")
    return line + "; ".join(cells) + (". So " + " and ".join(advice) + "." if advice else
                                      ". No setting measured here let a bullet through.")


def guidance_scene(runs, default, scene, title, unit, threshold, advice):
    """One scene's defaults in both pipelines, and the cheapest setting of each under `threshold`."""
    b = {p: baseline(runs, scene, p) for p in PIPELINES}
    if not any(b.values()):
        return None
    meet = [p for p in PIPELINES if b[p] and finite(b[p]["err"]) and b[p]["err"] <= threshold]
    if len(meet) == 2:
        pick = min(meet, key=lambda p: b[p]["cpu"])
        why = f"both meet {fmt(threshold)}{unit} at the defaults and it is the cheaper"
    else:
        pick = better_pipeline(b["soft"], b["fx2d"])
        why = "the lower error at the defaults"
    line = (f"- **{title}.** Prefer {PIPELINE_PHRASES[pick]} ({why}): at the defaults "
            + both(runs, scene, default, lambda r: f"{fmt(r['err'])}{unit} ({fmt(r['cpu'])} ms)"))
    cells = []
    for p in PIPELINES:
        mine = [r for r in ours(runs, scene, pipeline=p) if finite(r["err"])]
        best = cheapest_at(mine, threshold, "cpu")
        if best:
            cells.append(f"{setting(best)} ({fmt(best['err'])}{unit}, {fmt(best['cpu'])} ms)")
        elif mine:
            low = min(mine, key=lambda r: (r["err"], r["cpu"]))
            cells.append(f"no {PIPELINE_NAMES[p]} setting (its best: {setting(low)}, {fmt(low['err'])}{unit}, "
                         f"{fmt(low['cpu'])} ms)")
    line += f". Cheapest setting under {fmt(threshold)}{unit}: " + "; ".join(cells)
    return line + (". " + advice if advice else "") + "."


def incline_substep_advice(runs):
    """The soft step's substep counts at which the held box slides, if any."""
    slid = sorted((r for r in ours(runs, "incline", pipeline="soft")
                   if r["part"] == "world" and r["knob"] == "substeps" and finite(r["err"])
                   and r["err"] > INCLINE_TARGET), key=lambda r: r["substeps"])
    if not slid:
        return None
    counts = " and ".join(str(r["substeps"]) for r in slid)
    return (f"On a slope that friction must hold, give the soft step more than {slid[-1]['substeps']} substeps: "
            f"at {counts} the box slid ({fmt(slid[0]['err'])} m/s^2), because its first frame rocks it on its "
            f"corners, its friction reaches the static bound and the kinetic coefficient then applies")


def guidance_mass_ratio(runs, default):
    scenes = [s for s in scene_names(runs) if s.startswith("heavy_on_light_")]
    if not scenes:
        return None
    cells = []
    failed = []
    for scene in scenes:
        ratio_text = scene.replace("heavy_on_light_", "")
        drifts = []
        for p in PIPELINES:
            b = baseline(runs, scene, p)
            if b:
                drifts.append(f"{PIPELINE_NAMES[p]} {mm(b['err'])}")
                if p == default and not b["err"] < DRIFT_TARGET_M:
                    failed.append(ratio_text)
        exact = [r for r in ours(runs, scene) if r["solver_mode"] == "exact" and finite(r["err"])]
        if exact:
            e = min(exact, key=lambda r: (r["err"], r["cpu"]))
            drifts.append(f"best exact {mm(e['err'])} ({setting(e)}, {fmt(e['cpu'])} ms)")
        cells.append(f"{ratio_text}: " + ", ".join(drifts))
    line = ("- **Heavy on light (mass ratios), exact mode.** Drift of the heavy box on a 1 kg box at the "
            "defaults and in the exact solver mode: " + "; ".join(cells))
    if failed:
        line += (f". At the ratios {', '.join(failed)} the default pipeline's iterative solve let the heavy box "
                 f"drift 1 mm or more; for large mass ratios use `solver_mode: exact` (it works in both pipelines; "
                 f"in Fx2D add `compliance: 0` to keep the heavy box from sinking by load x compliance)")
    else:
        line += ". The default pipeline held every ratio measured within 1 mm"
    return line + "."


def guidance_realtime(runs, default):
    cells = []
    for scene in ["pyramid", "elastic_gas"]:
        cell = both(runs, scene, default, lambda r: f"{fmt(r['cpu'])} ms")
        if cell:
            cells.append(f"{scene}: {cell}")
    if not cells:
        return None
    return ("- **Real-time budget.** A frame at the defaults costs (CPU, median) " + "; ".join(cells) +
            ", well inside 16.7 ms at 60 Hz. Keep warm starting on (Auto): it is nearly free and holds stacks up.")


def guidance_section(runs, stacks, default):
    lines = [guidance_pipeline(runs, stacks, default), guidance_stacks(runs, stacks, default),
             guidance_fast(runs, default),
             guidance_scene(runs, default, "bouncing_disks", "Bouncing (restitution)", "", BOUNCE_TARGET,
                            "Both pipelines apply Newton restitution per contact; the soft step after the "
                            "substeps, iterated to the fixed point"),
             guidance_scene(runs, default, "elastic_gas", f"Elastic gas (e = 1, mu = 0, "
                            f"{fmt(number((baseline(runs, 'elastic_gas', default) or {}).get('seconds')))} s)",
                            "", GAS_TARGET, None),
             guidance_scene(runs, default, "newtons_cradle", "Newton's cradle", "", GAS_TARGET, None),
             guidance_scene(runs, default, "incline", "Resting on an incline (friction holds)", " m/s^2",
                            INCLINE_TARGET, incline_substep_advice(runs)),
             guidance_scene(runs, default, "incline_slide", "Sliding down an incline", " m/s^2", INCLINE_TARGET,
                            None),
             guidance_mass_ratio(runs, default), guidance_realtime(runs, default)]
    return "\n".join(line for line in lines if line) + "\n"


# -- Targets ------------------------------------------------------------------

def stack_target_rows(stacks, default):
    if not stacks:
        return [["stacks (base-20/60/100 pyramids, 20-box column)", "not measured in this run", "-"]]
    rows = []
    longest = max(r["seconds"] for r in stacks)
    short = "" if longest >= STACK_TARGET_SECONDS else f" (this run: {fmt(longest)} s)"
    other_p = other(default)
    for scene in [s for s in STACK_SCENES if stack_rows(stacks, s, default, seconds=longest)]:
        r = stack_rows(stacks, scene, default, seconds=longest)
        o = stack_rows(stacks, scene, other_p, seconds=longest)
        target = STACK_DRIFT_TARGET_M.get(scene, DRIFT_TARGET_M)
        rows.append([f"{scene} stands: drift 1 s -> {fmt(STACK_TARGET_SECONDS)} s < {mm(target)}{short}",
                     f"{mm(r['drift_m'])}" + (f" ({PIPELINE_NAMES[other_p]}: {mm(o['drift_m'])})" if o else ""),
                     verdict(r["drift_m"], target)])
    pens = [(s, stack_rows(stacks, s, default, seconds=longest)) for s in STACK_SCENES]
    pens = [(s, r) for s, r in pens if r]
    if pens:
        worst = max(pens, key=lambda sr: sr[1]["max_penetration_m"])
        others = [stack_rows(stacks, s, other_p, seconds=longest) for s, _ in pens]
        cell = ", ".join(f"{s.replace('stack_', '')} {mm(r['max_penetration_m'])}" for s, r in pens)
        if all(others):
            cell += (f" ({PIPELINE_NAMES[other_p]}: " +
                     ", ".join(f"{mm(o['max_penetration_m'])}" for o in others) + ")")
        missed = [s for s, r in pens if not r["max_penetration_m"] <= STACK_PENETRATION_TARGET_M]
        rows.append([f"largest penetration <= {mm(STACK_PENETRATION_TARGET_M)} on the four stacks", cell,
                     "met" if not missed else
                     f"missed on {len(missed)} of {len(pens)} (worst {worst[0]} by "
                     f"{fmt(worst[1]['max_penetration_m'] / STACK_PENETRATION_TARGET_M)}x)"])
    for scene in [s for s in STACK_SCENES if stack_rows(stacks, s, default, seconds=longest)]:
        r = stack_rows(stacks, scene, default, seconds=longest)
        o = stack_rows(stacks, scene, other_p, seconds=longest)
        if not finite(r["cpu_ms_over_box2d_v3"]):
            rows.append([f"{scene}: ms/frame <= {fmt(STACK_TIME_TARGET)}x Box2D v3's", "Box2D v3 not in this run",
                         "not measured"])
            continue
        rows.append([f"{scene}: ms/frame <= {fmt(STACK_TIME_TARGET)}x Box2D v3's",
                     f"CPU {fmt(r['cpu_ms_over_box2d_v3'])}x, wall {fmt(r['ms_over_box2d_v3'])}x "
                     f"({fmt(r['cpu_ms_per_frame'])} ms)" +
                     (f" ({PIPELINE_NAMES[other_p]}: CPU {fmt(o['cpu_ms_over_box2d_v3'])}x)" if o else ""),
                     verdict(r["cpu_ms_over_box2d_v3"], STACK_TIME_TARGET, strict=False)])
    return rows


def time_target_row(runs, scene):
    trs = time_target_rows(runs, scene)
    unreached = [t for t in trs if t["ours"] == "not reached"]
    reached = [t for t in trs if t["ours"] != "not reached"]
    parts = []
    if reached:
        worst = max(reached, key=lambda t: t["ratio"])
        worst_cpu = max(t["ratio_cpu"] for t in reached)
        parts.append(f"worst {fmt(worst['ratio'])}x (CPU {fmt(worst_cpu)}x): ours {worst['ours']} against "
                     f"{worst['peer']}")
    if unreached:
        parts.append("no setting of ours reaches " +
                     ", ".join(f"{t['peer']} ({fmt(t['peer_err'])})" for t in unreached))
    worst_ratio = max(t["ratio"] for t in reached) if reached else float("inf")
    met = not unreached and worst_ratio <= TIME_TARGET
    missed = [t for t in reached if t["ratio"] > TIME_TARGET]
    text = "met" if met else (f"missed: accuracy not reached ({len(unreached)} of {len(trs)} peer runs)"
                              if unreached else
                              f"missed by {over(worst_ratio / TIME_TARGET)}x ({len(missed)} of {len(trs)} peer runs)")
    return [f"{scene}: time <= {TIME_TARGET}x each peer run at equal or better error", "; ".join(parts), text]


def defaults_target_rows(runs, default):
    other_p = other(default)
    rows = []

    def measured(scene, fn):
        b, o = baseline(runs, scene, default), baseline(runs, scene, other_p)
        if not b:
            return None, "not measured"
        return b, fn(b) + (f" ({PIPELINE_NAMES[other_p]}: {fn(o)})" if o else "")

    b, text = measured("bouncing_disks", lambda r: fmt(r["err"]))
    rows.append([f"bounce at the defaults: \\|e measured - e\\| < {fmt(BOUNCE_TARGET)}", text,
                 verdict(b["err"], BOUNCE_TARGET) if b else "not measured"])
    incl = [(s, baseline(runs, s, default), baseline(runs, s, other_p)) for s in ["incline", "incline_slide"]]
    incl = [x for x in incl if x[1]]
    if incl:
        worst = max(r["err"] for _, r, _ in incl)
        cell = ", ".join(f"{s} {fmt(r['err'])}" for s, r, _ in incl) + " m/s^2"
        if all(o for _, _, o in incl):
            cell += f" ({PIPELINE_NAMES[other_p]}: " + ", ".join(fmt(o["err"]) for _, _, o in incl) + ")"
        rows.append([f"incline acceleration error at the defaults < {fmt(INCLINE_TARGET)} m/s^2", cell,
                     verdict(worst, INCLINE_TARGET)])
    b, text = measured("elastic_gas", lambda r: f"{fmt(r['err'])} over {fmt(number(r['seconds']))} s")
    rows.append([f"elastic gas (e = 1, mu = 0) at the defaults: kinetic energy drift < {fmt(GAS_TARGET)} over "
                 f"{fmt(GAS_TARGET_SECONDS)} s", text, verdict(b["err"], GAS_TARGET) if b else "not measured"])
    b, text = measured(FAST_BULLET, lambda r: "tunnelled" if r["err"] > 0 else "stopped at the wall")
    rows.append(["no tunnelling at 1e4 m/s at the defaults", text,
                 ("met" if b["err"] == 0 else "missed") if b else "not measured"])
    return rows


def targets_section(runs, stacks, default):
    rows = stack_target_rows(stacks, default)
    rows += [time_target_row(runs, scene) for scene in time_target_scenes(runs)]
    rows += defaults_target_rows(runs, default)
    return table(["target", "measured", "verdict"], rows)


def earlier_targets_section(runs, solver, scaling, world_has_exact):
    rows = []
    for scene in ["column", "pyramid"]:
        stand = [r for r in ours(runs, scene, True) if r["part"] == "stand" and finite(r["err"])]
        if not stand:
            continue
        seconds = fmt(max(number(r["seconds"]) for r in stand))
        cells = []
        met = False
        for p in PIPELINES:
            mine = [r for r in stand if r["pipeline"] == p]
            if not mine:
                continue
            best = cheapest_at(mine, DRIFT_TARGET_M)
            if best:
                met = True
                cells.append(f"{PIPELINE_NAMES[p]}: cheapest {setting(best)}, drift {mm(best['err'])} at "
                             f"{fmt(best['ms'])} ms/frame")
            else:
                low = min(mine, key=lambda r: r["err"])
                cells.append(f"{PIPELINE_NAMES[p]}: best {setting(low)}, drift {mm(low['err'])}")
        best_all = min(stand, key=lambda r: r["err"])
        rows.append([f"base-20 {scene} (sweep) stands {seconds} s at some setting, drift < 1 mm", "; ".join(cells),
                     "met" if met else f"missed by {over(best_all['err'] / DRIFT_TARGET_M)}x"])
    rows.append(exact_target_row(runs, solver, world_has_exact))
    slope = scaling_slope(scaling, "collision2d")
    rows.append([f"scaling slope <= {SLOPE_TARGET}", f"{fmt(slope)} (1e2..1e5 bodies, ours at its defaults)",
                 "met" if finite(slope) and slope <= SLOPE_TARGET else f"missed by {fmt(slope - SLOPE_TARGET)}"])
    return table(["target", "measured", "verdict"], rows)


def exact_target_row(runs, solver, world_has_exact):
    if world_has_exact:
        exact = [r for r in ours(runs, "heavy_on_light_1e6") if r["solver_mode"] == "exact" and finite(r["err"])]
        if exact:
            r = min(exact, key=lambda run: run["err"])
            held = finite(r["err"]) and r["err"] < DRIFT_TARGET_M
            return ["exact mode holds a 1e6 mass-ratio stack",
                    f"World {setting(r)}: drift {mm(r['err'])}, penetration {mm(r['pen'])}",
                    "met" if held else "missed"]
    rows = [s for s in solver if s["mode"] == "exact" and number(s["max_mass_ratio"]) >= 1e6]
    if not rows:
        return ["exact mode holds a 1e6 mass-ratio stack", "not measured", "-"]
    worst = max(number(s["max_complementarity"]) for s in rows)
    fallbacks = max(int(s["exact_fallbacks"]) for s in rows)
    return ["exact mode holds a 1e6 mass-ratio stack",
            f"WorldSettings has no solver mode in this build, so the World stack cannot run exact; "
            f"ContactSolver exact on random clusters with masses up to 1e6: complementarity {fmt(worst)} m/s, "
            f"{fallbacks} fallbacks", "not measurable in the World"]


def scaling_slope(scaling, engine, scenes=("gas",), workers="1"):
    pts = [(number(r["bodies"]), number(r["ms_per_step"])) for r in scaling if r["engine"] == engine
           and r.get("scene", "gas") in scenes and r.get("workers", "1") == workers]
    pts = [p for p in pts if finite(p[1]) and p[1] > 0]
    return least_squares_slope(pts) if len(pts) >= 2 else float("nan")


# -- Detail sections ----------------------------------------------------------

def peers_section(runs, default):
    out = ""
    for scene in scene_names(runs):
        bases = [b for b in [baseline(runs, scene, default), baseline(runs, scene, other(default))] if b]
        others = [r for r in runs if r["scene"] == scene and r["part"] == "peers"]
        if not bases or not others:
            continue
        b = bases[0]
        rows = [[label(r), r["ms"], r["cpu"], r["ms"] / b["ms"], r["err"], ratio(r["err"], b["err"]),
                 r["pen"] * 1e3] for r in bases + others]
        out += f"\n**{scene}** (main error: {ERROR_UNITS[b['error_name']]})\n\n"
        out += table(["engine, setting", "ms/frame", "CPU ms/frame", "time / ours at defaults", "error",
                      "error / ours at defaults", "max penetration (mm)"], rows)
    return out


def time_target_section(runs):
    out = ""
    for scene in time_target_scenes(runs):
        trs = time_target_rows(runs, scene)
        if not trs:
            continue
        out += f"\n**{scene}**\n\n"
        out += table(["peer run", "peer ms", "peer error", "our cheapest run at <= that error", "our ms",
                      "our error", "ours / peer (wall)", "ours / peer (CPU)"],
                     [[t["peer"], t["peer_ms"], t["peer_err"], t["ours"], t["ours_ms"], t["ours_err"], t["ratio"],
                       t["ratio_cpu"]] for t in trs])
    return out


def knob_section(runs):
    out = ""
    for scene in scene_names(runs):
        mine = [r for r in ours(runs, scene) if r["part"] == "world"]
        if not mine:
            continue
        out += f"\n**{scene}** ({ERROR_UNITS[mine[0]['error_name']]})\n\n"
        out += table(["pipeline", "knob", "value", "substeps x iterations", "ms/frame", "CPU ms/frame", "error",
                      "max penetration (mm)"],
                     [[PIPELINE_NAMES[r["pipeline"]], r["knob"], r["value"], f"{r['substeps']}x{r['iterations']}",
                       r["ms"], r["cpu"], r["err"], r["pen"] * 1e3] for r in mine])
    return out


def stand_section(runs):
    rows = [[r["scene"], setting(r), number(r["seconds"]), r["ms"], r["cpu"], r["err"] * 1e3,
             number(r["sink_m"]) * 1e3, r["pen"] * 1e3] for r in runs if r["part"] == "stand"]
    return table(["scene", "setting", "simulated s", "ms/frame", "CPU ms/frame", "drift after 1 s (mm)",
                  "sink in first 1 s (mm)", "max penetration (mm)"], rows) if rows else "No stand runs.\n"


def mass_ratio_section(runs):
    rows = []
    for r in runs:
        if r["scene"].startswith("heavy_on_light_") and r["part"] == "world":
            rows.append([r["scene"].replace("heavy_on_light_", ""), setting(r), r["ms"], r["err"] * 1e3,
                         number(r["sink_m"]) * 1e3, r["pen"] * 1e3])
    for r in runs:
        if r["scene"].startswith("heavy_on_light_") and r["part"] == "peers" and not is_ours(r):
            rows.append([r["scene"].replace("heavy_on_light_", ""), label(r), r["ms"], r["err"] * 1e3,
                         number(r["sink_m"]) * 1e3, r["pen"] * 1e3])
    return table(["mass ratio", "setting", "ms/frame", "drift after 1 s (mm)", "sink (mm)", "max penetration (mm)"],
                 rows)


def solver_section(solver):
    rows = [[s["mode"], s["iterations"] if s["mode"] == "iterative" else "-", s["tolerance"], s["max_mass_ratio"],
             number(s["us_per_solve"]), number(s["max_target_residual"]), number(s["max_complementarity"]),
             number(s["mean_complementarity"]), number(s["max_coulomb_excess"]), number(s["converged_fraction"]),
             s["exact_fallbacks"]] for s in solver]
    return table(["mode", "iteration cap", "tol", "mass ratio up to", "us/solve (median)", "max target shortfall (m/s)",
                  "max complementarity (m/s)", "mean complementarity (m/s)", "max Coulomb excess (m/s)",
                  "converged", "fallbacks"], rows)


def scaling_section(scaling):
    scaling = gas_rows(scaling)
    rows = [[r["engine"], r["bodies"], r["frames"], number(r["ms_per_step"]), number(r["cpu_ms_per_step"]),
             number(r["vmhwm_kib"]) / 1024.0] for r in scaling]
    slopes = [[e, scaling_slope(scaling, e)] for e in ["collision2d"] + PEERS + OPTIONAL_PEERS
              if any(r["engine"] == e for r in scaling)]
    return (table(["engine", "bodies", "timed frames", "ms/frame", "CPU ms/frame", "peak RSS (MiB)"], rows) + "\n" +
            table(["engine", "least-squares slope of log time vs log n"], slopes))


def stack_engine_label(r):
    if is_ours(r):
        return f"ours {PIPELINE_NAMES[r['pipeline']]}"
    return PEER_NAMES.get(r["engine"], r["engine"])


def stacks_section(stacks, default):
    """The stack scenes: every engine of collision2d_stack_bench's one run, one row per engine."""
    if not stacks:
        return "Not measured in this run (`collision2d_stack_bench` wrote no stacks.csv).\n"
    v3 = any(r["engine"] == "box2d_v3" for r in stacks)
    checkpoints = sorted({r["seconds"] for r in stacks})
    longest = checkpoints[-1]
    out = ("Box2D v3 is in this run, built from a checkout given through `COLLISION2D_BOX2D_V3_DIR`; its code is "
           "not part of this repository. Ratios are to its time in the same run.\n\n" if v3 else
           "Box2D v3 is not in this run (the script was not given `COLLISION2D_BOX2D_V3_DIR`), so there is no "
           "ratio to it.\n\n")
    rows = []
    order = {"collision2d": 0, "box2d": 1, "chipmunk": 2, "box2d_v3": 3}
    for scene in [s for s in STACK_SCENES if any(r["scene"] == s for r in stacks)]:
        engines = sorted({(r["engine"], r["pipeline"]) for r in stacks if r["scene"] == scene},
                         key=lambda ep: (order.get(ep[0], 9), ep[1] != default))
        for engine, pipeline in engines:
            at = {r["seconds"]: r for r in stacks if r["scene"] == scene and r["engine"] == engine
                  and r["pipeline"] == pipeline}
            last = at[max(at)]
            name = stack_engine_label(last) + (" (default)" if is_ours(last) and pipeline == default else "")
            rows.append([scene.replace("stack_", ""), last["boxes"], name, last["ms_per_frame"],
                         last["cpu_ms_per_frame"], last["ms_over_box2d_v3"], last["cpu_ms_over_box2d_v3"]] +
                        [at[c]["drift_m"] * 1e3 if c in at else float("nan") for c in checkpoints] +
                        [last["max_penetration_m"] * 1e3])
    out += table(["scene", "boxes", "engine", "ms/frame", "CPU ms/frame", "time / Box2D v3", "CPU time / Box2D v3"] +
                 [f"drift 1 s -> {fmt(c)} s (mm)" for c in checkpoints] +
                 [f"largest penetration to {fmt(longest)} s (mm)"], rows)
    return out


# ---------------------------------------------------------------------------

def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--perf-dir", required=True)
    parser.add_argument("--doc", required=True)
    parser.add_argument("--elapsed", default="?")
    parser.add_argument("--quick", action="store_true")
    # Re-rendering saved CSVs: the commit and load average of the run that measured them.
    parser.add_argument("--commit", default="")
    parser.add_argument("--load", default="")
    args = parser.parse_args()

    runs = prepare(read_csv(os.path.join(args.perf_dir, "runs.csv")))
    solver = read_csv(os.path.join(args.perf_dir, "solver.csv"))
    scaling = median_runs(read_csv(os.path.join(args.perf_dir, "scaling.csv")))
    stacks = prepare_stacks(read_csv(os.path.join(args.perf_dir, "stacks.csv")))
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

    doc = render(args, runs, solver, scaling, stacks, world_has_exact, plots, scaling_png, default, plots_extra)
    with open(args.doc, "w") as f:
        f.write(doc)


def render(args, runs, solver, scaling, stacks, world_has_exact, plots, scaling_png, default, plots_extra=()):
    mode_note = ("The World's exact solver mode is swept in both pipelines on every scene but the "
                 "pyramid: its one cluster of 210 boxes (about 2400 complementarity rows) did not finish 30 frames "
                 "in exact mode within several minutes, so it is not measured there." if world_has_exact else
                 "`WorldSettings` has no solver mode in the build measured here, so the World is swept in its "
                 "iterative mode only; the exact mode is measured on the instantaneous `ContactSolver` (solver "
                 "table).")
    gas = baseline(runs, "elastic_gas", default)
    gas_seconds = fmt(number(gas["seconds"])) if gas else "10"
    return f"""# Performance: which pipeline and settings to use, and what each costs

Generated by `scripts/performance_report.sh` from the CSVs in `docs/perf/`;
do not edit by hand. Every number below was measured in the one run described
here; the guidance is written by the script from those numbers.

{machine_section(args, runs, stacks, scaling, default)}
## Guidance

Which pipeline and which settings to use, from this run's measurements
(ms are CPU time per frame unless marked wall; details in the sections below).

{guidance_section(runs, stacks, default)}
## Targets

Reported, not asserted; a target that is missed says by how much. "At the
defaults" means ours with a default `WorldSettings` (the scene's own gravity;
the stacks also run with sleeping off), in the default pipeline
({PIPELINE_NAMES[default]}); the other pipeline's value is in parentheses.
The time target compares, for every peer run (Box2D 2.4.1 and Chipmunk 7,
their defaults and matched to our steps), our cheapest run in either
pipeline whose main error is equal or better (details in *The time target
in detail*). The stack targets come from the stack bench (*Stacks against
Box2D v3*; the time ratio is CPU time per frame, wall in the table).

{targets_section(runs, stacks, default)}
### Earlier targets

{earlier_targets_section(runs, solver, scaling, world_has_exact)}
## What was measured and how

- **Scenes** (the shipped builders, `collision2d::scenes`): pyramid of base 20
  (210 boxes), 20-box column, heavy box on a 1 kg box at mass ratios 1e1 to 1e6,
  five disks bouncing with e = 0.8, a box resting on a 0.4 rad incline
  (mu_s 0.5 holds it) and one sliding on a 0.6 rad incline (mu 0.3), elastic gas
  of 1000 disks ({gas_seconds} s), Newton's cradle of 5 disks, and a 5 cm bullet at
  500 m/s (`bullet_wall`) and at 1e4 m/s (`bullet_wall_1e4`) toward a 5 cm
  wall. dt = 1/60 s everywhere.
- **Main error per scene** (the y axis of the Pareto plots): stacks: largest
  displacement of any box between t = 1 s (settled) and the end of the run
  (the sink while settling is reported separately); gas and cradle: largest
  |KE - KE0| / KE0 at any frame end; bouncing disks: the restitution measured
  from the rebound apex, sqrt(h1 / h0), worst |e_meas - e| over the disks;
  inclines: |measured - analytic| acceleration along the slope between 0.5 s
  and 2 s (analytic: 0 when tan(angle) <= mu_s, else g (sin - mu_k cos));
  bullet: 1 if it ends beyond the wall. Largest penetration: the deepest
  overlap at any frame end.
- **Same code for every engine.** Each engine reports body states at frame
  ends; every metric, including penetration (our detection run on those
  states), is computed by the same benchmark code.
- **Timing.** Median over 5 (3 with --quick) fresh runs of 0.5 s simulated,
  wall time by `steady_clock`; the thread's CPU time is recorded too. Ours and
  the peers were timed in the same process, scene by scene. The two cores
  were shared with other processes during the run, so wall times carry noise
  (compare the wall and CPU columns; CPU time excludes time spent preempted).
- **Both pipelines.** Every run of ours sets `soft_step` explicitly: the
  soft step (contacts found once a frame within a speculative margin, solved
  as damped springs, relaxed every substep, restitution at the end of each substep)
  and the Fx2D order (detect, correct positions, solve velocities every
  substep). Shared knobs, one at a time around the scene's settings (4
  substeps x 2 velocity iterations, every effect Auto), in both: velocity
  iterations, substeps 1 to 16, warm starting On/Off, the exact solver mode,
  time of impact On/Off on the headline scenes, and on the pyramid, column and gas a substeps
  {{1, 2, 8}} x iterations {{1, 8}} grid. Fx2D only: iterations up to 256 (the
  pyramid to 64; 32 with --quick), slop 0.1 mm and 1 cm, and on the stacks
  `warm_start_before_integration`, 1 and 16 position passes, `position_block`,
  `warm_start_every_substep` off and `warm_start_factor` 0.5; on the mass
  ratios `exact_position_correction`. Soft step only: `contact_hertz` 10 and
  60 Hz (and 120 Hz at 8 substeps, 240 Hz at 16 on the headline scenes),
  `contact_damping_ratio` 1 and 100, `contact_push_speed` 1 and 10 m/s,
  `speculative_margin` 5 mm and 10 cm (0 on the bullets). --quick thins
  these lists. {mode_note}
- **Peers.** Box2D 2.4.1 and Chipmunk 7.0.3 as packaged by Debian (the Chipmunk
  package is built with its debug checks on), and Box2D v3 when the script is
  given a build of it. *Defaults*: one step per frame with the engine's own
  settings (Box2D 8 velocity / 3 position iterations, sleeping on,
  restitution threshold 1 m/s; Chipmunk 10 iterations, collision slop 0.1 m;
  Box2D v3 its 4 substeps). *Matched*: our substeps (as that many steps of
  dt/substeps, Box2D v3 as its substep count) and our velocity iterations;
  Chipmunk also gets our slop; Box2D gets our restitution threshold and keeps
  3 position iterations (its linear slop, 5 mm, is compile-time). Sleeping is
  off in matched peer runs.
- **Same effective coefficients.** Ours mixes a pair by min; Box2D uses
  sqrt(f1 f2) for friction and max(e1, e2) for restitution; Chipmunk multiplies
  both. Each body gets the value whose self-mix is its own coefficient: Box2D
  (mu, e), Chipmunk (sqrt(mu), sqrt(e)). In every scene here all bodies that
  touch share one material, so every touching pair sees exactly our
  coefficient. The peers have one friction coefficient: they get mu_s (which
  decides whether a resting body holds); the sliding incline has mu_s = mu_k.
  Box2D rounds polygons by a 1 cm skin: its boxes are inset by the skin so the
  rounded outline matches ours; masses and inertias are set to ours exactly.
- **Scaling.** `collision2d_scaling_bench`: elastic gas of n disks (the gas
  builder), ours at its defaults (the default pipeline), one process per
  engine and size so that VmHWM from /proc/self/status is that size's peak;
  time per frame is the median of 5 timed batches after 3 warm-up frames.

## Time against accuracy (Pareto fronts, peers as points)

Ours as two series, the soft step and Fx2D: every setting measured (light),
its Pareto front (line) and its defaults (ring); the peers as points.

{chr(10).join(plots)}

## Stacks against Box2D v3

The same scenes in every engine (`bench/stack_scenes.h`): unit boxes of 1 kg,
friction 0.6, restitution 0, a static ground 200 m x 1 m with its top at
y = 0, exactly touching boxes, gravity -10 m/s^2, dt 1/60 s, 4 substeps, one
thread, sleeping off, every other setting the engine's default (ours: the
World's defaults, once per pipeline). Time: median of fresh runs of the first
second, the engines taking turns (one run each per round); a ratio to
Box2D v3 is the median over the rounds of that round's ratio, so the
machine's drift between rounds does not skew it; drift: largest
displacement of any dynamic body between 1 s and the checkpoint; penetration: our detection on each engine's poses at every frame
end. All rows come from one run of `collision2d_stack_bench`.

The drift targets count from 1 s, and in both engines the tall pyramids are
still settling then. `collision2d_stack_trace --scene NAME --engine NAME`
prints the top box's pose and the drift since 1 s every few frames. Until
commit b7dfb95 the soft step coloured its rows in body index order, which
made the colours lopsided across a pyramid built row by row, and the stack
leaned as it settled: on base-60 the top box swung between -31.9 and
+58.2 mm sideways in the first second, on base-100 between -73.5 and
+64.8 mm. Since b7dfb95 the rows are coloured from the top of the scene
down; at that commit (not this run) the top box stayed within 0 .. +1.4 mm
(base-60) and -0.2 .. +2.6 mm (base-100) sideways, and the drift 1 s -> 10 s
fell from 8.58 to 7.10 mm and from 61.5 to 17.8 mm. What is left is the
stack's vertical settling, which Box2D v3 shares: the contacts carry the
weight by compressing, the whole pyramid sinks into them and rebounds. At
b7dfb95 the base-100 top box was 289 mm below its final height at 0.65 s
and 107 mm above it at 1.25 s (Box2D v3: 204 mm below at 0.65 s, 53 mm
above at 1.45 s), and the flank boxes slide a few millimetres while the
load shifts.

Why the contact defaults stay at 40 Hz and damping ratio 10: the largest
penetration is a loaded contact's steady compression, its load over
m_eff (2 pi f)^2, so only a stiffer contact makes it smaller, and every
stiffer contact we measured made the tall pyramids drift more. Measured at
commit 6a4da26 (not this run) with a scratch driver stepping
`make_stack_scene` for 10 s; drift 1 s -> 10 s / largest penetration, mm:

| contact model | column | base-20 | base-60 | base-100 |
|---|---|---|---|---|
| defaults (40 Hz, damping ratio 10) | 0.047 / 6.02 | 0.425 / 2.87 | 7.10 / 10.8 | 17.8 / 20.0 |
| contact_hertz 45 | 0.008 / 5.02 | 0.348 / 2.80 | 7.21 / 9.26 | 91.9 / 16.7 |
| contact_hertz 50 | 0.038 / 4.58 | 0.292 / 2.66 | 8.02 / 8.13 | 165 / 14.3 |
| contact_damping_ratio 20 | 2.00 / 6.02 | 0.728 / 2.86 | 12.2 / 9.54 | 39.1 / 18.1 |
| contact_damping_ratio 40 | 9.49 / 6.02 | 3.59 / 3.05 | 49.8 / 9.45 | 123 / 15.7 |
| stiffness by load: f times sqrt(supported mass / m_eff), at most a quarter of the substep rate | 0.541 / 4.24 | 0.363 / 2.53 | 138 / 7.19 | 196 / 11.6 |
| rigid normal update, same push-out rate (no soft leak) | 18.2 / 4.82 | 16.1 / 2.68 | | |

A stiffer or more damped contact slows the tall pyramids' breathing mode
rather than ending it, and a stiffness that follows the load changes every
frame and pumps energy into the flank boxes. Letting that stiffness reach
half the substep rate, or the full rate, rings: the base-20 pyramid then
drifts 34 and 88 mm.

{stacks_section(stacks, default)}
## Stacks standing for a minute (base-20 pyramid and 20-box column of the sweep)

{stand_section(runs)}
## Peers side by side (ratios to ours at the defaults, same run)

Ratios above 1 mean the peer took longer or erred more than ours at the
defaults in the default pipeline ({PIPELINE_NAMES[default]}, 4 x 2).
{peers_section(runs, default)}
## The time target in detail

For every peer run, our cheapest run (either pipeline, any setting) whose main
error is equal or better, and the time ratio. The target is a ratio of at most
{TIME_TARGET} against every peer point.
{time_target_section(runs)}
### Fx2D: where the column's drift comes from

Measured by hand in the Fx2D pipeline before the soft step existed; not
regenerated by the script (the column's knob table below has this run's
numbers). The soft step avoids this sag: it solves the contacts before it
moves the bodies.

Measured on the 20-box column at 4x2 (10 s, default settings). The drift is
pure vertical settling: sideways offsets and rotations stay at round-off
(1e-15). At 1 s the column has sunk 4.4 cm and is still bouncing by about
3 mm; it comes to rest about 8 mm lower at t = 6 s, with each contact resting
deeper the more load it carries (1.1 mm under the top box, 4.2 mm at the
base).

The cause is the order of an Fx2D substep (integrate, detect,
correct positions, derive velocities, solve velocities). Integration moves
every resting body by its gravity kick, g h^2 (0.17 mm at 4 substeps), before
the velocity solve cancels that kick, so the position passes must lift the
whole column back every substep, and a Gauss-Seidel pass carries that lift
up a 20-box chain only in part. Box2D solves velocities before it moves
positions, so its resting bodies do not move at all. More velocity iterations
therefore do not help (4x8 drifts 7.9 mm, the same as 4x2); what does:

| column, 4x2 plus | drift (m) |
|---|---|
| nothing (4 position passes) | 8.2e-3 |
| 1 / 2 / 8 / 16 position passes | 9.0e-2 / 3.2e-2 / 1.9e-3 / 7.8e-4 |
| slop 1e-4 / 5e-3 | 4.5e-3 / 7.0e-2 |
| 8 substeps x 2 / x 4 iterations (g h^2 four times smaller) | 2.1e-3 / 2.8e-3 |
| compliance 0 or 1e-5, friction or restitution off | unchanged (8.1e-3 to 1.1e-2) |
| warm starting off | the column falls (18 m) |

Two changes to the position stage were prototyped and not shipped:
warm-starting the position correction, and taking back only the gravity drop
the contacts carry. Both fix the column but make the base-20 pyramid spread
sideways at 4 substeps (0.1 to 0.57 m).

What ships instead, opt-in, is `warm_start_before_integration`: before the
poses move, the previous substep's contacts are warm-started and given one
velocity pass with rest targets, the poses advance with those predicted
velocities, and the velocities are then put back exactly, so Newton targets
and the velocity solve are as before and only the poses differ. It brings the
column level with Box2D (the tables above and below) for about 1.2x to 1.5x
the time. It stays off by default because at 4x2 the base-20 pyramid rattles
and collapses with it (0.78 m over 60 s): resting contacts now come and go,
each returning one starts without a cached impulse, and two passes cannot
carry the pyramid from there. With 8 substeps or 8 velocity passes it holds
the pyramid better than anything else measured. Keeping touching contacts
alive with a detection margin, as Box2D's skin does, is the likely fix for
4x2 and is not done.

## Mass ratios (heavy box on a light one)

{mass_ratio_section(runs)}
## ContactSolver on random clusters: residuals per mode

Random multi-contact clusters from `RandomSceneGenerator` (chains, stars,
piles of disks and polygons, e and mu random per scene), the same draws for
every row. Residuals are recomputed from the returned velocities and
impulses: the shortfall below each contact's fixed Newton target; the normal
complementarity min(|v_n - target|, j_n w_n) (w_n: effective inverse mass, so
both are speeds); the Coulomb bound excess.

{solver_section(solver)}
## Scaling

{"![scaling](perf/scaling.png)" if scaling_png else ""}

{scaling_section(scaling)}
## Throughput

`collision2d_scaling_bench --scene pyramid|rain` under the stack scenes'
rules (unit boxes, mu 0.6, g -10, 4 substeps, sleeping off): the largest
pyramid of at most n boxes, and a rain of n disks and boxes falling onto the
ground (timed after its first second, when the lowest rows have landed).
Ours with 1 and 2 workers (`WorldSettings::workers`), Box2D v3 on one
thread when it is in the run; one process per size, so the peak memory is
that size's alone. Ours runs {throughput_rounds(scaling)} rounds alternating 1 and 2
workers, and each row is the round of median time: a second core busy for
a moment slows only the runs that need it. A speed-up of 2 workers over 1
is the median over the rounds of each round's own ratio (its 1-worker run
and the 2-worker run right after it): this machine's speed drifts within
minutes, and a ratio of two medians taken at different times can carry it. Two more scenes, with each
engine's own sleeping on and timed after 10 s: `resting`, the pyramid
fallen asleep, and `stirred`, the same with one kinematic disk sliding
along the ground far from it, so some body moves every frame and the rest
of the world sleeps.

{chr(10).join(plots_extra)}

{throughput_section(scaling, stacks, default)}
## Knob sweeps, scene by scene
{knob_section(runs)}
## Where the World's time goes (profile notes)

Profiled by hand with `perf record` on `collision2d_scaling_bench` (gas of
1e5 disks); not regenerated by the script. Two findings at commit c43aeb6,
both since fixed:

- `World::add_body` recomputed the inner radius of every body, so building
  an n-body world was O(n^2) (89% of the 1e5-body process's CPU). It now
  updates only the new body's radius and the running minimum (commit
  efde78e): building the 1e5-body test world went from about 35 s to 0.5 s.
- About 85% of the stepping time at 1e5 bodies was `BroadPhase::find_pairs`,
  a sort and sweep along one axis, which is O(n^1.5) for bodies scattered
  over a square. It is now a uniform grid laid out by counting sort, with
  boxes wider than four cells (ground slabs, walls) kept out of the grid
  (commits a086ca9, fe5777c). Measured in one session, one process per size,
  CPU ms per frame before/after: 1e3 bodies 0.59/0.47, 1e4 12.4/5.38,
  1e5 433/80.6; the least-squares CPU slope from 1e2 to 1e5 fell from 1.40
  to 1.09. At 1e5 the broad phase is still about 60% of the step (two
  passes that read memory in random order), and small scenes (1e2 bodies)
  pay about 0.014 ms of fixed grid overhead per frame.

A third finding, on the base-60 pyramid of the stack bench at commit
798fa2e (`perf record`, soft step, one thread): 61% of the samples in
`WorldImpl::add_manifold` fell on one `rep stos`, GCC's clear of the whole
320-byte contact point before the defaults were set (`row = ContactPoint{{}}`).
On this machine's AMD cores that instruction's start-up costs more than the
plain stores. The point is now default-initialised in place (commit 49f5a9f,
same bits): whole-process CPU time A/B 0.968, median of 11 alternating pairs.
Building everything with GCC's `-mstringop-strategy=unrolled_loop` instead
gave 0.89 and 0.96 in two such runs (7 and 11 pairs); it was not kept, as
`perf` on that build showed the gain in `add_manifold` alone.

A fourth, on the rain of 1e5 bodies (one worker, soft step, commit 5856e6f,
`perf record`): the per-body passes of each substep took most of the time,
led by the velocities stored onto the bodies (11%), the marking for time of
impact (11%), the pose change of each body (10%) and the gravity kick (9%);
each streams the bodies through memory. Four commits (740992b, 9eac8fb,
7f350dd, 9b6d5ac, same bits) store the velocities in the move pass, skip the
pose change of a body no contact touches, give such a body its next kick in
the move pass, and let the marking read a per-frame threshold instead of the
bodies: whole-process CPU A/B 0.899, 0.945, 0.912, 0.911 (medians of 11 to
15 alternating pairs). Fusing two per-frame passes the same way (velocities
loaded with the pose reset) and the rows' unpacking with the contacts'
publication measured no gain, on the rain and on the base-100 pyramid
(whose data fit this machine's cache), and were not kept then.

A fifth, on the base-100 pyramid (one worker, soft step, commit 2022044,
`perf record` of a driver that only steps): the row passes lead (solve and
relax 24%, warm start 6%), then the stages that move points between
layouts (publishing the contacts 8%, filling the rows 8%, adding and
preparing points 10%) and the narrow phase (polygon against polygon 13%).
Two commits remove work there (same bits). 35ac911: the rows' impulses no
longer go back into the points in a pass of their own; publishing reads
each point's from its lane (a per-point map kept by the packing), so each
point is read once after the substeps. 2022044: a touching body's turn
since prepare, far below a milliradian on a resting stack, gets its cosine
and sine from their series instead of the library call. In-process stage
timers over 178 frames, 3 alternating rounds: unpacking and publishing
257/265/245 -> 216/208/180 ms, integrating positions 117/106/130 ->
86/86/111 ms. Whole-process CPU A/B of the base-100 stack bench against
1517c1b: 0.950 (median of 12 alternating pairs; 0.876 to 1.153).
"""


if __name__ == "__main__":
    main()
