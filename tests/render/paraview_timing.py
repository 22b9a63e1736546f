# How long ParaView takes to open limber's output and to step through every time step
# (docs/rendering.md, "ParaView output: measured"). A measurement, not a test:
#   pvpython paraview_timing.py DIR/vtk/scene.xmf DIR/vtk/scene.pvd ...
# prints, per file: the reader, the time steps, the wall time to open it (reader created, time
# steps known, first step read) and to read every other step, and the points at the last step.
import sys
import time

from paraview.simple import Delete, PVDReader, XDMFReader, Xdmf3ReaderS

for path in sys.argv[1:]:
    kinds = ["PVDReader"] if path.endswith(".pvd") else ["XDMFReader", "Xdmf3ReaderS"]
    for kind in kinds:
        start = time.perf_counter()
        if kind == "PVDReader":
            reader = PVDReader(FileName=path)
        elif kind == "XDMFReader":
            reader = XDMFReader(FileNames=[path])
        else:
            reader = Xdmf3ReaderS(FileName=[path])
        steps = list(reader.TimestepValues)
        reader.UpdatePipeline(steps[0])
        opened = time.perf_counter() - start
        start = time.perf_counter()
        for t in steps[1:]:
            reader.UpdatePipeline(t)
        stepped = time.perf_counter() - start
        points = reader.GetDataInformation().GetNumberOfPoints()
        print(f"{path} {kind}: {len(steps)} steps, open {opened:.2f} s, every other step "
              f"{stepped:.2f} s ({1e3 * stepped / max(len(steps) - 1, 1):.1f} ms/step), "
              f"{points} points at the last")
        Delete(reader)
