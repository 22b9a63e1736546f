# Opens a scene.pvd with ParaView's own PVD reader, as a user would, and checks its time steps
# and the number of points at the first one. Run by paraview_test.cpp:
#   pvpython paraview_check.py SCENE.pvd POINTS TIME...
# Exit status 0 when both match; otherwise a message (expected/got) and status 1.
import sys

from paraview.simple import PVDReader

pvd = sys.argv[1]
points = int(sys.argv[2])
times = [float(t) for t in sys.argv[3:]]

reader = PVDReader(FileName=pvd)

# Time steps: written with 17 significant digits, so they read back exactly.
steps = list(reader.TimestepValues)
if len(steps) != len(times) or any(abs(a - b) > 1e-12 for a, b in zip(steps, times)):
    sys.exit(f"{pvd}: expected time steps {times}, got {steps}")

# Points of every part (body) at the first time step.
reader.UpdatePipeline(steps[0])
got = reader.GetDataInformation().GetNumberOfPoints()
if got != points:
    sys.exit(f"{pvd}: expected {points} points at t = {steps[0]}, got {got}")
print(f"{pvd}: {len(steps)} time steps, {got} points")
