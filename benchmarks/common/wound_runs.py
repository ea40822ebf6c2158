"""What the convergence benchmarks share: the paper decks, the wound figures read from a
run's summary.json, and running vulnus once per case (a completed run is reused)."""
import json
import os
import shlex
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
VULNUS = os.environ.get("VULNUS", os.path.join(ROOT, "build", "app", "vulnus"))
PAPER = os.path.join(ROOT, "inputs", "paper")
SCENES = ["anisotropic_150ms", "anisotropic_50ms", "isotropic_150ms", "isotropic_50ms"]


def mean(values):
    return sum(values) / len(values) if values else None


FIGURES = [
    ("vol_matrix", lambda s: s["failed_volume_m3"]["matrix"]),
    ("vol_fiber", lambda s: s["failed_volume_m3"]["fiber"]),
    ("vol_total", lambda s: s["failed_volume_m3"]["total"]),
    ("entrance_d", lambda s: s["entrance_wound"]["equivalent_diameter_m"]),
    ("exit_d", lambda s: s["exit_wound"]["equivalent_diameter_m"]),
    ("entrance_aspect", lambda s: s["entrance_wound"]["aspect_ratio"]),
    ("exit_aspect", lambda s: s["exit_wound"]["aspect_ratio"]),
    ("tract_area", lambda s: mean(s["tract"]["area_m2"])),
    ("exit_velocity", lambda s: s["bullet"]["exit_velocity_m_s"]),
]
# The figures that measure the mechanics, beside the paper's flags: the debris (failed points
# that carry no deviatoric stress) and the faces' smoothed outlines; each with the name
# summary.json's wound_resolution judges it under.
MECHANICS = [
    ("debris_volume", lambda s: s["debris"]["volume_m3"], "debris"),
    ("debris_tract_area", lambda s: mean(s["tract"]["debris_area_m2"]), "tract.debris_area_m2"),
    ("entrance_outline_d",
     lambda s: s["entrance_wound"]["outline"]["equivalent_diameter_m"], "entrance_wound.outline"),
    ("entrance_outline_aspect",
     lambda s: s["entrance_wound"]["outline"]["aspect_ratio"], "entrance_wound.outline"),
    ("exit_outline_d",
     lambda s: s["exit_wound"]["outline"]["equivalent_diameter_m"], "exit_wound.outline"),
    ("exit_outline_aspect",
     lambda s: s["exit_wound"]["outline"]["aspect_ratio"], "exit_wound.outline"),
]
# The wound_resolution entry of each paper figure (None: always resolved, as the exit velocity).
FLAG_NAMES = {
    "vol_matrix": "failed_volume_m3.matrix", "vol_fiber": "failed_volume_m3.fiber",
    "vol_total": "failed_volume_m3.total", "entrance_d": "entrance_wound",
    "exit_d": "exit_wound", "entrance_aspect": "entrance_wound", "exit_aspect": "exit_wound",
    "tract_area": "tract.area_m2", "exit_velocity": None,
}


def all_figures():
    """(name, getter, resolution entry) of every wound figure: the paper's, then the mechanics'."""
    return [(f, g, FLAG_NAMES.get(f)) for f, g in FIGURES] + MECHANICS


def resolved(summary, name):
    """Whether the run's summary marks the figure `name` resolved at its cell."""
    if name is None:
        return True
    for entry in summary.get("wound_resolution", {}).get("figures", []):
        if entry["figure"] == name:
            return bool(entry["resolved"])
    return True


# A failed volume below this fraction of the total (the fiber-only remainder; none in the
# isotropic slabs) is measured against the total failed volume, not against itself.
SMALL_VOLUME_FRACTION = 0.01


def value(summary, getter):
    try:
        v = getter(summary)
        return None if v is None else float(v)
    except (KeyError, TypeError):
        return None


def relative(a, b, scale):
    if a is None or b is None or scale == 0:
        return float("nan")
    return abs(a - b) / abs(scale)


def scale_of(figure, reference, total):
    """What a change of `figure` is measured against: its reference value, or the total failed
    volume for a failed volume that is a tiny part of it."""
    scale = reference if reference else 1.0
    if figure.startswith("vol_") and abs(reference or 0) < SMALL_VOLUME_FRACTION * total:
        scale = total
    return scale


def deck_entry(deck, path):
    """The value of `path` ('Section/Sub/Entry') in a deck file, or None when it is not set."""
    *sections, entry = path.split("/")
    stack = []
    with open(deck, encoding="utf-8") as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            if words[0] == "subsection":
                stack.append(" ".join(words[1:]))
            elif words[0] == "end":
                stack.pop()
            elif words[0] == "set" and stack == sections:
                name, _, text = " ".join(words[1:]).partition("=")
                if name.strip() == entry:
                    return text.strip()
    return None


def completed_summary(directory):
    path = os.path.join(directory, "summary.json")
    if not os.path.isfile(path):
        return None
    with open(path, encoding="utf-8") as f:
        summary = json.load(f)
    return summary if summary.get("completed") else None


def run_once(deck, directory, settings, options=()):
    """Runs `vulnus run deck` with the --set entries (and the command-line `options`) into
    `directory` unless a completed run is there; returns its summary, or None when it did not
    complete. No particle series is written (the figures are in summary.json) unless the
    settings ask for one."""
    summary = completed_summary(directory)
    if summary:
        return summary
    subprocess.run(["rm", "-rf", directory], check=True)
    command = [VULNUS, "run", deck, "--output", directory] + list(options)
    for entry in ["Output/Particle output interval=0"] + list(settings):
        command += ["--set", entry]
    print("$ " + shlex.join(command), flush=True)
    start = time.time()
    status = subprocess.run(command, stdout=subprocess.DEVNULL, check=False).returncode
    print("  exit status %d, %.0f s" % (status, time.time() - start), flush=True)
    return completed_summary(directory)
