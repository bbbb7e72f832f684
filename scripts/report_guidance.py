"""The performance report's guidance: which pipeline and settings to use, per
kind of scene, written from the measured numbers."""

import math
import statistics

from report_data import (BOUNCE_TARGET, DRIFT_TARGET_M, FAST_BULLET, GAS_TARGET, INCLINE_SLID, INCLINE_TARGET,
                         PIPELINES, PIPELINE_NAMES, PIPELINE_PHRASES, STACK_SCENES, STIFF_SETTING, THROUGHPUT_SCENES,
                         number)
from report_format import finite, fmt, mm, setting
from report_analysis import (baseline, cheapest_at, find, other, ours, peak_kib_beside_peer, round_speedups,
                             scene_names, stack_rows, worker_speedups)


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
                 f"runs at other iteration counts matched their defaults exactly): the soft step's passes per "
                 f"substep are `soft_iterations` (one solve and one relax pass by default)")
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
    stiff = [(s, stack_rows(stacks, s, "soft"), stack_rows(stacks, s, "soft", stiff=True)) for s in scenes]
    stiff = [(s, d, t) for s, d, t in stiff if d and t]
    if stiff:
        lines.append("  - Taller stacks: the soft step with more substeps, the stiffest contacts they allow, more "
                     "damping and two passes (" + STIFF_SETTING + "), drifted " +
                     "; ".join(f"{s.replace('stack_', '')} {mm(t['drift_m'])}, penetration {mm(t['max_penetration_m'])}"
                               f" at {fmt(t['cpu_ms_per_frame'] / d['cpu_ms_per_frame'])}x the defaults' CPU time"
                               for s, d, t in stiff) + ".")
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
                " (too costly for large islands: the pyramid is not run exact). Let large resting scenes sleep "
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
    """The soft step's substep counts at which the held box misses the target, and whether it slid or settles."""
    missed = sorted((r for r in ours(runs, "incline", pipeline="soft")
                     if r["part"] == "world" and r["knob"] == "substeps" and finite(r["err"])
                     and r["err"] > INCLINE_TARGET), key=lambda r: r["substeps"])
    if not missed:
        return None
    counts = " and ".join(str(r["substeps"]) for r in missed)
    worst = max(r["err"] for r in missed)
    if worst > INCLINE_SLID:
        return (f"On a slope that friction must hold, give the soft step more than {missed[-1]['substeps']} "
                f"substeps: at {counts} the box slid ({fmt(worst)} m/s^2)")
    return (f"At {counts} substeps the held box does not slide but is still settling after 0.5 s (a mean "
            f"acceleration of {fmt(worst)} m/s^2 to 2 s): its contacts are softer there, their stiffness being "
            f"capped at a quarter of the substep rate")


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


# A second worker "pays" where the median round ran at least this much faster.
WORKERS_PAY = 1.2


def paced_sentence(paced):
    """What 2 workers gave a world stepped on a clock, or "" where none was."""
    points = round_speedups(paced)
    if not points:
        return ""
    periods = sorted({period for _, _, period, _, _, _ in points})
    cells = {}
    for scene, bodies, period, _, _, ratios in points:
        cells.setdefault((scene, bodies), []).append(f"{fmt(statistics.median(ratios))}x")
    return (" Stepped on a clock, one frame every " + ", ".join(fmt(p) for p in periods) + " ms (a ROS timer; the "
            "workers sleep between frames): " + "; ".join(f"{scene} {int(b)} " + ", ".join(c)
                                                           for (scene, b), c in cells.items()) + ".")


def busy_sentence(busy):
    """What 2 workers gave beside a core another process kept busy, or "" where not measured."""
    cells = {engine: [f"{scene} {int(bodies)} {fmt(statistics.median(r))}x"
                      for scene, bodies, _, _, _, r in round_speedups(busy, engine)]
             for engine in ("collision2d", "box2d_v3")}
    if not cells["collision2d"]:
        return ""
    peer = f" (Box2D v3: {', '.join(cells['box2d_v3'])})" if cells["box2d_v3"] else ""
    paid = [f"{scene} {int(bodies)}" for scene, bodies, _, _, _, r in round_speedups(busy)
            if statistics.median(r) >= WORKERS_PAY]
    verdict = (f"a second worker still paid ({fmt(WORKERS_PAY)}x or more) in: {', '.join(paid)}" if paid else
               "a second worker pays only on a core of its own")
    return (f" With another process keeping one of the cores busy (a shell loop on core {busy[0]['busy_cpu']}): "
            f"{', '.join(cells['collision2d'])}{peer}; {verdict}.")


def guidance_workers(scaling, paced=(), busy=()):
    """Where `workers: 2` paid in the throughput rounds (each round's own ratio, their median), and
    on a clock and beside a busy core where the report stepped worlds those ways."""
    cells, paid, unpaid = [], [], []
    for scene in THROUGHPUT_SCENES:
        points = worker_speedups(scaling, scene)
        if points:
            cells.append(f"{scene} " + ", ".join(f"{int(b)} bodies {fmt(s)}x" for b, s in points))
            paid += [(scene, b) for b, s in points if s >= WORKERS_PAY]
            unpaid += [(scene, b) for b, s in points if s < WORKERS_PAY]
    if not cells:
        return None

    def named(worlds):
        return ", ".join(f"{scene} {int(b)}" for scene, b in worlds) or "none"

    advice = ("keep 1 worker" if not paid else
              f"keep 1 worker below some {int(10 ** round(math.log10(min(b for _, b in paid))))} bodies "
              "and measure a world that size before adding one")
    return ("- **Workers.** 2 workers against 1 (wall time, median of each throughput round's own ratio): " +
            "; ".join(cells) + f". A second worker paid ({fmt(WORKERS_PAY)}x or more) in: {named(paid)}; "
            f"not in: {named(unpaid)}.{paced_sentence(paced)}{busy_sentence(busy)} So {advice}. Trajectories are "
            "the same for any count.")


def guidance_memory(scaling):
    """What a large world costs in memory a body, from the throughput rows (1 worker)."""
    mem = peak_kib_beside_peer(scaling, THROUGHPUT_SCENES)
    if not mem:
        return None
    cells = [f"{scene} {b} {fmt(x)} kB" + (f" (Box2D v3 {fmt(p)})" if p is not None else "")
             for scene, b, x, p in mem]
    most = max(mem, key=lambda x: x[2])
    least = min(mem, key=lambda x: x[2])
    return ("- **Memory.** Peak resident memory above the empty process, a body (1 worker): " + ", ".join(cells) +
            f". Plan on {fmt(least[2])} to {fmt(most[2])} kB a body ({least[0]} {least[1]} to {most[0]} "
            f"{most[1]}): what a body costs grows with its contacts, which hold most of it (the profile notes "
            "break it down).")


def guidance_section(runs, stacks, default, scaling, paced, busy=()):
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
             guidance_mass_ratio(runs, default), guidance_realtime(runs, default),
             guidance_workers(scaling, paced, busy),
             guidance_memory(scaling)]
    return "\n".join(line for line in lines if line) + "\n"
