#!/usr/bin/env python3
"""`mpirun -n 2 bimrock run CASE --solver petsc` against `bimrock run CASE` (CHOLMOD).

Source of the expected numbers: the serial command's results, a second method (a direct
solve) on the same model. The parallel run must write the same files, every number of its
tables and of summary.json within RTOL of the largest of its column (or key) in the serial
run, and only its first process may write (one results folder, complete).

usage: same_results.py BIMROCK MPIEXEC CASE WORKDIR
"""
import csv
import json
import os
import shutil
import subprocess
import sys

RTOL = 1e-7


def numbers(value, path=""):
    """The numeric leaves of a JSON value, by path; the timings and the solver's own words
    (which differ by construction) left out."""
    if isinstance(value, dict):
        for k, v in value.items():
            if k in ("timings_s", "program", "files", "case"):
                continue
            yield from numbers(v, f"{path}/{k}")
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from numbers(v, f"{path}[{i}]")
    elif isinstance(value, (int, float)) and not isinstance(value, bool):
        yield path, float(value)


def compare_columns(name, serial, parallel, failures):
    with open(serial) as f:
        a = list(csv.reader(f))
    with open(parallel) as f:
        b = list(csv.reader(f))
    if a[0] != b[0] or len(a) != len(b):
        failures.append(f"{name}: header or row count differs")
        return
    for j, column in enumerate(a[0]):
        try:
            x = [float(r[j]) for r in a[1:]]
            y = [float(r[j]) for r in b[1:]]
        except ValueError:
            if [r[j] for r in a[1:]] != [r[j] for r in b[1:]]:
                failures.append(f"{name}: column {column} differs")
            continue
        scale = max((abs(v) for v in x), default=0.0)
        worst = max((abs(p - q) for p, q in zip(x, y)), default=0.0)
        if worst > RTOL * scale + 1e-300:
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
    for table in ("blocks.csv", "interfaces.csv"):
        compare_columns(table, os.path.join(serial, table), os.path.join(parallel, table),
                        failures)
    with open(os.path.join(serial, "summary.json")) as f:
        a = dict(numbers(json.load(f)))
    with open(os.path.join(parallel, "summary.json")) as f:
        b = dict(numbers(json.load(f)))
    if a.keys() != b.keys():
        failures.append("summary.json: other keys")
    for key, x in a.items():
        if key in b and abs(b[key] - x) > RTOL * abs(x) + 1e-15:
            failures.append(f"summary.json{key}: {b[key]!r} against {x!r}")
    for f in failures:
        print("FAIL", f)
    print(f"{len(files_a)} files compared, {len(failures)} differences")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
