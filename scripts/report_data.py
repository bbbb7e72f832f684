"""The performance report's shared constants (targets with their units, scene,
pipeline and engine names, plot colours) and its reading of the benchmark
CSVs into prepared rows; the other report_*.py modules build on it."""
import csv
import os


HEADLINE = ["pyramid", "column", "elastic_gas"]
PARETO_SCENES = ["pyramid", "column", "elastic_gas", "newtons_cradle", "bouncing_disks", "incline",
                 "incline_slide"]
SCENE_ORDER = ["pyramid", "column", "elastic_gas", "newtons_cradle", "bouncing_disks", "incline", "incline_slide",
               "bullet_wall", "bullet_wall_1e4"]
PIPELINES = ["soft", "fx2d"]
PIPELINE_NAMES = {"soft": "soft step", "fx2d": "Fx2D"}
PIPELINE_PHRASES = {"soft": "the soft step", "fx2d": "the Fx2D pipeline"}
# The stack bench's stiff soft-step row (with_stiff_contacts in bench/sweep.cpp).
STIFF_SUBSTEPS, STIFF_HERTZ, STIFF_DAMPING_RATIO, STIFF_PASSES = 6, 90, 15, 2
STIFF_SETTING = (f"{STIFF_SUBSTEPS} substeps, `contact_hertz` {STIFF_HERTZ}, "
                 f"`contact_damping_ratio` {STIFF_DAMPING_RATIO}, `soft_iterations` {STIFF_PASSES}")
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
STACK_SCENES = ["stack_pyramid_20", "stack_column_20", "stack_column_20_nudged", "stack_pyramid_60",
                "stack_pyramid_100"]
STACK_DRIFT_TARGET_M = {"stack_pyramid_100": 1e-2}  # the others: DRIFT_TARGET_M
STACK_PENETRATION_TARGET_M = 5e-3
STACK_TIME_TARGET = 2.0     # our CPU ms/frame / Box2D v3's on each stack
STACK_TARGET_SECONDS = 60.0
BOUNCE_TARGET = 1e-3        # |measured e - e| at the defaults
INCLINE_TARGET = 1e-6       # m/s^2 at the defaults
INCLINE_SLID = 0.01         # m/s^2: a held box's error this large is a slide, not settling
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
               "contact_push_speed": "push {} m/s", "speculative_margin": "margin {} m",
               "contact_reuse_distance": "reuse {} m", "sleeping": "sleeping {}",
               "soft_iterations": f"{STIFF_HERTZ} Hz, damping ratio {STIFF_DAMPING_RATIO}, {{}} passes"}
# Plot colours: ours per pipeline (all points, front), the peers.
COLOURS = {"soft": ("#f1b6da", "#c51b7d"), "fx2d": ("#9ecae1", "#08519c"), "box2d": "#ff7f00",
           "chipmunk": "#238b45", "box2d_v3": "#6a3d9a"}


THROUGHPUT_SCENES = ["pyramid", "rain"]
WORKER_SPEEDUP_TARGET = 1.7
WORKER_SPEEDUP_MIN_BODIES = 5000
MEMORY_TARGET_KIB_PER_BODY = 1.0
# "Per-frame cost follows what moves", read as: a settled world's frame, and
# one where a single body moves, cost at most this fraction of the same world
# awake.
RESTING_FRACTION_TARGET = 0.01


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


def v3_on_two_workers(scaling):
    """Whether the run timed Box2D v3 on 2 workers (reports before it did not)."""
    return any(r["engine"] == "box2d_v3" and r.get("workers", "1") == "2" for r in scaling)


def v3_in_rounds(scaling):
    """Whether Box2D v3 ran in the throughput rounds beside ours (reports before ran it once)."""
    return v3_on_two_workers(scaling) and throughput_rounds(scaling, "box2d_v3") > 1


def v3_threads(scaling):
    """How the report ran Box2D v3 in the throughput part, in words."""
    if v3_in_rounds(scaling):
        return ("when it is in the run, in the same\n"
                "rounds as ours, on one thread and then on two (`workerCount` 2, its own\n"
                "scheduler): what a second core gives the peer built for threads on this machine")
    if v3_on_two_workers(scaling):
        return ("when it is in the run, on one\n"
                "thread and then once on two (`workerCount` 2, its own scheduler): what a\n"
                "second core gives the peer built for threads on this machine")
    return "on one\nthread when it is in the run"


def throughput_rounds(scaling, engine="collision2d"):
    """How many rounds an engine ran at each throughput size (the script alternates 1 and 2 workers)."""
    return max((r["rounds"] for r in scaling if r["engine"] == engine and r.get("workers", "1") == "2"),
               default=1)


def is_ours(run):
    return run["engine"] == "collision2d"


def is_stiff(run):
    """A stack bench row of ours with the stiff soft-step setting."""
    return run.get("variant") == "stiff"


# The columns that tell one run of a scene from another (run_key in bench/sweep_bench.cpp).
KEY_COLUMNS = ("part", "engine", "variant", "pipeline", "knob", "value", "substeps", "iterations")


def run_key(run):
    """How the sweep bench's `paired` part names a run."""
    return "|".join(run.get(c) or "" for c in KEY_COLUMNS)


def attach_paired(runs, paired):
    """Each run timed again in paired rounds (paired.csv) gets r["paired_rounds"]:
    {round: (wall ms, CPU ms)}."""
    by_key = {}
    for row in paired:
        by_key.setdefault((row["scene"], row["key"]), {})[int(row["round"])] = (number(row["ms_per_step"]),
                                                                                 number(row["cpu_ms_per_step"]))
    for r in runs:
        r["paired_rounds"] = by_key.get((r["scene"], run_key(r)), {})
    return runs


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
        # Stack benches before the sway column wrote none.
        r["sway_m"] = number(r.get("sway_m"))
    return stacks
