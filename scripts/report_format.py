"""How the performance report writes numbers, tables and runs: significant
digits, millimetres, Markdown tables, and a run's setting and label."""
import math

from report_data import KNOB_LABELS, OPTIONAL_PEERS, PEER_NAMES, PIPELINE_NAMES, is_ours


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


def span(low_high):
    """A range of values, lowest first."""
    return f"{fmt(low_high[0])} - {fmt(low_high[1])}"


def mm(x):
    """A length in metres, written in millimetres."""
    return fmt(x * 1e3) + " mm" if finite(x) else fmt(x)


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(fmt(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


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
