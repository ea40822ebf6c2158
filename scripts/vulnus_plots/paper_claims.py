"""The paper's qualitative claims about the wound, checked against vulnus runs: each claim
becomes a measured figure and a threshold, so the table says which claims a run reproduces.

Thresholds: on the coarse grid (1 mm cells, a 9 mm bullet) a wound is about nine cells
across, so one cell more along one axis changes the aspect ratio by about 11 %; a wound is
called circular below 1.25 (two cells) and elliptic above."""
import numpy as np

from .run_data import summary_value

CIRCULAR_BELOW = 1.25


def failure_zones(wound):
    """Counts and median distances from the tract axis (reference positions, m) of the
    target's points by final flag: 1 matrix only, 2 fiber only, 3 total."""
    radius = np.linalg.norm(wound.reference[:, [0, 2]] - wound.centre, axis=1)
    zones = {}
    for flag, name in ((1, "matrix"), (2, "fiber"), (3, "total")):
        chosen = radius[wound.flags == flag]
        zones[name] = {"count": int(chosen.size),
                       "median_radius_m": float(np.median(chosen)) if chosen.size else None}
    return zones


def layered(zones, anisotropic=True):
    """The paper's layering: total failure innermost, matrix-only and (for a slab with
    fibers) fiber-only failure around it: present and further out."""
    total = zones["total"]["median_radius_m"]
    if total is None:
        return False
    outer = [zones[name]["median_radius_m"]
             for name in (("matrix", "fiber") if anisotropic else ("matrix",))]
    return all(r is not None and r > total for r in outer)


def tract_growth(summary):
    """Mean total-failure area of the deepest third of the tract over the shallowest third
    (> 1: the tract widens towards the exit); None without a tract."""
    area = summary_value(summary, "tract", "area_m2") or []
    third = len(area) // 3
    if third == 0:
        return None
    first, last = np.mean(area[:third]), np.mean(area[-third:])
    return float(last / first) if first > 0 else None


def _ratio(summary, face):
    value = summary_value(summary, face + "_wound", "aspect_ratio")
    return None if value is None else float(value)


def _fmt(value, digits=3):
    return "n/a" if value is None else ("%.*g" % (digits, value))


def radius_mm(zones, name):
    radius = zones[name]["median_radius_m"]
    return _fmt(None if radius is None else 1e3 * radius)


def evaluate(runs):
    """runs: {name: (summary, zones)} with names like 'anisotropic_150ms_coarse'. Returns
    rows (claim, run, figure text, holds: True/False/None when the figure is missing)."""
    rows = []
    for name, (summary, zones) in sorted(runs.items()):
        ratio = _ratio(summary, "entrance")
        rows.append(("entrance wound circular (aspect ratio < %.2f)" % CIRCULAR_BELOW, name,
                     "entrance aspect ratio %s" % _fmt(ratio),
                     None if ratio is None else ratio < CIRCULAR_BELOW))
    for name, (summary, zones) in sorted(runs.items()):
        if not name.startswith("anisotropic"):
            continue  # without fibers a failed matrix is total failure: no layers to show
        rows.append(("total failure next to the tract, matrix and fiber failure around it", name,
                     "median distance from the axis: total %s mm, matrix %s mm (%d points), "
                     "fiber %s mm (%d points)" % (
                         radius_mm(zones, "total"), radius_mm(zones, "matrix"),
                         zones["matrix"]["count"], radius_mm(zones, "fiber"),
                         zones["fiber"]["count"]),
                     layered(zones)))
    for name, (summary, zones) in sorted(runs.items()):
        growth = tract_growth(summary)
        rows.append(("tract diameter grows from entrance to exit", name,
                     "total-failure area, exit third / entrance third: %s" % _fmt(growth),
                     None if growth is None else growth > 1.0))
    for name, (summary, zones) in sorted(runs.items()):
        ratio = _ratio(summary, "exit")
        anisotropic = name.startswith("anisotropic")
        claim = ("exit wound elliptic for the anisotropic slab" if anisotropic
                 else "exit wound circular for the isotropic slab")
        holds = None if ratio is None else (ratio >= CIRCULAR_BELOW if anisotropic
                                            else ratio < CIRCULAR_BELOW)
        rows.append((claim + " (paper: at 50 m/s)", name, "exit aspect ratio %s" % _fmt(ratio),
                     holds))
    return rows


def markdown_table(rows):
    lines = ["| paper's claim | run | vulnus | reproduced |", "|---|---|---|---|"]
    for claim, name, figure, holds in rows:
        verdict = {True: "yes", False: "**no**", None: "no data"}[holds]
        lines.append("| %s | %s | %s | %s |" % (claim, name, figure, verdict))
    return "\n".join(lines) + "\n"
