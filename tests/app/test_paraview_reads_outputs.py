"""ParaView's own readers open a short run's particle output right (run by pvbatch under
xvfb-run): every time step has as many cells as points, as many steps as files written, and
the stress tensor at the most stressed point equals the HDF5 values in XDMF's Tensor6 order.

Usage: pvbatch test_paraview_reads_outputs.py VULNUS SOURCE_DIR SCRATCH_DIR
"""
import glob
import os
import shutil
import subprocess
import sys

from paraview import servermanager
from paraview.simple import XDMFReader, Xdmf3ReaderS
import h5py
import numpy

vulnus, source, scratch = sys.argv[1:4]
shutil.rmtree(scratch, ignore_errors=True)
run = os.path.join(scratch, "run")
subprocess.run([vulnus, "run", os.path.join(source, "inputs/paper/anisotropic_150ms_coarse.prm"),
                "--output", run, "--threads", "1",
                "--set", "Material bullet/Model=rigid", "--set", "Time/End time=3e-5",
                "--set", "Output/Particle output interval=1e-5"],
               check=True, stdout=subprocess.DEVNULL)
files = sorted(glob.glob(os.path.join(run, "particles_*.h5")))
xdmf = os.path.join(run, "particles.xdmf")
failures = []

reader = Xdmf3ReaderS(FileName=[xdmf])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
if len(times) != len(files):
    failures.append("%d time steps for %d files" % (len(times), len(files)))
for t in times:
    reader.UpdatePipeline(t)
    data = servermanager.Fetch(reader)
    if data.GetNumberOfPoints() == 0 or data.GetNumberOfCells() != data.GetNumberOfPoints():
        failures.append("t = %g: %d points, %d cells" % (t, data.GetNumberOfPoints(),
                                                          data.GetNumberOfCells()))

with h5py.File(files[-1], "r") as f:
    stored = f["stress"][:]  # XX XY XZ YY YZ ZZ
point = int(numpy.argmax(numpy.abs(stored).sum(axis=1)))
xx, xy, xz, yy, yz, zz = stored[point]
expected = [xx, xy, xz, xy, yy, yz, xz, yz, zz]  # the full tensor, row by row
legacy = XDMFReader(FileNames=[xdmf])
legacy.UpdatePipeline(times[-1])
data = servermanager.Fetch(legacy)
if data.IsA("vtkCompositeDataSet"):  # the legacy reader may wrap the grid in blocks
    leaves = data.NewIterator()
    leaves.InitTraversal()
    while not leaves.IsDoneWithTraversal() and \
            leaves.GetCurrentDataObject().GetPointData().GetArray("stress") is None:
        leaves.GoToNextItem()
    data = leaves.GetCurrentDataObject()
tensor = data.GetPointData().GetArray("stress") if data is not None else None
if tensor is None:
    print("FAILED: the legacy XDMF reader gives no stress array")
    sys.exit(1)
got = [tensor.GetComponent(point, c) for c in range(tensor.GetNumberOfComponents())]
scale = max(abs(v) for v in expected)
if scale == 0 or len(got) != 9 or max(abs(a - b) for a, b in zip(got, expected)) > 1e-12 * scale:
    failures.append("stress at point %d: reader %s, file %s" % (point, got, expected))

for line in failures:
    print("FAILED: " + line)
print("%d time steps, %d points; stress at point %d read back" % (len(times),
                                                                   data.GetNumberOfPoints(), point))
sys.exit(1 if failures else 0)
