"""Reading what benchmarks/uintah/side_by_side needs from a Uintah data archive (uda):
per-point values of one particle variable at the last saved time, and a reduction
variable's time series (the <label>.dat files written every step)."""
import glob
import os
import re
import struct
import xml.etree.ElementTree as ElementTree


def last_timestep_directory(uda):
    steps = sorted(glob.glob(os.path.join(uda, "t[0-9]*")), key=lambda d: int(os.path.basename(d)[1:]))
    if not steps:
        raise RuntimeError("%s holds no saved time step" % uda)
    return steps[-1]


def final_particle_values(uda, variable, material):
    """Every point's value of a scalar (double) particle variable of `material`, at the last
    saved time, over all patches."""
    level = os.path.join(last_timestep_directory(uda), "l0")
    values = []
    for index_file in sorted(glob.glob(os.path.join(level, "p*.xml"))):
        for entry in ElementTree.parse(index_file).getroot().iter("Variable"):
            if entry.findtext("variable") != variable or int(entry.findtext("index")) != material:
                continue
            start, end = int(entry.findtext("start")), int(entry.findtext("end"))
            count = int(entry.findtext("numParticles") or (end - start) // 8)
            with open(os.path.join(level, entry.findtext("filename")), "rb") as f:
                f.seek(start)
                data = f.read(end - start)
            if len(data) != 8 * count:
                raise RuntimeError("%s: %s of patch %s has %d bytes for %d points (compressed "
                                   "output is not read)" % (index_file, variable,
                                                            entry.findtext("patch"), len(data), count))
            values.extend(struct.unpack("<%dd" % count, data))
    if not values:
        raise RuntimeError("%s: no %s of material %d in %s" % (uda, variable, material, level))
    return values


def reduction_series(uda, file_name):
    """[(time, [components])] of a reduction variable's .dat file (a scalar has one)."""
    series = []
    with open(os.path.join(uda, file_name), encoding="utf-8") as f:
        for line in f:
            numbers = [float(x) for x in re.findall(r"[-+0-9.eE]+", line)]
            if len(numbers) >= 2:
                series.append((numbers[0], numbers[1:]))
    return series
