#!/usr/bin/python3
"""CPU cost of limber.run against the `limber run` command on one case (docs/python.md).

Usage: PYTHONPATH=build/solver/python scripts/python-overhead.py CASE LIMBER_EXECUTABLE [ROUNDS]

Each round runs, in turn, the command (its whole process: CPU from getrusage(RUSAGE_CHILDREN)),
limber.run(case) with the results in memory and limber.run(case, output=DIR) (the call: CPU of
this process from time.process_time()). Alternating rounds share the machine's load. Prints
the median and the minimum of each, and the calls' difference from the command.
"""
import pathlib
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import limber


def children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def command_cpu(cli, case, folder):
    before = children_cpu()
    done = subprocess.run([cli, "run", case, "-o", folder], capture_output=True)
    assert done.returncode in (0, 5), done.stderr  # 5: ok_inaccurate, a finished run
    return children_cpu() - before


def call_cpu(case, **options):
    before = time.process_time()
    results = limber.run(case, **options)
    assert results.status in ("ok", "ok_inaccurate"), results.message
    return time.process_time() - before


def main():
    case, cli = sys.argv[1], sys.argv[2]
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 7
    figures = {"command": [], "in memory": [], "output=DIR": []}
    with tempfile.TemporaryDirectory() as scratch:
        folder = pathlib.Path(scratch)
        for k in range(rounds):
            figures["command"].append(command_cpu(cli, case, folder / "cli"))
            figures["in memory"].append(call_cpu(case))
            figures["output=DIR"].append(call_cpu(case, output=folder / "py"))
            print(f"round {k + 1}: " + ", ".join(f"{name} {values[-1]:.3f} s" for name, values in figures.items()),
                  flush=True)
    command_median = statistics.median(figures["command"])
    command_min = min(figures["command"])
    for name, values in figures.items():
        median, least = statistics.median(values), min(values)
        print(f"{name:12s} CPU median {median:.3f} s ({100 * (median / command_median - 1):+.1f} %), "
              f"min {least:.3f} s ({100 * (least / command_min - 1):+.1f} %)")


if __name__ == "__main__":
    main()
