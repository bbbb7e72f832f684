"""The performance report's measured sections: the machine and run, and the
detail tables (peers, time target, knobs, stands, mass ratios, solver,
scaling, throughput, stacks)."""
import datetime
import os
import platform
import statistics
import subprocess

from report_data import (ERROR_UNITS, OPTIONAL_PEERS, PEERS, PEER_NAMES, PIPELINE_NAMES, PIPELINE_PHRASES,
                         STACK_SCENES, STIFF_SETTING, THROUGHPUT_SCENES, is_ours, is_stiff, number, v3_on_two_workers)
from report_format import fmt, label, setting, span, table
from report_analysis import (baseline, gas_rows, other, ours, ratio, round_speedups, scaling_slope, scene_names,
                             time_target_rows, time_target_scenes)
from report_targets import throughput_target_rows


def has_v3(runs, stacks, scaling):
    return any(r["engine"] == "box2d_v3" for r in list(runs) + list(stacks) + list(scaling))


def pinned_line(args, scaling):
    """Where the single-threaded runs ran, when the script pinned them."""
    if not args.pinned_cpu:
        return ""
    return (f"- Every single-threaded run (ours with 1 worker, every peer) ran on core {args.pinned_cpu} "
            f"(`taskset`); ours{' and Box2D v3' if v3_on_two_workers(scaling) else ''} with 2 workers on both cores.\n")


def cpu_fields():
    """The first processor's fields of /proc/cpuinfo (empty where there is none)."""
    fields = {}
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if not line.strip():
                    break
                key, _, value = line.partition(":")
                fields[key.strip()] = value.strip()
    except OSError:
        pass
    return fields


def cache_sizes():
    """Each cache level of the first core with its size, as the kernel lists them ("L2 512K")."""
    root = "/sys/devices/system/cpu/cpu0/cache"

    def read(index, name):
        with open(os.path.join(root, index, name)) as f:
            return f.read().strip()

    try:
        return [f"L{read(i, 'level')} {read(i, 'size')}" for i in sorted(os.listdir(root))
                if i.startswith("index") and read(i, "type") != "Instruction"]
    except OSError:
        return []


def row_lanes(flags):
    """How many lanes the soft step's rows run on a CPU with these flags, as
    the core chooses (src/core/soft_rows_dispatch.cpp)."""
    if {"avx512f", "avx512dq"} <= flags:
        return "AVX-512: the soft step's rows run eight lanes"
    if "avx2" in flags:
        return "AVX2: the soft step's rows run four lanes"
    return "no AVX2: the soft step's rows run two lanes"


def cpu_description():
    """The CPU as the report names it. The model name alone ("AMD EPYC" on this
    host) hides the generation, and the same build's ratios to the peers moved
    by a third between two hosts of that name (docs/performance.md, profile notes)."""
    cpu = cpu_fields()
    text = cpu.get("model name", "unknown CPU")
    detail = []
    if "cpu family" in cpu and "model" in cpu:
        detail.append(f"family {cpu['cpu family']} model {cpu['model']}")
    if "flags" in cpu:
        detail.append(row_lanes(set(cpu["flags"].split())))
    detail += cache_sizes()
    return f"{text} ({', '.join(detail)})" if detail else text


def machine_section(args, runs, stacks, scaling, default):
    model = cpu_description()
    commit = args.commit
    try:
        commit = commit or subprocess.run(["git", "-C", os.path.dirname(os.path.abspath(__file__)), "rev-parse",
                                           "--short", "HEAD"], capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = "unknown"
    load = args.load or ", ".join(f"{x:.1f}" for x in os.getloadavg())
    measured = args.date or datetime.date.today().isoformat()
    kernel = args.kernel or platform.release()
    grid = "quick (--quick: thinned grids, stacks to 10 s, stands to 20 s)" if args.quick else "full"
    v3 = ("**Box2D v3 was included** in this run as a third peer (built from a checkout outside this repository, "
          "given through `COLLISION2D_BOX2D_V3_DIR`)" if has_v3(runs, stacks, scaling) else
          "**Box2D v3 was not included** in this run (the script was not given `COLLISION2D_BOX2D_V3_DIR`), so "
          "there are no ratios to it")
    return (f"- Machine: {model}, {os.cpu_count()} logical cores, {platform.system()} {kernel}; "
            f"load average at report time {load} (the cores were shared with other work, see *Timing*).\n"
            f"{pinned_line(args, scaling)}"
            f"- Measured {measured} at commit `{commit}` (plus any uncommitted changes in the tree), {grid} grids, "
            f"all measurements in one run of `scripts/performance_report.sh` taking {args.elapsed} s.\n"
            f"- Peers: Box2D 2.4.1 and Chipmunk 7 in every part; {v3}.\n"
            f"- Ours in both pipelines, each run naming its own: the **soft step** (`soft_step: true`) and the "
            f"**Fx2D** order (`soft_step: false`). The default in the build measured: the "
            f"**{PIPELINE_PHRASES[default].replace('the ', '', 1)}**.\n")


def speedup_cell(ratios):
    """Rounds' speed-ups as their median and range: "1.69x (1.38 - 2)"."""
    return f"{fmt(statistics.median(ratios))}x ({span((min(ratios), max(ratios)))})"


def paced_table(paced):
    """Ours on 1 and 2 workers with a frame every period, as a ROS timer steps a world."""
    rows = [[scene, str(int(bodies)), period, one, two, speedup_cell(r)]
            for scene, bodies, period, one, two, r in round_speedups(paced)]
    if not rows:
        return ""
    return ("\nStepped on a clock (`collision2d_scaling_bench --period-ms`): one frame every period, as a timer "
            "in a ROS node steps a world, so the workers sleep between frames; only the steps are timed (wall). "
            "The speed-up is the median of each round's own ratio, with its range.\n\n" +
            table(["scene", "bodies", "period (ms)", "1 worker (ms/frame)", "2 workers (ms/frame)",
                   "2 workers over 1"], rows))


def busy_table(busy):
    """Each engine on 1 and 2 workers beside another process that keeps a core busy."""
    points = [(engine, p) for engine in ("collision2d", "box2d_v3") for p in round_speedups(busy, engine)]
    if not points:
        return ""
    rows = [[scene, str(int(bodies)), PEER_NAMES.get(engine, "ours"), one, two, speedup_cell(r)]
            for engine, (scene, bodies, _, one, two, r) in points]
    rounds = max(len(r) for _, (_, _, _, _, _, r) in points)
    plural = "s" if rounds != 1 else ""
    return (f"\nBeside a busy core: a shell loop (`while :; do :; done`) kept core {busy[0]['busy_cpu']} busy, as "
            "another process on a robot's computer may, while 1 worker ran on the pinned core and 2 workers on "
            f"both; {rounds} round{plural}, each a 1-worker run and the 2-worker run after it (wall). A speed-up "
            "under 1 means the second worker cost time.\n\n" +
            table(["scene", "bodies", "engine", "1 worker (ms/frame)", "2 workers (ms/frame)", "2 workers over 1"],
                  rows))


def throughput_section(scaling, stacks, default, paced, busy=()):
    runs = [r for r in scaling if r.get("scene") in THROUGHPUT_SCENES + ["resting", "stirred"]]
    if not runs:
        return "Not measured in this run.\n"
    rows = [[r["scene"], r["engine"], r["workers"], r["bodies"], r["frames"], number(r["ms_per_step"]),
             number(r["ms_per_step"]) * 1e3 / number(r["bodies"]),
             (number(r["vmhwm_kib"]) - number(r["vmhwm_start_kib"])) / number(r["bodies"])]
            for r in sorted(runs, key=lambda r: (r["scene"], r["engine"], r["workers"], number(r["bodies"])))]
    return (table(["target", "measured", "verdict"], throughput_target_rows(scaling, stacks, default)) + "\n" +
            table(["scene", "engine", "workers", "bodies", "timed frames", "ms/frame (wall)", "us per body",
                   "peak memory above start (kB/body)"], rows) + paced_table(paced) + busy_table(busy))


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


def paired_rounds(row):
    """A time-target row's rounds and the range of their wall ratios."""
    if not row["rounds"]:
        return "none"
    return f"{row['rounds']} ({span(row['spread'])})"


def time_target_section(runs):
    out = ""
    for scene in time_target_scenes(runs):
        trs = time_target_rows(runs, scene)
        if not trs:
            continue
        out += f"\n**{scene}**\n\n"
        out += table(["peer run", "peer ms", "peer error", "our cheapest run at <= that error", "our ms",
                      "our error", "ours / peer (wall)", "ours / peer (CPU)", "paired rounds (wall ratio range)"],
                     [[t["peer"], t["peer_ms"], t["peer_err"], t["ours"], t["ours_ms"], t["ours_err"], t["ratio"],
                       t["ratio_cpu"], paired_rounds(t)] for t in trs])
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
    if is_ours(r) and is_stiff(r):
        return f"ours {PIPELINE_NAMES[r['pipeline']]}, {STIFF_SETTING}"
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
        engines = sorted({(r["engine"], r["pipeline"], is_stiff(r)) for r in stacks
                          if r["scene"] == scene},
                         key=lambda eps: (order.get(eps[0], 9), eps[1] != default, eps[2]))
        for engine, pipeline, stiff in engines:
            at = {r["seconds"]: r for r in stacks if r["scene"] == scene and r["engine"] == engine
                  and r["pipeline"] == pipeline and is_stiff(r) == stiff}
            last = at[max(at)]
            name = stack_engine_label(last) + (" (default)" if is_ours(last) and pipeline == default and not stiff
                                               else "")
            rows.append([scene.replace("stack_", ""), last["boxes"], name, last["ms_per_frame"],
                         last["cpu_ms_per_frame"], last["ms_over_box2d_v3"], last["cpu_ms_over_box2d_v3"]] +
                        [at[c]["drift_m"] * 1e3 if c in at else float("nan") for c in checkpoints] +
                        [last["sway_m"] * 1e3, last["max_penetration_m"] * 1e3])
    out += table(["scene", "boxes", "engine", "ms/frame", "CPU ms/frame", "time / Box2D v3", "CPU time / Box2D v3"] +
                 [f"drift 1 s -> {fmt(c)} s (mm)" for c in checkpoints] +
                 [f"sway 1 s -> {fmt(longest)} s (mm)", f"largest penetration to {fmt(longest)} s (mm)"], rows)
    return out
