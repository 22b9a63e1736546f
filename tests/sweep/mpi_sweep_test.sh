#!/bin/sh
# `limber sweep` under `mpirun -n 2` gathers the same table as a serial sweep: same points, same
# statuses, step and Newton counts and errors (each run is deterministic and single-threaded),
# and both ranks ran points. Usage: mpi_sweep_test.sh LIMBER CASE OUT MPIEXEC
set -eu
limber=$1 case=$2 out=$3 mpiexec=$4
rm -rf "$out"
grid="--over integrator=galpha step=1e-3,5e-4,2.5e-4 --t-end 0.05 --jobs 1"
"$limber" sweep "$case" $grid -o "$out/serial" >/dev/null
# Open MPI refuses root and more ranks than cores unless told (a container in CI).
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  "$mpiexec" -n 2 --allow-run-as-root --oversubscribe "$limber" sweep "$case" $grid -o "$out/mpi" >/dev/null
# point, status, steps, Newton iterations, Jacobian evaluations, error_peak, error_rms.
columns=1,7,12,14,15,21,22
cut -d, -f$columns "$out/serial/sweep/work_precision.csv" >"$out/serial.txt"
cut -d, -f$columns "$out/mpi/sweep/work_precision.csv" >"$out/mpi.txt"
diff "$out/serial.txt" "$out/mpi.txt"
test "$(wc -l <"$out/mpi.txt")" -eq 4
# The rank column (25): points 1 and 3 on rank 0, point 2 on rank 1.
test "$(cut -d, -f25 "$out/mpi/sweep/work_precision.csv" | tail -n +2 | tr '\n' ' ')" = "0 1 0 "
echo "mpi sweep: the gathered table equals the serial one"
