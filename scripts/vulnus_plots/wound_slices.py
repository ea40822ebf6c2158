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
