"""Reading one vulnus run directory: summary.json, history.csv, particles_NNNNN.h5 and the
entries of deck_used.prm. Every reader returns None when its file is missing, so callers
can skip a picture instead of failing."""
import csv
import json
import os
import re

import numpy as np

PARTICLE_FILE = re.compile(r"^particles_(\d+)\.h5$")


def summary_value(summary, *keys):
    """summary[k1][k2]...; None when any key is missing."""
    node = summary
    for key in keys:
        if not isinstance(node, dict) or key not in node:
            return None
        node = node[key]
    return node


def read_deck(path):
    """Entries of a deal.II ParameterHandler deck as {'Section/Sub/Entry': 'value'}."""
    entries, sections = {}, []
    with open(path, encoding="utf-8") as deck:
        for raw in deck:
            line = raw.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                sections.append(line[len("subsection "):].strip())
            elif line == "end":
                if sections:
                    sections.pop()
            elif line.startswith("set ") and "=" in line:
                key, value = line[4:].split("=", 1)
                entries["/".join(sections + [key.strip()])] = value.strip()
    return entries


class RunDirectory:
    """The files of a run directory written by `vulnus run`."""

    def __init__(self, path):
        self.path = path

    def file(self, name):
        return os.path.join(self.path, name)

    def has(self, name):
        return os.path.isfile(self.file(name))

    def summary(self):
        if not self.has("summary.json"):
            return None
        with open(self.file("summary.json"), encoding="utf-8") as f:
            return json.load(f)

    def history(self):
        """history.csv as {column: numpy array}, or None."""
        if not self.has("history.csv"):
            return None
        with open(self.file("history.csv"), encoding="utf-8", newline="") as f:
            rows = list(csv.reader(f))
        if len(rows) < 2:
            return None
        header, values = rows[0], np.array(rows[1:], dtype=float)
        return {name: values[:, c] for c, name in enumerate(header)}

    def deck(self):
        return read_deck(self.file("deck_used.prm")) if self.has("deck_used.prm") else {}

    def particle_files(self):
        """particles_NNNNN.h5 in output order."""
        if not os.path.isdir(self.path):
            return []
        numbered = [(int(m.group(1)), name) for name in os.listdir(self.path)
                    for m in [PARTICLE_FILE.match(name)] if m]
        return [self.file(name) for _, name in sorted(numbered)]


def load_particles(path, fields=("positions", "reference_position", "failure", "material_id")):
    """The named datasets of one particle file (those present) and its time (or None)."""
    import h5py  # only the particle pictures need it

    data = {}
    with h5py.File(path, "r") as f:
        for name in fields:
            if name in f:
                data[name] = f[name][()]
        data["time"] = float(f.attrs["time"]) if "time" in f.attrs else None
    return data


def first_and_last_by_id(run, fields):
    """The named datasets of the run's first and last particle outputs, each ordered by point
    id (so a point's row can be found in the other by id), without their times; None when the
    run has fewer than two outputs."""
    files = run.particle_files()
    if len(files) < 2:
        return None
    outputs = []
    for path in (files[0], files[-1]):
        data = load_particles(path, fields)
        order = np.argsort(data["id"])
        outputs.append({name: values[order] for name, values in data.items() if name != "time"})
    return outputs


def cell_size(deck, default=1e-3):
    """Grid/Cell size of the deck (m); `default` when absent."""
    try:
        return float(deck["Grid/Cell size"])
    except (KeyError, ValueError):
        return default


def body_names(deck):
    """Scene/Bodies in order (a body's index is its material_id)."""
    return [b.strip() for b in deck.get("Scene/Bodies", "").split(",") if b.strip()]


def is_projectile(deck, body):
    return deck.get("Body %s/Projectile" % body, "false").lower() == "true"


def projectile_body(deck):
    """Name of the deck's first projectile body, or None."""
    return next((body for body in body_names(deck) if is_projectile(deck, body)), None)


def target_body_index(deck):
    """Index (material_id) of the tissue body: the body named 'slab', else the first body
    that is not a projectile, else 0."""
    bodies = body_names(deck)
    if "slab" in bodies:
        return bodies.index("slab")
    for index, body in enumerate(bodies):
        if not is_projectile(deck, body):
            return index
    return 0


def deck_vector(deck, entry, default="0, 0, 0"):
    """A deck entry of comma-separated numbers as a numpy array."""
    return np.array([float(x) for x in deck.get(entry, default).replace(",", " ").split()])
