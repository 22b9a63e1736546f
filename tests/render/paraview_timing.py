# How long ParaView takes to open limber's output and to step through every time step
# (docs/rendering.md, "ParaView output: measured"). A measurement, not a test:
#   pvpython paraview_timing.py DIR/vtk/scene.xmf DIR/vtk/scene.pvd ...
# prints, per file: the reader, the time steps, the wall and CPU (this process) times to open it
# (reader created, time steps known, first step read) and to read every other step, and the
# points at the last step. The CPU times are the steadier figures on a shared machine.
import sys
import time

from paraview.simple import Delete, PVDReader, XDMFReader, Xdmf3ReaderS

for path in sys.argv[1:]:
    kinds = ["PVDReader"] if path.endswith(".pvd") else ["XDMFReader", "Xdmf3ReaderS"]
    for kind in kinds:
        start, start_cpu = time.perf_counter(), time.process_time()
        if kind == "PVDReader":
            reader = PVDReader(FileName=path)
        elif kind == "XDMFReader":
            reader = XDMFReader(FileNames=[path])
        else:
            reader = Xdmf3ReaderS(FileName=[path])
        steps = list(reader.TimestepValues)
        reader.UpdatePipeline(steps[0])
        opened, opened_cpu = time.perf_counter() - start, time.process_time() - start_cpu
        start, start_cpu = time.perf_counter(), time.process_time()
        for t in steps[1:]:
            reader.UpdatePipeline(t)
        stepped, stepped_cpu = time.perf_counter() - start, time.process_time() - start_cpu
        points = reader.GetDataInformation().GetNumberOfPoints()
        print(f"{path} {kind}: {len(steps)} steps, open {opened:.2f} s wall {opened_cpu:.2f} s CPU, "
              f"every other step {stepped:.2f} s wall {stepped_cpu:.2f} s CPU "
              f"({1e3 * stepped_cpu / max(len(steps) - 1, 1):.1f} ms CPU/step), {points} points at the last")
        Delete(reader)
