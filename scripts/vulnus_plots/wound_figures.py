"""Pictures of the wound from one particle file, like the paper's figures 2 and 3:
cuts through the tract (reference and current positions), a 3-D view of the failed
points, and the entrance and exit faces seen from outside. Flight axis +y."""
import math

import numpy as np
from matplotlib.patches import Ellipse

from . import style


class Wound:
    """The target's points of one particle file, and the geometry the pictures need."""

    def __init__(self, particles, target_index, cell):
        flags = np.asarray(particles["failure"]).astype(int)
        material = particles.get("material_id")
        target = np.ones(flags.shape, bool) if material is None else material == target_index
        self.cell = cell
        self.time = particles.get("time")
        self.flags = flags[target]
        self.reference = np.asarray(particles["reference_position"])[target]
        current = particles.get("positions")
        self.current = None if current is None else np.asarray(current)[target]
        self.other = None if current is None or material is None else np.asarray(current)[~target]
        # Faces: half a point spacing outside the outermost points.
        y = np.unique(np.round(self.reference[:, 1], 9))
        half = 0.5 * (np.diff(y).min() if len(y) > 1 else cell)
        self.entrance, self.exit = y[0] - half, y[-1] + half
        total = self.reference[self.flags == 3]
        failed = total if len(total) else self.reference[self.flags > 0]
        if len(failed):
            self.centre = failed[:, [0, 2]].mean(axis=0)
        else:
            self.centre = 0.5 * (self.reference[:, [0, 2]].min(axis=0)
                                 + self.reference[:, [0, 2]].max(axis=0))
        lateral = np.abs(self.reference[self.flags > 0][:, [0, 2]] - self.centre)
        reach = lateral.max() if lateral.size else 0.0
        self.half_width = max(10e-3, reach + 4 * cell)

    def title(self, what):
        return what if self.time is None else "%s, t = %.4g ms" % (what, 1e3 * self.time)


def _mm(values):
    return 1e3 * np.asarray(values)


def _cut_panel(axis, wound, positions, lateral, others, label):
    """Points within one cell of the plane through the tract normal to `lateral` (0 x, 2 z);
    flight axis y horizontal, the other lateral axis vertical."""
    vertical = 2 if lateral == 0 else 0
    centre = {0: wound.centre[0], 2: wound.centre[1]}
    cut = np.abs(wound.reference[:, lateral] - centre[lateral]) < wound.cell
    style.scatter_flags(axis, _mm(positions[cut, 1]), _mm(positions[cut, vertical]),
                        wound.flags[cut], size=3.0)
    if others is not None:
        near = np.abs(others[:, lateral] - centre[lateral]) < wound.cell
        if near.any():
            axis.scatter(_mm(others[near, 1]), _mm(others[near, vertical]), s=3.0, linewidths=0,
                         c=style.BULLET_COLOUR, label="bullet", rasterized=True)
    names = "xyz"
    axis.set_xlabel("y (flight) [mm]")
    axis.set_ylabel("%s [mm]" % names[vertical])
    offset = 1e3 * centre[lateral]
    plane = names[lateral] if abs(offset) < 0.05 else "%s - %.1f mm" % (names[lateral], offset)
    axis.set_title("%s, |%s| < one cell" % (label, plane))
    axis.set_ylim(_mm(centre[vertical] - wound.half_width), _mm(centre[vertical] + wound.half_width))
    axis.set_aspect("equal", adjustable="datalim")
    for face in (wound.entrance, wound.exit):
        axis.axvline(_mm(face), color="k", lw=0.5, ls=":")


def plot_tract_cuts(wound, path):
    """Figure 2 (cuts): rows reference / current positions, columns y-z and x-y planes."""
    rows = [("reference positions", wound.reference, None)]
    if wound.current is not None:
        rows.append(("current positions", wound.current, wound.other))
    fig, axes = style.figure(len(rows), 2, width=6.0, height=5.0)
    for r, (label, positions, others) in enumerate(rows):
        for c, lateral in enumerate((0, 2)):
            _cut_panel(axes[r][c], wound, positions, lateral, others, label)
    axes[0][0].legend(loc="upper right", fontsize=7, markerscale=3)
    axes[-1][0].legend(loc="upper right", fontsize=7, markerscale=3)
    fig.suptitle(wound.title("Wound tract: cuts through the bullet path (top: material map, "
                             "bottom: deformed)"))
    style.save(fig, path)


def plot_wound_3d(wound, path, max_points=150000):
    """Figure 2 (3-D): failed points of the half x >= tract centre, reference positions."""
    chosen = (wound.flags > 0) & (wound.reference[:, 0] >= wound.centre[0])
    if not chosen.any():
        print("skipped %s: no failed points" % path)
        return
    index = np.flatnonzero(chosen)
    if len(index) > max_points:
        index = np.random.default_rng(0).choice(index, max_points, replace=False)
    fig = style.plt.figure(figsize=(7, 6))
    axis = fig.add_subplot(projection="3d")
    for flag in (1, 2, 3):
        pick = index[wound.flags[index] == flag]
        if len(pick):
            x = _mm(wound.reference[pick])
            axis.scatter(x[:, 0], x[:, 1], x[:, 2], s=1.5, c=style.FLAG_COLOURS[flag],
                         label="%s (%d)" % (style.FLAG_LABELS[flag], len(pick)), linewidths=0,
                         depthshade=False, rasterized=True)
    axis.set_xlabel("x [mm]")
    axis.set_ylabel("y (flight) [mm]")
    axis.set_zlabel("z [mm]")
    axis.view_init(elev=20, azim=-150)
    axis.legend(loc="upper left", fontsize=7, markerscale=4)
    axis.set_title(wound.title("Failed points, half slab x >= tract axis (material map)"))
    style.save(fig, path)


def _face_ellipse(axis, face_summary, centre):
    """The wound of summary.json drawn as the ellipse of its area and aspect ratio."""
    try:
        diameter = float(face_summary["equivalent_diameter_m"])
        ratio = max(float(face_summary.get("aspect_ratio", 1.0)), 1.0)
        major = face_summary.get("major_axis_direction", [1.0, 0.0, 0.0])
    except (KeyError, TypeError, ValueError):
        return
    if not diameter > 0:
        return
    angle = math.degrees(math.atan2(major[2], major[0]))
    axis.add_patch(Ellipse(_mm(centre), _mm(diameter * math.sqrt(ratio)),
                           _mm(diameter / math.sqrt(ratio)), angle=angle, fill=False,
                           ls="--", lw=1.0, ec="k",
                           label="summary: d = %.2f mm, aspect %.2f" % (1e3 * diameter, ratio)))


def plot_face(wound, name, path, face_summary=None):
    """Figure 3: the failed points within one cell of a face, seen from outside the slab
    (the exit face from +y, so x grows to the left; the entrance face from -y)."""
    if name == "exit":
        band = wound.reference[:, 1] > wound.exit - wound.cell
    else:
        band = wound.reference[:, 1] < wound.entrance + wound.cell
    panels = [("reference positions", wound.reference)]
    if wound.current is not None:
        panels.append(("current positions", wound.current))
    fig, axes = style.figure(1, len(panels), width=5.5, height=5.5)
    for c, (label, positions) in enumerate(panels):
        axis = axes[0][c]
        style.scatter_flags(axis, _mm(positions[band, 0]), _mm(positions[band, 2]),
                            wound.flags[band], size=4.0)
        if c == 0 and face_summary:
            total = wound.reference[band & (wound.flags == 3)]
            if len(total):
                _face_ellipse(axis, face_summary, total[:, [0, 2]].mean(axis=0))
        axis.set_xlim(_mm(wound.centre[0] - wound.half_width),
                      _mm(wound.centre[0] + wound.half_width))
        axis.set_ylim(_mm(wound.centre[1] - wound.half_width),
                      _mm(wound.centre[1] + wound.half_width))
        if name == "exit":
            axis.invert_xaxis()
        axis.set_aspect("equal")
        axis.set_xlabel("x [mm]")
        axis.set_ylabel("z [mm]")
        axis.set_title(label)
        axis.legend(loc="upper right", fontsize=7, markerscale=2)
    side = "+y" if name == "exit" else "-y"
    fig.suptitle(wound.title("%s face seen from outside (from %s), points within one cell"
                             % (name.capitalize(), side)))
    style.save(fig, path)
