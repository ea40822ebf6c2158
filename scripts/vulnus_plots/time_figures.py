"""Line plots of a run: the tract cross-section, the projectile's velocity and the temporary
cavity against depth (summary.json), and the energies, bullet velocity and failed counts
against time (history.csv)."""
import numpy as np

from . import style

ENERGY_COLUMNS = [("kinetic_J", "kinetic"), ("strain_J", "strain"), ("potential_J", "potential"),
                  ("dissipated_material_J", "dissipated, material"),
                  ("dissipated_contact_J", "dissipated, contact"),
                  ("dissipated_supports_J", "dissipated, supports"), ("outflow_J", "outflow")]
FAILED_COLUMNS = [("failed_matrix", 1), ("failed_fiber", 2), ("failed_total", 3)]


def plot_tract(summary, path):
    """Total-failure area (and the debris area, where the summary has it) and the total's
    equivalent diameter against depth below the entrance.
    Returns False (and says why) when summary.json has no tract."""
    tract = (summary or {}).get("tract") or {}
    depth, area = np.asarray(tract.get("depth_m", []), float), np.asarray(tract.get("area_m2", []), float)
    if depth.size == 0 or depth.size != area.size:
        print("skipped %s: summary.json has no tract depth/area lists" % path)
        return False
    fig, axes = style.figure(1, 1, width=6.0, height=4.0)
    axis = axes[0][0]
    axis.plot(1e3 * depth, 1e6 * area, "o-", color=style.FLAG_COLOURS[3], label="total failure")
    debris = np.asarray(tract.get("debris_area_m2", []), float)
    if debris.size == depth.size:
        axis.plot(1e3 * depth, 1e6 * debris, "^:", color="0.4", label="debris (no deviatoric stress)")
        axis.legend(loc="lower right", fontsize=8)
    axis.set_xlabel("depth below the entrance face [mm]")
    axis.set_ylabel("failed area [mm$^2$]", color=style.FLAG_COLOURS[3])
    axis.set_ylim(bottom=0)
    twin = axis.twinx()
    twin.plot(1e3 * depth, 1e3 * np.sqrt(4 * area / np.pi), "s--", color="k", ms=3)
    twin.set_ylabel("equivalent diameter [mm]")
    twin.set_ylim(bottom=0)
    axis.set_title("Wound tract cross-section")
    axis.grid(alpha=0.3)
    style.save(fig, path)
    return True


def plot_penetration(summary, path):
    """The projectile's velocity against its nose's depth (summary.json's penetration.curve)
    and the temporary cavity's largest diameter against depth, with when it peaked. Returns
    False (and says why) when summary.json has neither."""
    penetration = (summary or {}).get("penetration") or {}
    curve = penetration.get("curve") or {}
    cavity = (summary or {}).get("temporary_cavity") or {}
    depth, speed = np.asarray(curve.get("depth_m", []), float), np.asarray(curve.get("velocity_m_s", []), float)
    slices = np.asarray(cavity.get("depth_m", []), float)
    if depth.size == 0 and slices.size == 0:
        print("skipped %s: summary.json has no penetration curve or temporary cavity" % path)
        return False
    fig, axes = style.figure(1, 2, width=6.0, height=4.0)
    axis = axes[0][0]
    axis.plot(1e3 * depth, speed, "-", color=style.BULLET_COLOUR)
    if penetration.get("stopped"):
        axis.axvline(1e3 * penetration["stop_depth_m"], color="k", ls=":",
                     label="stopped at %.1f mm" % (1e3 * penetration["stop_depth_m"]))
        axis.legend(loc="upper right")
    axis.axvline(0.0, color="0.6", lw=0.8)
    axis.set_xlabel("front's depth past the entrance point, along the path [mm]")
    axis.set_ylabel("velocity along the flight [m/s]")
    axis.set_title("Projectile velocity against depth")
    axis.grid(alpha=0.3)
    axis = axes[0][1]
    if slices.size:
        largest = np.asarray(cavity["max_diameter_m"], float)
        when = np.asarray(cavity["max_time_s"], float)
        axis.plot(1e3 * slices, 1e3 * largest, "o-", ms=3, color=style.FLAG_COLOURS[1],
                  label="largest")
        axis.plot(1e3 * slices, 1e3 * np.asarray(cavity["diameter_now_m"], float), "-",
                  color="0.5", label="at the end")
        axis.set_ylabel("cavity diameter [mm]")
        axis.set_ylim(bottom=0)
        floor = float(cavity.get("resolution_floor_m", 0.0))
        axis.axhline(1e3 * floor, color="0.6", lw=0.8, ls=":", label="resolution floor")
        axis.legend(loc="lower left", framealpha=0.9)
        # A time only where the cavity opened well beyond what undisturbed material measures:
        # near the floor the largest diameter is the material's jitter and its time meaningless.
        opened = largest > 1.5 * floor
        twin = axis.twinx()
        twin.plot(1e3 * slices[opened], 1e6 * when[opened], "s", ms=2, color="k")
        twin.set_ylabel("time of the largest [us]")
        twin.set_ylim(bottom=0)
    axis.set_xlabel("depth past the entrance point, along the path [mm]")
    axis.set_title("Temporary cavity")
    axis.grid(alpha=0.3)
    style.save(fig, path)
    return True


def plot_history(history, path):
    """Energies, bullet velocity and failed counts against time. Returns False (and says
    why) when history.csv is missing or has no time column."""
    if not history or "time_s" not in history:
        print("skipped %s: no history.csv with a time_s column" % path)
        return False
    t = 1e3 * history["time_s"]
    fig, axes = style.figure(3, 1, width=7.0, height=3.0, sharex=True)
    energy, velocity, failed = axes[0][0], axes[1][0], axes[2][0]
    for column, label in ENERGY_COLUMNS:
        if column in history:
            energy.plot(t, history[column], label=label)
    parts = [history[c] for c, _ in ENERGY_COLUMNS if c in history]
    if parts:
        energy.plot(t, np.sum(parts, axis=0), "k--", lw=1, label="sum (stays at the initial energy)")
    energy.set_ylabel("energy [J]")
    energy.legend(fontsize=7, ncol=2)
    components = [c for c in ("bullet_velocity_x", "bullet_velocity_y", "bullet_velocity_z")
                  if c in history]
    for column in components:
        velocity.plot(t, history[column], label=column.replace("bullet_velocity_", "v_"))
    if len(components) == 3:
        speed = np.sqrt(sum(history[c] ** 2 for c in components))
        velocity.plot(t, speed, "k--", lw=1, label="|v|")
    velocity.set_ylabel("bullet velocity [m/s]")
    if components:
        velocity.legend(fontsize=7)
    for column, flag in FAILED_COLUMNS:
        if column in history:
            failed.plot(t, history[column], color=style.FLAG_COLOURS[flag],
                        label=style.FLAG_LABELS[flag])
    failed.set_ylabel("failed points")
    failed.set_xlabel("time [ms]")
    failed.legend(fontsize=7)
    for axis in (energy, velocity, failed):
        axis.grid(alpha=0.3)
    energy.set_title("Energy budget and bullet")
    style.save(fig, path)
    return True
