# ParaView itself opens limber's output, as a user would. Run by paraview_test.cpp:
#   pvpython paraview_check.py pvd SCENE.pvd POINTS TIME...
#       the PVD reader: the time steps, and the points of every part at the first one;
#   pvpython paraview_check.py xdmf|xdmf3 SCENE.xmf BODIES TIME...
#       the XDMF Reader (xdmf) or Xdmf3ReaderS (xdmf3) on scene.xmf: the time steps, then at
#       EVERY step, block b (BODIES: their count) against the VTU of the same sample and part
#       b listed in scene.pvd beside it, read with ParaView's VTU reader (a second writer): the
#       number of points and cells, the cell types, the point positions and the point arrays
#       displacement and displacement_magnitude to 1e-12 relative.
# Exit status 0 when all match; otherwise a message (expected/got) and status 1.
import os
import sys
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
    """The leaves of a multiblock data set, in order."""
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

bodies = int(sys.argv[3])
times = [float(t) for t in sys.argv[4:]]
reader = XDMFReader(FileNames=[path]) if kind == "xdmf" else Xdmf3ReaderS(FileName=[path])
steps = check_times(reader, times)
directory = os.path.dirname(path)
# The VTU of each (time, part), from the PVD written beside the scene.
vtu_files = {}
for dataset in ElementTree.parse(os.path.join(directory, "scene.pvd")).getroot().iter("DataSet"):
    vtu_files[(float(dataset.get("timestep")), int(dataset.get("part")))] = dataset.get("file")
# Tolerance 1e-12 relative: both writers store the same float64 products of the same
# results.h5 values (the VTU's pose applied by vtkTransform, the scene's by Eigen), which differ
# by a few ulps.
tolerance = 1e-12
for k, t in enumerate(steps):
    reader.UpdatePipeline(t)
    got = blocks(servermanager.Fetch(reader))
    if len(got) != bodies:
        sys.exit(f"{path} ({kind}): expected {bodies} blocks at t = {t}, got {len(got)}")
    for part, block in enumerate(got):
        vtu_file = vtu_files[(t, part)]
        vtu = XMLUnstructuredGridReader(FileName=[os.path.join(directory, vtu_file)])
        vtu.UpdatePipeline()
        expected = servermanager.Fetch(vtu)
        where = f"{path} ({kind}), {vtu_file} at t = {t}"
        for what, a, b in (("points", block.GetNumberOfPoints(), expected.GetNumberOfPoints()),
                           ("cells", block.GetNumberOfCells(), expected.GetNumberOfCells())):
            if a != b:
                sys.exit(f"{where}: expected {b} {what} (the VTU's), got {a}")
        # XDMF has no two-point line cell: a beam element is a polyline of 2 points there.
        types = [VTK_LINE if block.GetCellType(c) == VTK_POLY_LINE and block.GetCell(c).GetNumberOfPoints() == 2
                 else block.GetCellType(c) for c in range(block.GetNumberOfCells())]
        expected_types = [expected.GetCellType(c) for c in range(expected.GetNumberOfCells())]
        if types != expected_types:
            sys.exit(f"{where}: expected the VTU's cell types, got others")
        if block.GetNumberOfPoints() == 0:
            continue
        pairs = [("points", block.GetPoints().GetData(), expected.GetPoints().GetData())]
        for name in ("displacement", "displacement_magnitude"):
            pairs.append((name, block.GetPointData().GetArray(name), expected.GetPointData().GetArray(name)))
        for name, a, b in pairs:
            if a is None:
                sys.exit(f"{where}: expected point array {name}, got none")
            difference = relative_difference(vtk_to_numpy(a), vtk_to_numpy(b))
            if difference > tolerance:
                sys.exit(f"{where}: expected {name} as in the VTU to {tolerance} relative, got {difference:.3g}")
        Delete(vtu)
print(f"{path} ({kind}): {len(steps)} time steps, {bodies} blocks each, as the VTU series")
