#!/usr/bin/env bash
# Modal analysis at scale: limber against CalculiX on the same cantilever plate.
#
#   scripts/bench-modal.sh [BUILD_DIR] [RUNS] [N:MODES ...]
#     BUILD_DIR  build tree with limber_bench_modal (default: build; configure with
#                -DLIMBER_BUILD_BENCHMARKS=ON)
#     RUNS       runs per program and plate, alternating limber, ccx, limber, ... (default 3)
#     N:MODES    plate of N x N quads and the number of modes (default: 100:10 204:20)
#
# For every plate, limber_bench_modal writes the CalculiX deck of the same model (same nodes,
# element order and clamped edge; S4 shells, which ccx expands to 3-D solids, where limber
# uses MITC4) and the two programs run alternately, each under /usr/bin/time -v. Prints, per
# program, the minimum over the runs of the wall time, user CPU time and peak RSS, the ratios
# limber / ccx, and the relative difference of every frequency (close, not identical: the
# elements differ). ccx runs only when it is on PATH (Debian: apt-get install calculix-ccx);
# without it only limber's figures are printed. Not a test: nothing passes or fails on time.
set -euo pipefail

build_dir=${1:-build}
runs=${2:-3}
shift $(( $# > 2 ? 2 : $# ))
plates=("$@")
[[ ${#plates[@]} -gt 0 ]] || plates=(100:10 204:20)

bench="$build_dir/tests/modal/limber_bench_modal"
if [[ ! -x $bench ]]; then
  echo "bench-modal: expected $bench (configure with -DLIMBER_BUILD_BENCHMARKS=ON and build" \
       "the target limber_bench_modal)" >&2
  exit 1
fi
bench=$(realpath "$bench")
have_ccx=0
command -v ccx > /dev/null && have_ccx=1
[[ -x /usr/bin/time ]] || { echo "bench-modal: expected GNU time at /usr/bin/time" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Fields of /usr/bin/time -v: wall [s], user [s], peak RSS [MiB].
time_fields() {
  awk -F': ' '
    /Elapsed \(wall clock\)/ { n = split($2, p, ":"); w = 0; for (i = 1; i <= n; ++i) w = w * 60 + p[i] }
    /User time/ { u = $2 }
    /Maximum resident set size/ { r = $2 / 1024 }
    END { printf "%.2f %.2f %.0f\n", w, u, r }' "$1"
}

# Minimum of each column of a file of "wall user rss" lines.
column_minima() {
  awk 'NR == 1 { w = $1; u = $2; r = $3 }
       { if ($1 < w) w = $1; if ($2 < u) u = $2; if ($3 < r) r = $3 }
       END { printf "%s %s %s\n", w, u, r }' "$1"
}

echo "bench-modal: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)," \
     "$runs runs each, alternating; ccx $([[ $have_ccx == 1 ]] && ccx -v 2>&1 | grep -o '[0-9][0-9.]*' | head -1 || true; [[ $have_ccx == 1 ]] || echo 'not found')"
for plate in "${plates[@]}"; do
  n=${plate%%:*}
  modes=${plate##*:}
  dir="$work/plate$n"
  mkdir -p "$dir"
  : > "$dir/limber.min"
  : > "$dir/ccx.min"
  for ((run = 1; run <= runs; ++run)); do
    (cd "$dir" && /usr/bin/time -v -o limber.time "$bench" --modes "$modes" \
       --ccx-deck plate.inp "$n" > limber.out)
    time_fields "$dir/limber.time" >> "$dir/limber.min"
    if [[ $have_ccx == 1 ]]; then
      (cd "$dir" && /usr/bin/time -v -o ccx.time ccx -i plate > ccx.out 2>&1)
      time_fields "$dir/ccx.time" >> "$dir/ccx.min"
    fi
  done
  dofs=$(awk '/^DOFs/ { print $2 }' "$dir/limber.out")
  read -r lw lu lr < <(column_minima "$dir/limber.min")
  echo
  echo "cantilever plate $n x $n quads, $dofs DOFs, $modes modes (min of $runs)"
  printf "  %-8s  %8s  %8s  %9s\n" program "wall [s]" "user [s]" "RSS [MiB]"
  printf "  %-8s  %8s  %8s  %9s\n" limber "$lw" "$lu" "$lr"
  if [[ $have_ccx == 1 ]]; then
    read -r cw cu cr < <(column_minima "$dir/ccx.min")
    printf "  %-8s  %8s  %8s  %9s\n" ccx "$cw" "$cu" "$cr"
    awk -v lw="$lw" -v lu="$lu" -v lr="$lr" -v cw="$cw" -v cu="$cu" -v cr="$cr" 'BEGIN {
      printf "  limber / ccx: wall %.3f, user %.3f, peak RSS %.3f\n", lw / cw, lu / cu, lr / cr }'
    # Frequencies: limber's "mode k  f Hz" lines against ccx's eigenvalue table (4th column).
    awk '/^  mode/ { print $3 }' "$dir/limber.out" > "$dir/limber.f"
    awk '/E I G E N V A L U E   O U T P U T/ { on = 1; next }
         on && /P A R T I C I P A T I O N/ { on = 0 }
         on && $1 ~ /^[0-9]+$/ && NF == 5 { print $4 }' "$dir/plate.dat" > "$dir/ccx.f"
    echo "  mode   limber [Hz]       ccx [Hz]    (ccx - limber) / limber"
    paste "$dir/limber.f" "$dir/ccx.f" | awk '{ printf "  %4d  %12.6f  %12.6f  %+.2e\n", NR, $1, $2, ($2 - $1) / $1 }'
  fi
done
