#!/usr/bin/env python3
"""`mpirun -n 2 bimrock run CASE --solver petsc` against `bimrock run CASE` (CHOLMOD).

Source of the expected numbers: the serial command's results, a second method (a direct
solve, or the serial analysis' route through the increments) on the same model. The parallel
run must write the same files, every number of its tables and of summary.json within a
tolerance (below) of the largest of its column (or key) in the serial run, and only its first
process may write (one results folder, complete). Of a staged case, the history (stage factors, monitors, yielding and
open points), the mechanism and the collapse bracket are compared; the solver's own counts
(factorizations, active-set iterations, pivots, rounds) and times differ by construction.

usage: same_results.py BIMROCK MPIEXEC CASE WORKDIR
"""
import csv
import json
import os
import shutil
import subprocess
import sys

# Elastic results: two solves of the same K. Staged ones: the increments' LCPs solved on other
# stiffnesses (K itself or a region's S where the serial analysis condenses K in a new order),
# which agree to about 1e-7 of each quantity: a hundredth of the bracket tolerance (1e-4) bounds
# them.
RTOL_ELASTIC = 1e-7
RTOL_STAGED = 1e-6


def numbers(value, path=""):
    """The numeric leaves of a JSON value, by path; the timings and the solver's own words
    (which differ by construction) left out."""
    if isinstance(value, dict):
        for k, v in value.items():
            if k in ("timings_s", "program", "files", "case", "factorizations"):
                continue
            yield from numbers(v, f"{path}/{k}")
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from numbers(v, f"{path}[{i}]")
    elif isinstance(value, (int, float)) and not isinstance(value, bool):
        yield path, float(value)


# The columns of the solver's own work, which the routes do differently.
# (The rows of an increment's LCP too: the points its zone covers join it at no cost.)
SOLVER_COLUMNS = {"lcp_size", "active_set_iterations", "tangent_factorizations", "pivots",
                  "rounds", "seconds"}


def compare_columns(name, serial, parallel, rtol, failures, floor_column=None):
    """Each column within rtol of its largest value; with floor_column, of that column's largest
    too (the mechanism's rates, whose columns of round-off have no scale of their own)."""
    with open(serial) as f:
        a = list(csv.reader(f))
    with open(parallel) as f:
        b = list(csv.reader(f))
    if a[0] != b[0] or len(a) != len(b):
        failures.append(f"{name}: header or row count differs")
        return
    floor = 0.0
    if floor_column is not None:
        k = a[0].index(floor_column)
        floor = max(abs(float(r[k])) for r in a[1:])
    for j, column in enumerate(a[0]):
        if column in SOLVER_COLUMNS:
            continue
        try:
            x = [float(r[j]) for r in a[1:]]
            y = [float(r[j]) for r in b[1:]]
        except ValueError:
            if [r[j] for r in a[1:]] != [r[j] for r in b[1:]]:
                failures.append(f"{name}: column {column} differs")
            continue
        scale = max(max((abs(v) for v in x), default=0.0), floor)
        worst = max((abs(p - q) for p, q in zip(x, y)), default=0.0)
        if worst > rtol * scale + 1e-300:
            failures.append(f"{name}: column {column} differs by {worst:.3g} (largest {scale:.3g})")


def main():
    bimrock, mpiexec, case, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    serial = os.path.join(work, "serial")
    parallel = os.path.join(work, "parallel")
    subprocess.run([bimrock, "run", case, "-o", serial, "-q"], check=True)
    subprocess.run([mpiexec, "-n", "2", "--oversubscribe", bimrock, "run", case, "--solver",
                    "petsc", "-o", parallel], check=True)
    failures = []
    files_a = sorted(os.path.relpath(os.path.join(d, f), serial)
                     for d, _, fs in os.walk(serial) for f in fs)
    files_b = sorted(os.path.relpath(os.path.join(d, f), parallel)
                     for d, _, fs in os.walk(parallel) for f in fs)
    if files_a != files_b:
        failures.append(f"files differ: {files_a} against {files_b}")
    staged = os.path.exists(os.path.join(serial, "history.csv"))
    rtol = RTOL_STAGED if staged else RTOL_ELASTIC
    for table in ("blocks.csv", "interfaces.csv", "history.csv", "mechanism.csv"):
        if not os.path.exists(os.path.join(serial, table)):
            continue
        compare_columns(table, os.path.join(serial, table), os.path.join(parallel, table), rtol,
                        failures, "speed" if table == "mechanism.csv" else None)
    with open(os.path.join(serial, "summary.json")) as f:
        a = dict(numbers(json.load(f)))
    with open(os.path.join(parallel, "summary.json")) as f:
        b = dict(numbers(json.load(f)))
    if a.keys() != b.keys():
        failures.append("summary.json: other keys")
    for key, x in a.items():
        if key in b and abs(b[key] - x) > rtol * abs(x) + 1e-15:
            failures.append(f"summary.json{key}: {b[key]!r} against {x!r}")
    for f in failures:
        print("FAIL", f)
    print(f"{len(files_a)} files compared, {len(failures)} differences")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
