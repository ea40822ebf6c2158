"""A continuum estimate of a tract's totally failed cross-section: the quasi-static,
incompressible, plane-strain expansion of a cavity from a line to the bullet's radius R,
checked against the two-surface failure criterion (matrix shear, fibre stretch).

A point at reference radius r0 moves out to r = sqrt(r0^2 + R^2) along its ray; its in-plane
principal stretches are s = r / r0 around the cavity (hoop) and 1 / s along the ray (radial),
and 1 along the path. A fibre in the cross-section at angle theta from the ray stretches to
lambda^2 = cos^2(theta) / s^2 + sin^2(theta) s^2: fibres that point at the path are compressed
and never fail however close to it they start, so the totally failed cross-section is pinched
along the fibres. Dynamics, the nose and the faces are left out: this is a reference for the
shape a fine grid should approach mid-depth, not a prediction of the wound.
"""
import math

import numpy as np

SHEAR_MEASURES = ("E1-E3", "(E1-E3)/2", "ln(l1/l3)")


def hoop_stretch_squared(r0, radius):
    """s^2 = 1 + R^2 / r0^2 at reference radius r0 (> 0)."""
    return 1.0 + (radius / r0) ** 2


def matrix_shear(s2, measure="E1-E3"):
    """The matrix shear measure of the in-plane stretches s and 1/s (eigenvalues s^2, 1, s^-2 of
    C), as materials/two_surface_failure.h defines it."""
    if measure == "E1-E3":
        return 0.5 * (s2 - 1.0 / s2)
    if measure == "(E1-E3)/2":
        return 0.25 * (s2 - 1.0 / s2)
    if measure == "ln(l1/l3)":
        return 0.5 * np.log(s2 * s2)
    raise ValueError("cavity_expansion: unknown shear measure %r (expected one of %s)"
                     % (measure, ", ".join(SHEAR_MEASURES)))


def totally_failed(across, along, radius, fibre_limit, shear_limit, measure="E1-E3"):
    """Whether the reference points (across, along) of the cross-section, the fibre along the
    second coordinate and the path at the origin, end with matrix and fibres failed. With
    fibre_limit None (no fibres) the matrix alone decides."""
    across = np.asarray(across, float)
    along = np.asarray(along, float)
    r0 = np.maximum(np.hypot(across, along), 1e-12 * radius)
    s2 = hoop_stretch_squared(r0, radius)
    failed = matrix_shear(s2, measure) > shear_limit
    if fibre_limit is not None:
        radial_share = (along / r0) ** 2
        fibre_stretch_squared = radial_share / s2 + (1.0 - radial_share) * s2
        failed &= fibre_stretch_squared > fibre_limit ** 2
    return failed


def section_figures(radius, fibre_limit, shear_limit, measure="E1-E3", samples=2001):
    """Area, equivalent diameter, and length along / width across the fibres (4 sqrt of the
    second moment, as benchmarks/convergence/wound_profile measures them) of the totally failed
    cross-section, by sampling a square of side 3 R (every failure lies within r0 < 1.5 R for
    the limits of a tissue: the matrix's fails out to r0 = R / sqrt(s_c^2 - 1), s_c its limit)."""
    side = 1.5 * radius
    reach = radius / math.sqrt(critical_hoop_stretch_squared(shear_limit, measure) - 1.0)
    if reach > side:
        side = 1.05 * reach
    grid = np.linspace(-side, side, samples)
    across, along = np.meshgrid(grid, grid)
    failed = totally_failed(across, along, radius, fibre_limit, shear_limit, measure)
    cell_area = (grid[1] - grid[0]) ** 2
    area = failed.sum() * cell_area
    if not failed.any():
        return {"area": 0.0, "diameter": 0.0, "along": 0.0, "across": 0.0, "aspect": math.nan,
                "failed": failed, "grid": grid}
    length_along = 4.0 * math.sqrt(np.mean(along[failed] ** 2))
    width_across = 4.0 * math.sqrt(np.mean(across[failed] ** 2))
    return {"area": area, "diameter": math.sqrt(4.0 * area / math.pi), "along": length_along,
            "across": width_across, "aspect": length_along / width_across, "failed": failed,
            "grid": grid}


def critical_hoop_stretch_squared(shear_limit, measure="E1-E3"):
    """The s^2 at which the matrix measure reaches its limit (it grows with s^2 > 1)."""
    if measure == "E1-E3":
        k = 2.0 * shear_limit
    elif measure == "(E1-E3)/2":
        k = 4.0 * shear_limit
    elif measure == "ln(l1/l3)":
        return math.exp(shear_limit)
    else:
        raise ValueError("cavity_expansion: unknown shear measure %r" % measure)
    # s2 - 1/s2 = k
    return 0.5 * (k + math.sqrt(k * k + 4.0))
