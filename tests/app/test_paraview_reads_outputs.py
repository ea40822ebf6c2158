"""ParaView's own readers open a short run's outputs right (run by pvbatch under xvfb-run).
Particles of a pure run: every time step has as many cells as points, as many steps as files
written, and the stress tensor at the most stressed point equals the HDF5 values in XDMF's
Tensor6 order. FE mesh of a short hybrid run: every step has its hexahedra, no node is
duplicated, the mesh's times are the particles' times, and a cell's stress tensor and failure
flag (an integer) read back as written.

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

print("particles: %d time steps, %d points; stress at point %d read back"
      % (len(times), data.GetNumberOfPoints(), point))

hybrid = os.path.join(scratch, "hybrid")
subprocess.run([vulnus, "run",
                os.path.join(source, "inputs/paper/anisotropic_150ms_coarse_hybrid.prm"),
                "--output", hybrid, "--threads", "1",
                "--set", "Material bullet/Model=rigid", "--set", "Time/End time=4e-5",
                "--set", "Output/Particle output interval=2e-5",
                # a stiff tissue, so that its waves load the far field within the run
                "--set", "Material tissue/Transversely isotropic hyperelastic/Bulk modulus=1e8"],
               check=True, stdout=subprocess.DEVNULL)
mesh_files = sorted(glob.glob(os.path.join(hybrid, "fe_mesh_*.h5")))
mesh = Xdmf3ReaderS(FileName=[os.path.join(hybrid, "fe_mesh.xdmf")])
mesh.UpdatePipelineInformation()
mesh_times = list(mesh.TimestepValues)
particles = Xdmf3ReaderS(FileName=[os.path.join(hybrid, "particles.xdmf")])
particles.UpdatePipelineInformation()
if mesh_times != list(particles.TimestepValues):
    failures.append("FE mesh times %s, particle times %s" % (mesh_times,
                                                            list(particles.TimestepValues)))
if len(mesh_times) != len(mesh_files):
    failures.append("FE mesh: %d time steps for %d files" % (len(mesh_times), len(mesh_files)))
for t in mesh_times:
    mesh.UpdatePipeline(t)
    grid = servermanager.Fetch(mesh)
    if grid.GetNumberOfCells() == 0 or grid.GetNumberOfPoints() == 0:
        failures.append("FE mesh at t = %g: %d points, %d cells" % (t, grid.GetNumberOfPoints(),
                                                                    grid.GetNumberOfCells()))
with h5py.File(mesh_files[-1], "r") as f:
    positions = f["positions"][:]
    cell_stress = f["stress"][:]
    cell_failure = f["failure"][:]
unique = numpy.unique(numpy.round(positions / 1e-9).astype(numpy.int64), axis=0)
if len(unique) != len(positions):
    failures.append("FE mesh: %d nodes, %d distinct" % (len(positions), len(unique)))
mesh.UpdatePipeline(mesh_times[-1])
grid = servermanager.Fetch(mesh)
cell = int(numpy.argmax(numpy.abs(cell_stress).sum(axis=1)))
xx, xy, xz, yy, yz, zz = cell_stress[cell]
# The Xdmf3 readers keep Tensor6's 6 components, the legacy reader expands them to 9.
expected = [xx, xy, xz, yy, yz, zz]
array = grid.GetCellData().GetArray("stress")
got = [array.GetComponent(cell, c) for c in range(array.GetNumberOfComponents())] if array else []
scale = max(abs(v) for v in expected)
if scale == 0 or len(got) != 6 or max(abs(a - b) for a, b in zip(got, expected)) > 1e-12 * scale:
    failures.append("FE stress at cell %d: reader %s, file %s" % (cell, got, expected))
flag = grid.GetCellData().GetArray("failure")
if flag is None or flag.GetDataTypeAsString() not in ("int", "long", "long long") or \
        flag.GetNumberOfTuples() != len(cell_failure):
    failures.append("FE failure flag: %s" % (flag.GetDataTypeAsString() if flag else "missing"))
print("FE mesh: %d time steps, %d nodes, %d cells; stress at cell %d read back"
      % (len(mesh_times), grid.GetNumberOfPoints(), grid.GetNumberOfCells(), cell))

for line in failures:
    print("FAILED: " + line)
sys.exit(1 if failures else 0)
