#!/usr/bin/python3
"""scripts/vulnus_plots/paper_claims.py on synthetic wounds with known answers: layered
failure zones, tract growth, circular and elliptic wounds, missing data."""
import os
import sys
import types
import unittest

import numpy as np

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "scripts"))
from vulnus_plots import paper_claims  # noqa: E402


def ring_wound(bands):
    """Points on rings around the axis (x, z) = (1, 2) mm: bands = [(flag, radius_m, n)]."""
    reference, flags = [], []
    for flag, radius, n in bands:
        angle = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
        for a in angle:
            reference.append([1e-3 + radius * np.cos(a), 0.0, 2e-3 + radius * np.sin(a)])
            flags.append(flag)
    return types.SimpleNamespace(reference=np.array(reference), flags=np.array(flags),
                                 centre=np.array([1e-3, 2e-3]))


def summary(entrance, exit_ratio, area):
    return {"entrance_wound": {"aspect_ratio": entrance},
            "exit_wound": {"aspect_ratio": exit_ratio}, "tract": {"area_m2": area}}


class FailureZones(unittest.TestCase):
    def test_rings_give_their_radii_and_counts(self):
        zones = paper_claims.failure_zones(ring_wound([(3, 2e-3, 40), (1, 4e-3, 30),
                                                       (2, 6e-3, 20), (0, 9e-3, 10)]))
        self.assertEqual(zones["total"]["count"], 40)
        self.assertEqual(zones["matrix"]["count"], 30)
        self.assertEqual(zones["fiber"]["count"], 20)
        self.assertAlmostEqual(zones["total"]["median_radius_m"], 2e-3, delta=1e-12)
        self.assertAlmostEqual(zones["fiber"]["median_radius_m"], 6e-3, delta=1e-12)
        self.assertTrue(paper_claims.layered(zones))

    def test_total_outside_matrix_is_not_layered(self):
        zones = paper_claims.failure_zones(ring_wound([(3, 5e-3, 40), (1, 3e-3, 30),
                                                       (2, 6e-3, 20)]))
        self.assertFalse(paper_claims.layered(zones))

    def test_no_fiber_failure_is_layered_only_without_fibers(self):
        zones = paper_claims.failure_zones(ring_wound([(3, 2e-3, 40), (1, 4e-3, 30)]))
        self.assertIsNone(zones["fiber"]["median_radius_m"])
        self.assertFalse(paper_claims.layered(zones, anisotropic=True))
        self.assertTrue(paper_claims.layered(zones, anisotropic=False))


class Claims(unittest.TestCase):
    def test_tract_growth_is_the_ratio_of_the_outer_thirds(self):
        self.assertAlmostEqual(paper_claims.tract_growth(summary(1, 1, [1, 1, 2, 2, 3, 3])), 3.0)
        self.assertIsNone(paper_claims.tract_growth(summary(1, 1, [1, 2])))

    def test_verdicts_follow_the_thresholds(self):
        layered = paper_claims.failure_zones(ring_wound([(3, 2e-3, 8), (1, 4e-3, 8),
                                                         (2, 6e-3, 8)]))
        rows = paper_claims.evaluate({
            "anisotropic_50ms": (summary(1.1, 1.6, [1, 1, 1, 2, 2, 2]), layered),
            "isotropic_50ms": (summary(1.3, 1.1, [2, 2, 1, 1]), layered)})
        verdict = {(claim.split(" (")[0], run): holds for claim, run, _, holds in rows}
        self.assertTrue(verdict[("entrance wound circular", "anisotropic_50ms")])
        self.assertFalse(verdict[("entrance wound circular", "isotropic_50ms")])
        self.assertTrue(verdict[("exit wound elliptic for the anisotropic slab",
                                 "anisotropic_50ms")])
        self.assertTrue(verdict[("exit wound circular for the isotropic slab", "isotropic_50ms")])
        self.assertTrue(verdict[("tract diameter grows from entrance to exit", "anisotropic_50ms")])
        self.assertFalse(verdict[("tract diameter grows from entrance to exit", "isotropic_50ms")])
        self.assertIn("| **no** |", paper_claims.markdown_table(rows))

    def test_missing_figures_give_no_verdict(self):
        zones = paper_claims.failure_zones(ring_wound([(3, 2e-3, 8)]))
        rows = paper_claims.evaluate({"anisotropic_150ms": ({}, zones)})
        self.assertIn(None, [holds for _, _, _, holds in rows])
        self.assertIn("| no data |", paper_claims.markdown_table(rows))


if __name__ == "__main__":
    unittest.main()
