"""A finished run's totally failed points in reference positions, and slices of them along the
path: what benchmarks/convergence/wound_profile and wound_section measure a wound's depth
profile and cross-sections from."""
import numpy as np

from . import run_data

AXES = {"x": 0, "y": 1, "z": 2}
FIELDS = ("id", "reference_position", "fiber_direction", "failure", "material_id")


class FailedPoints:
    """The target's points present at the run's last output: reference positions, whether
    they failed totally, their reference fibres (None when isotropic), the run's summary and
    deck, and the path's slicing (depth from the entrance face along its axis)."""

    def __init__(self, path, tool):
        run = run_data.RunDirectory(path)
        outputs, summary = run_data.first_and_last_by_id(run, FIELDS), run.summary()
        if outputs is None or not summary:
            raise SystemExit("%s: %s has no summary.json or fewer than two particle outputs"
                             % (tool, path))
        entrance = summary.get("entrance_wound")
        if not entrance:
            raise SystemExit("%s: %s has no entrance wound in summary.json" % (tool, path))
        first, last = outputs
        self.deck = run.deck()
        self.summary = summary
        target = run_data.target_body_index(self.deck)
        kept = np.isin(first["id"], last["id"]) & (first["material_id"] == target)
        self.failed = last["failure"][np.isin(last["id"], first["id"][kept])] == 3
        self.reference = first["reference_position"][kept]
        fibres = first.get("fiber_direction")
        if fibres is not None:
            fibres = fibres[kept]
            if not np.any(np.linalg.norm(fibres, axis=1) > 0.5):
                fibres = None
        self.fibres = fibres
        self.axis = AXES[entrance["face"][0]]
        self.plane = [a for a in range(3) if a != self.axis]
        lattice = np.unique(np.round(self.reference[:, self.axis], 10))
        self.spacing = float(np.min(np.diff(lattice)))
        face = self.reference[:, self.axis].min() - 0.5 * self.spacing
        direction = 1.0
        if entrance["face"][1] == "+":
            face = self.reference[:, self.axis].max() + 0.5 * self.spacing
            direction = -1.0
        self.depth = direction * (self.reference[:, self.axis] - face)
        self.total_depth = (lattice.max() - lattice.min()) + self.spacing

    def slice_thickness(self, thickness):
        """The thickness of whole rows of points nearest to `thickness` (m)."""
        return max(1, round(thickness / self.spacing)) * self.spacing

    def in_slice(self, low, high):
        return (self.depth >= low) & (self.depth < high)

    def slice_fibre(self, in_slice):
        """The slice's mean fibre direction in the slice plane (unit 2-vector), or None."""
        if self.fibres is None or not in_slice.any():
            return None
        a = self.fibres[in_slice][:, self.plane]
        values, vectors = np.linalg.eigh(a.T @ a)
        if values[-1] <= 0.0:
            return None
        return vectors[:, -1]

    def fibre_frame(self, in_slice, fallback=None):
        """The slice's points along and across its fibre (m), about the centroid of its failed
        points; `fallback` (a unit 2-vector) stands for the fibre of an isotropic run, else
        None is returned for one."""
        fibre = self.slice_fibre(in_slice)
        if fibre is None:
            fibre = fallback
        if fibre is None:
            return None
        r = self.reference[in_slice][:, self.plane]
        r = r - r[self.failed[in_slice]].mean(axis=0)
        return r @ fibre, r @ np.array([-fibre[1], fibre[0]])

    def section_figures(self, in_slice, thickness, fallback_fibre=None):
        """The failed cross-section of a slice `thickness` thick: equivalent diameter (m), and
        length along and width across the fibre (4 sqrt of the second moment, a uniform
        ellipse's axes) and their ratio, NaN under 3 failed points or without a fibre; and
        the slice's fibre frame (fibre_frame) or None."""
        failed = self.failed[in_slice]
        n = int(failed.sum())
        area = n * self.spacing ** 3 / thickness
        figures = {"diameter": np.sqrt(4.0 * area / np.pi) if n else 0.0,
                   "along": float("nan"), "across": float("nan"), "aspect": float("nan")}
        frame = self.fibre_frame(in_slice, fallback_fibre) if n >= 3 else None
        if frame is not None:
            along, across = frame
            figures["along"] = 4.0 * np.sqrt(np.mean(along[failed] ** 2))
            figures["across"] = 4.0 * np.sqrt(np.mean(across[failed] ** 2))
            if figures["across"] > 0.0:
                figures["aspect"] = figures["along"] / figures["across"]
        return figures, frame
