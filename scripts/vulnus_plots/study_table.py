"""The table and comparison picture of a study (scripts/study): one row per run with its
varied values, exit status and the main wound figures of its summary.json."""
import csv
import os

import numpy as np

from . import style
from .run_data import summary_value as _get


def _vector_y(v):
    return None if v is None else v[1]


def _supports_y(summary):
    """Impulse all domain faces' supports gave the target along y (the paper's flight axis)."""
    supports = _get(summary, "supports")
    if not supports:
        return None
    return sum(face["impulse_N_s"][1] for face in supports.values())


# (CSV header, how to read it from summary.json)
FIGURES = [
    ("completed", lambda s: _get(s, "completed")),
    ("failed_matrix", lambda s: _get(s, "failed", "matrix")),
    ("failed_fiber", lambda s: _get(s, "failed", "fiber")),
    ("failed_total", lambda s: _get(s, "failed", "total")),
    ("entrance_diameter_m", lambda s: _get(s, "entrance_wound", "equivalent_diameter_m")),
    ("entrance_aspect_ratio", lambda s: _get(s, "entrance_wound", "aspect_ratio")),
    ("exit_diameter_m", lambda s: _get(s, "exit_wound", "equivalent_diameter_m")),
    ("exit_aspect_ratio", lambda s: _get(s, "exit_wound", "aspect_ratio")),
    ("bullet_exited", lambda s: _get(s, "bullet", "exited")),
    # empty when the bullet did not leave the target; its speed at the end is the next column
    ("bullet_exit_velocity_m_s", lambda s: _get(s, "bullet", "exit_velocity_m_s")),
    ("bullet_velocity_now_m_s", lambda s: _get(s, "bullet", "velocity_now_m_s")),
    ("kinetic_energy_lost_J", lambda s: _get(s, "bullet", "kinetic_energy_lost_J")),
    ("energy_balance_error", lambda s: _get(s, "energy", "balance_error")),
    ("end_time_s", lambda s: _get(s, "time_s")),
    ("target_kinetic_energy_J", lambda s: _get(s, "target", "kinetic_energy_J")),
    ("target_momentum_y_kg_m_s", lambda s: _vector_y(_get(s, "target", "momentum_kg_m_s"))),
    ("supports_impulse_y_N_s", lambda s: _supports_y(s)),
    ("wall_seconds", lambda s: _get(s, "wall_seconds")),
    ("steps", lambda s: _get(s, "steps")),
    ("particles", lambda s: _get(s, "particles")),
    ("warnings", lambda s: None if _get(s, "warnings") is None else len(_get(s, "warnings"))),
]


class StudyRun:
    """One combination: its name, varied values {column: value}, and (after running) the
    exit status and summary.json contents (None when absent)."""

    def __init__(self, name, values, directory):
        self.name, self.values, self.directory = name, values, directory
        self.status, self.summary = None, None

    def label(self):
        # A deck path is shown by its name alone.
        shown = [os.path.splitext(os.path.basename(v))[0] if str(v).endswith(".prm") else str(v)
                 for v in self.values.values()]
        return "\n".join(shown) or self.name

    def figure(self, header):
        getter = dict(FIGURES)[header]
        value = getter(self.summary) if self.summary else None
        return np.nan if value is None else float(value)


def write_csv(path, runs, varied_columns):
    headers = ["run"] + varied_columns + ["exit_status"] + [h for h, _ in FIGURES]
    with open(path, "w", encoding="utf-8", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(headers)
        for run in runs:
            row = [run.name] + [run.values[c] for c in varied_columns]
            row.append("" if run.status is None else run.status)
            for header, getter in FIGURES:
                value = getter(run.summary) if run.summary else None
                if isinstance(value, bool):
                    value = "true" if value else "false"
                row.append("" if value is None else value)
            writer.writerow(row)
    print("wrote %s" % path)


def _bars(axis, runs, headers, labels, scale=1.0, unit=""):
    x = np.arange(len(runs))
    width = 0.8 / len(headers)
    for k, header in enumerate(headers):
        values = np.array([scale * run.figure(header) for run in runs])
        colour = None
        for flag, name in ((1, "matrix"), (2, "fiber"), (3, "total")):
            if header == "failed_" + name:
                colour = style.FLAG_COLOURS[flag]
        axis.bar(x + (k - (len(headers) - 1) / 2) * width, np.nan_to_num(values), width,
                 label=labels[k], color=colour)
    for i, run in enumerate(runs):
        if run.status not in (0, None) or not run.summary:
            axis.annotate("failed (%s)" % run.status if run.status not in (0, None)
                          else "no summary", (i, 0), ha="center", va="bottom", fontsize=7,
                          rotation=90, color="r")
    axis.set_xticks(x)
    axis.set_xticklabels([run.label() for run in runs], fontsize=7)
    if len(headers) > 1:
        axis.legend(fontsize=7)
    axis.set_ylabel(unit)
    axis.grid(axis="y", alpha=0.3)


def plot_comparison(path, runs, title):
    panels = [
        ("Failed points", ["failed_matrix", "failed_fiber", "failed_total"],
         ["matrix", "fiber", "total"], 1.0, "points"),
        ("Wound diameter", ["entrance_diameter_m", "exit_diameter_m"], ["entrance", "exit"],
         1e3, "mm"),
        ("Wound aspect ratio", ["entrance_aspect_ratio", "exit_aspect_ratio"],
         ["entrance", "exit"], 1.0, "major / minor"),
        ("Bullet exit velocity", ["bullet_exit_velocity_m_s"], [""], 1.0, "m/s"),
        ("Target momentum and supports' impulse, y",
         ["target_momentum_y_kg_m_s", "supports_impulse_y_N_s"], ["target", "supports"], 1e3,
         "g m/s"),
        ("Target kinetic energy", ["target_kinetic_energy_J"], [""], 1.0, "J"),
        ("Energy balance error", ["energy_balance_error"], [""], 1.0, "fraction"),
        ("Wall time", ["wall_seconds"], [""], 1.0, "s"),
    ]
    fig, axes = style.figure(2, 4, width=max(4.5, 0.6 * len(runs) + 2.0), height=3.6)
    for axis, (name, headers, labels, scale, unit) in zip(axes.flat, panels):
        _bars(axis, runs, headers, labels, scale, unit)
        axis.set_title(name)
    fig.suptitle(title)
    fig.tight_layout()
    style.save(fig, path)
