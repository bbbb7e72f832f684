"""The performance report's target rows (target, measured, verdict): the stacks,
the time target against the peers, the defaults' accuracy, the earlier
targets, throughput, memory and resting cost."""
import math
import statistics

from report_data import (BOUNCE_TARGET, DRIFT_TARGET_M, FAST_BULLET, GAS_TARGET, GAS_TARGET_SECONDS, INCLINE_TARGET,
                         MEMORY_TARGET_KIB_PER_BODY, PIPELINES, PIPELINE_NAMES, RESTING_FRACTION_TARGET, SLOPE_TARGET,
                         STACK_DRIFT_TARGET_M, STACK_PENETRATION_TARGET_M, STACK_SCENES, STACK_TARGET_SECONDS,
                         STACK_TIME_TARGET, STIFF_SETTING, THROUGHPUT_SCENES, TIME_TARGET, WORKER_SPEEDUP_MIN_BODIES,
                         WORKER_SPEEDUP_TARGET, number)
from report_format import finite, fmt, mm, over, setting, span, table
from report_analysis import (baseline, cheapest_at, other, ours, peak_kib_beside_peer, scaling_slope, stack_rows,
                             throughput_rows, time_target_rows, time_target_scenes, worker_speedup_rounds)


def verdict(value, target, strict=True):
    """met, or missed by value / target (a value of 0 against a 0 target is met)."""
    if not finite(value):
        return "not measured" if math.isnan(value) else "missed"
    ok = value < target if strict else value <= target
    if ok:
        return "met"
    return f"missed by {over(value / target)}x" if target > 0 else "missed"


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
        t = stack_rows(stacks, scene, "soft", seconds=longest, stiff=True)
        target = STACK_DRIFT_TARGET_M.get(scene, DRIFT_TARGET_M)
        aside = ([f"sway {mm(r['sway_m'])}"] if finite(r["sway_m"]) else []) + (
            [f"{PIPELINE_NAMES[other_p]}: {mm(o['drift_m'])}"] if o else []) + (
            [f"soft step with {STIFF_SETTING}: {mm(t['drift_m'])}"] if t else [])
        rows.append([f"{scene} stands: drift 1 s -> {fmt(STACK_TARGET_SECONDS)} s < {mm(target)}{short}",
                     f"{mm(r['drift_m'])}" + (f" ({'; '.join(aside)})" if aside else ""),
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
        stiffs = [stack_rows(stacks, s, "soft", seconds=longest, stiff=True) for s, _ in pens]
        if all(stiffs):
            cell += (f" (soft step with {STIFF_SETTING}: " +
                     ", ".join(f"{mm(t['max_penetration_m'])}" for t in stiffs) + ")")
        missed = [s for s, r in pens if not r["max_penetration_m"] <= STACK_PENETRATION_TARGET_M]
        rows.append([f"largest penetration <= {mm(STACK_PENETRATION_TARGET_M)} on the {len(pens)} stacks", cell,
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
        rounds = f", median of {worst['rounds']} paired rounds, {span(worst['spread'])}" if worst["rounds"] else ""
        parts.append(f"worst {fmt(worst['ratio'])}x (CPU {fmt(worst_cpu)}x{rounds}): ours {worst['ours']} against "
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
            f"ContactSolver exact on random islands with masses up to 1e6: complementarity {fmt(worst)} m/s, "
            f"{fallbacks} fallbacks", "not measurable in the World"]


def large_speedup_rounds(scaling, engine):
    """(scene, bodies, each round's speed-up of 2 workers over 1) for the sizes the target covers."""
    return [(scene, int(b), r) for scene in THROUGHPUT_SCENES
            for b, r in worker_speedup_rounds(scaling, scene, engine) if b >= WORKER_SPEEDUP_MIN_BODIES]


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
    # Each round's ratio is shown as a range beside the median: on this
    # machine one round's ratio can differ from the next by half.
    speedups = large_speedup_rounds(scaling, "collision2d")
    # Box2D v3, built for threads, on the same machine: what a second core
    # gives a peer here, beside ours (not a target of its own).
    peer_rounds = large_speedup_rounds(scaling, "box2d_v3")
    one_round = all(len(r) == 1 for _, _, r in peer_rounds)
    peer = [f"{sc} {b}: {fmt(statistics.median(r))}x" + ("" if one_round else f" ({span((min(r), max(r)))})")
            for sc, b, r in peer_rounds]
    peer_label = "Box2D v3, one round" if one_round else f"Box2D v3, {max(len(r) for _, _, r in peer_rounds)} rounds"
    if speedups:
        worst = min(((sc, b, statistics.median(r)) for sc, b, r in speedups), key=lambda x: x[2])
        rows.append([f"2 workers >= {WORKER_SPEEDUP_TARGET}x faster than 1 at >= {WORKER_SPEEDUP_MIN_BODIES} bodies "
                     "(median of the rounds, their range in parentheses)",
                     ", ".join(f"{sc} {b}: {fmt(statistics.median(r))}x ({span((min(r), max(r)))}, {len(r)} rounds)"
                               for sc, b, r in speedups)
                     + (f" ({peer_label}: {', '.join(peer)})" if peer else ""),
                     "met" if worst[2] >= WORKER_SPEEDUP_TARGET else
                     f"missed by {over(WORKER_SPEEDUP_TARGET / worst[2])}x ({worst[0]} {worst[1]})"])
    slope = scaling_slope(scaling, "collision2d", scenes=tuple(THROUGHPUT_SCENES))
    rows.append([f"slope of log time against log bodies <= {SLOPE_TARGET} (pyramid and rain, 1 worker)",
                 f"{fmt(slope)}", "met" if finite(slope) and slope <= SLOPE_TARGET else
                 f"missed by {fmt(slope - SLOPE_TARGET)}" if finite(slope) else "not measured"])
    mem = peak_kib_beside_peer(scaling, THROUGHPUT_SCENES)
    if mem:
        worst = max(mem, key=lambda x: x[2])
        rows.append([f"peak memory above the empty process <= {fmt(MEMORY_TARGET_KIB_PER_BODY)} kB per body "
                     "(1e4 bodies and up)",
                     ", ".join(f"{sc} {b}: {fmt(x)} kB" + (f" (Box2D v3 {fmt(p)} kB)" if p is not None else "")
                               for sc, b, x, p in mem),
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
