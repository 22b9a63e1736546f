# ParaView itself opens limber's output, as a user would. Run by paraview_test.cpp:
#   pvpython paraview_check.py pvd SCENE.pvd POINTS TIME...
#       the PVD reader: the time steps, and the points of every part at the first one;
#   pvpython paraview_check.py xdmf|xdmf3 SCENE.xmf POINTS INDEX T X Y Z TIME...
#       the XDMF Reader (xdmf) or Xdmf3ReaderS (xdmf3) on scene.xmf: the time steps; at EVERY
#       step one grid of POINTS points, against the VTUs of the same sample listed in scene.pvd
#       beside it, one per body, one after the other (read with ParaView's VTU reader: a second
#       writer): the number of points and cells, the cell types, the point positions and the
#       point arrays displacement and displacement_magnitude to 1e-12 relative; at time T the
#       deformed position (points + displacement) of point INDEX is (X, Y, Z) [m], the closed
#       form results.h5 holds, to 1e-12 m.
# Exit status 0 when all match; otherwise a message (expected/got) and status 1.
import os
import sys

import numpy
from xml.etree import ElementTree

from paraview import servermanager
from paraview.simple import Delete, PVDReader, XDMFReader, Xdmf3ReaderS, XMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import VTK_LINE, VTK_POLY_LINE

kind, path = sys.argv[1], sys.argv[2]


def check_times(reader, times):
    # Time steps: written with 17 significant digits, so they read back exactly.
    steps = list(reader.TimestepValues)
    if len(steps) != len(times) or any(abs(a - b) > 1e-12 for a, b in zip(steps, times)):
        sys.exit(f"{path}: expected time steps {times}, got {steps}")
    return steps


def blocks(data):
    """The leaves of a multiblock data set, in order (a data set that is none: itself)."""
    if not data.IsA("vtkCompositeDataSet"):
        return [data]
    found = []
    iterator = data.NewIterator()
    iterator.InitTraversal()
    while not iterator.IsDoneWithTraversal():
        found.append(iterator.GetCurrentDataObject())
        iterator.GoToNextItem()
    return found


def relative_difference(a, b):
    scale = max(abs(b).max(), 1e-300) if b.size else 1.0
    return abs(a - b).max() / scale if a.size else 0.0


if kind == "pvd":
    points = int(sys.argv[3])
    times = [float(t) for t in sys.argv[4:]]
    reader = PVDReader(FileName=path)
    steps = check_times(reader, times)
    # Points of every part (body) at the first time step.
    reader.UpdatePipeline(steps[0])
    got = reader.GetDataInformation().GetNumberOfPoints()
    if got != points:
        sys.exit(f"{path}: expected {points} points at t = {steps[0]}, got {got}")
    print(f"{path}: {len(steps)} time steps, {got} points")
    sys.exit(0)

points = int(sys.argv[3])
index, point_time = int(sys.argv[4]), float(sys.argv[5])
point = [float(v) for v in sys.argv[6:9]]
times = [float(t) for t in sys.argv[9:]]
reader = XDMFReader(FileNames=[path]) if kind == "xdmf" else Xdmf3ReaderS(FileName=[path])
steps = check_times(reader, times)
directory = os.path.dirname(path)
# The VTUs of each time, in part order, from the PVD written beside the scene.
vtu_files = {}
for dataset in ElementTree.parse(os.path.join(directory, "scene.pvd")).getroot().iter("DataSet"):
    vtu_files.setdefault(float(dataset.get("timestep")), []).append((int(dataset.get("part")), dataset.get("file")))
# Tolerance 1e-12 relative: both writers store the same float64 products of the same
# results.h5 values (the VTU's pose applied by vtkTransform, the scene's by Eigen), which differ
# by a few ulps.
tolerance = 1e-12


def array(data, name):
    """A point array of `data` as numpy (the points for name "points"), or None."""
    values = data.GetPoints().GetData() if name == "points" else data.GetPointData().GetArray(name)
    return None if values is None else vtk_to_numpy(values)


for k, t in enumerate(steps):
    reader.UpdatePipeline(t)
    got = blocks(servermanager.Fetch(reader))
    if len(got) != 1:
        sys.exit(f"{path} ({kind}): expected one grid at t = {t}, got {len(got)}")
    grid = got[0]
    if grid.GetNumberOfPoints() != points:
        sys.exit(f"{path} ({kind}): expected {points} points at t = {t}, got {grid.GetNumberOfPoints()}")
    parts = []
    for part, vtu_file in sorted(vtu_files[t]):
        vtu = XMLUnstructuredGridReader(FileName=[os.path.join(directory, vtu_file)])
        vtu.UpdatePipeline()
        parts.append(servermanager.Fetch(vtu))
        Delete(vtu)
    where = f"{path} ({kind}) at t = {t}, against {len(parts)} VTUs"
    expected_cells = sum(part.GetNumberOfCells() for part in parts)
    for what, a, b in (("points", grid.GetNumberOfPoints(), sum(part.GetNumberOfPoints() for part in parts)),
                       ("cells", grid.GetNumberOfCells(), expected_cells)):
        if a != b:
            sys.exit(f"{where}: expected {b} {what} (the VTUs'), got {a}")
    # XDMF has no two-point line cell: a beam element is a polyline of 2 points there.
    types = [VTK_LINE if grid.GetCellType(c) == VTK_POLY_LINE and grid.GetCell(c).GetNumberOfPoints() == 2
             else grid.GetCellType(c) for c in range(grid.GetNumberOfCells())]
    expected_types = [part.GetCellType(c) for part in parts for c in range(part.GetNumberOfCells())]
    if types != expected_types:
        sys.exit(f"{where}: expected the VTUs' cell types, got others")
    for name in ("points", "displacement", "displacement_magnitude"):
        a = array(grid, name)
        if a is None:
            sys.exit(f"{where}: expected point array {name}, got none")
        b = numpy.concatenate([array(part, name) for part in parts if part.GetNumberOfPoints() > 0])
        difference = relative_difference(a, b)
        if difference > tolerance:
            sys.exit(f"{where}: expected {name} as in the VTUs to {tolerance} relative, got {difference:.3g}")
    # The deformed point against the closed form results.h5 holds: the same float64 values
    # summed in another order, on coordinates of order 1 m.
    if abs(t - point_time) < 1e-12:
        deformed = array(grid, "points")[index] + array(grid, "displacement")[index]
        if max(abs(a - b) for a, b in zip(deformed, point)) > 1e-12:
            sys.exit(f"{path} ({kind}): expected point {index} at t = {t} deformed to {point}, got {list(deformed)}")
print(f"{path} ({kind}): {len(steps)} time steps, one grid of {points} points each, as the VTU series")
