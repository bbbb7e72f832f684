"""The performance report's PNG plots, drawn by gnuplot: the Pareto fronts of
time against accuracy, the scaling, the throughput and the speed-up of 2
workers over 1."""
import os
import subprocess

from report_data import (COLOURS, ERROR_UNITS, OPTIONAL_PEERS, PEERS, PEER_NAMES, PIPELINES, PIPELINE_NAMES,
                         PLOT_FLOOR, THROUGHPUT_SCENES, WORKER_SPEEDUP_TARGET)
from report_analysis import baseline, gas_rows, ours, pareto, peers, throughput_rows, worker_speedups


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


def plot_workers(scaling, png, workdir):
    lines = []
    # A scene keeps its colour (gnuplot's line types 1 and 3, as before the
    # peer's lines); Box2D v3's line is dotted.
    for colour, scene in zip((1, 3), THROUGHPUT_SCENES):
        for engine, name, label, style in [("collision2d", f"speedup_{scene}", scene, f"lc {colour}"),
                                           ("box2d_v3", f"speedup_{scene}_box2d_v3", f"{scene}: Box2D v3",
                                            f"lc {colour} dt 3")]:
            pts = worker_speedups(scaling, scene, engine)
            if pts:
                lines.append(points_line(workdir, name, pts, label, style))
    if not lines:
        return False
    gnuplot(f"""set terminal pngcairo size 800,480 noenhanced
set output '{png}'
set title 'Speed-up of 2 workers over 1 (wall time per frame)'
set logscale x
set xlabel 'dynamic bodies'
set ylabel 'time with 1 worker / time with 2'
set yrange [0:2.2]
set grid
set key left top
plot {", ".join(lines)}, {WORKER_SPEEDUP_TARGET} dt 2 lc rgb 'gray' title 'target {WORKER_SPEEDUP_TARGET}'
""", workdir)
    return True
