#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The reliability sweep: random nonlinear cases of the kinds engineers run, each run in full.

Each seed gives one case file (the same seed, the same file): a jointed rock slope and its
factor of safety, a tunnel excavated in jointed rock under in-situ stress, a masonry arch of
voussoirs under its weight and a point load, or a strip footing on a jointed rock mass. Joints
are Mohr-Coulomb with random friction, dilation from 0 to the friction (0 for two in five),
cohesion 0 for half of them, and no tension. Every run must end carried, collapsed or with its
factor of safety; the sweep prints one line per case (exit code, seconds, outcome) and the cases
that stopped (exit 5), failed otherwise or ran past the time limit. Units: SI (m, N, Pa).

    bench/random_sweep.py --bimrock build/release/bimrock --seeds 0-99 --jobs 2 --out /tmp/sweep

Only the files of cases that did not end well are kept under --out.
"""
import argparse
import concurrent.futures
import json
import math
import os
import random
import shutil
import subprocess
import time

KINDS = ("slope", "tunnel", "arch", "footing")


def joint_strength(rng, max_cohesion):
    """Friction 15-50 deg; dilation 0 for two in five, else up to the friction; cohesion 0 for
    half; no tension."""
    phi = rng.uniform(15.0, 50.0)
    psi = 0.0 if rng.random() < 0.4 else rng.uniform(0.0, phi)
    cohesion = 0.0 if rng.random() < 0.5 else rng.uniform(0.0, max_cohesion)
    return f"cohesion: {cohesion:.1f}, friction: {phi:.3f}, dilation: {psi:.3f}"


def joint_sets(rng, count, spacing_range, trace_range):
    sets = []
    for k in range(count):
        dip = rng.uniform(0.0, 180.0)
        spacing = rng.uniform(*spacing_range)
        ox, oy = rng.uniform(0.0, spacing), rng.uniform(0.0, spacing)
        if rng.random() < 0.5:
            persistence = ""
        else:
            persistence = (f", trace_length: {rng.uniform(*trace_range):.3f}, "
                           f"gap: {rng.uniform(0.1, 0.5) * trace_range[0]:.3f}")
        sets.append(f"    - {{material: joint, dip: {dip:.3f}, spacing: {spacing:.3f}"
                    f"{persistence}, origin: [{ox:.3f}, {oy:.3f}]}}")
    return "\n".join(sets)


def preamble(title, plane, materials, joint):
    """The lines every case file starts with: its title, the units, the block materials (one
    per line) and the joint material."""
    lines = "\n".join(f"  {m}: {{E: {e}, nu: {nu}, unit_weight: {w}}}" for m, e, nu, w in materials)
    return f"""schema: 1
title: "{title}"
# Units: SI (m, N, Pa, Pa/m, N/m^3).
analysis: {{plane: {plane}, thickness: 1.0}}
materials:
{lines}
joint_materials:
  {joint}
"""


ROCK = ("20.0e9", "0.25", "26.0e3")


def slope(rng):
    height = rng.uniform(10.0, 40.0)
    face = math.radians(rng.uniform(45.0, 75.0))
    base = 0.5 * height
    toe = 1.5 * height
    crest = toe + height / math.tan(face)
    right = crest + 1.5 * height
    top = base + height
    sets = joint_sets(rng, rng.choice((1, 2)), (height / 6, height / 3), (height / 2, height))
    head = preamble("Random slope: factor of safety of a jointed rock slope", "strain",
                    [("rock", *ROCK)],
                    f"joint: {{kn: 10.0e9, ks: 4.0e9, {joint_strength(rng, 30e3)}}}")
    return head + f"""domain:
  outline: [[0, 0], [{right:.4f}, 0], [{right:.4f}, {top:.4f}], [{crest:.4f}, {top:.4f}],
            [{toe:.4f}, {base:.4f}], [0, {base:.4f}]]
  material: rock
  joint_sets:
{sets}
supports:
  - {{line: [[0, 0], [{right:.4f}, 0]], type: fixed}}
  - {{line: [[0, 0], [0, {base:.4f}]], type: roller}}
  - {{line: [[{right:.4f}, 0], [{right:.4f}, {top:.4f}]], type: roller}}
monitors:
  - {{name: crest, at: [{crest + 0.1:.4f}, {top - 0.1:.4f}]}}
stages:
  - name: gravity
    increments: {rng.randint(1, 4)}
    loads: {{gravity: [0, -1]}}
factor_of_safety: {{materials: [joint], tolerance: 1.0e-3, largest: 3}}
"""


def polygon(points):
    return "[" + ", ".join(f"[{x:.4f}, {y:.4f}]" for x, y in points) + "]"


def tunnel(rng):
    radius = rng.uniform(2.0, 4.0)
    half = round(5.0 * radius, 3)
    depth = rng.uniform(50.0, 400.0)
    k0 = rng.uniform(0.3, 3.0)
    n = 16
    circle = [(radius * math.cos(2 * math.pi * i / n), radius * math.sin(2 * math.pi * i / n))
              for i in range(n)]
    upper = circle[: n // 2 + 1]  # from (r, 0) over the crown to (-r, 0)
    lower = circle[n // 2 :] + circle[:1]  # from (-r, 0) under the floor to (r, 0)
    stages = rng.choice((1, 2))
    sets = joint_sets(rng, 2, (0.3 * radius, 0.6 * radius), (2 * radius, 4 * radius))
    overburden = 26.0e3 * (depth - half)
    if stages == 1:
        excavation = f"""  - name: excavation
    increments: {rng.randint(2, 6)}
    excavate: {{material: opening}}"""
        zones = f"    - {{material: opening, outline: {polygon(circle)}}}"
    else:
        release = rng.uniform(0.3, 0.8)
        excavation = f"""  - name: top heading
    increments: {rng.randint(2, 4)}
    excavate: {{material: heading}}
    release: {release:.3f}
  - name: bench
    increments: {rng.randint(2, 4)}
    excavate: {{material: bench}}"""
        zones = (f"    - {{material: heading, outline: {polygon(upper)}}}\n"
                 f"    - {{material: bench, outline: {polygon(lower)}}}")
    head = preamble("Random tunnel: a circular opening excavated in jointed rock under in-situ"
                    " stress", "strain",
                    [(m, *ROCK) for m in ("rock", "opening", "heading", "bench")],
                    f"joint: {{kn: 20.0e9, ks: 8.0e9, {joint_strength(rng, 100e3)}}}")
    return head + f"""domain:
  outline: [[{-half}, {-half}], [{half}, {-half}], [{half}, {half}], [{-half}, {half}]]
  material: rock
  zones:
{zones}
  joint_sets:
{sets}
initial_stress:
  gravity: {{ground_level: {depth:.3f}, unit_weight: 26.0e3, k0: {k0:.3f}}}
  allow_yield: true
supports:
  - {{line: [[{-half}, {-half}], [{half}, {-half}]], type: fixed}}
  - {{line: [[{-half}, {-half}], [{-half}, {half}]], type: roller}}
  - {{line: [[{half}, {-half}], [{half}, {half}]], type: roller}}
monitors:
  - {{name: crown, at: [0.0, {radius + 0.3:.4f}]}}
stages:
  - name: in situ
    loads:
      gravity: [0, -1]
      tractions: [{{line: [[{-half}, {half}], [{half}, {half}]], normal: {-overburden:.6e}}}]
{excavation}
"""


def arch(rng):
    radius = rng.uniform(2.0, 8.0)
    thickness = radius * rng.uniform(0.08, 0.25)
    count = rng.randint(5, 15)
    inner, outer = radius - thickness / 2, radius + thickness / 2
    blocks = []
    centroids = []
    weights = []
    for i in range(count):
        a, b = math.pi * i / count, math.pi * (i + 1) / count
        quad = [(inner * math.cos(b), inner * math.sin(b)),
                (inner * math.cos(a), inner * math.sin(a)),
                (outer * math.cos(a), outer * math.sin(a)),
                (outer * math.cos(b), outer * math.sin(b))]
        # Counter-clockwise: inner edge from b to a, outer edge from a to b.
        blocks.append(f"  - {{material: stone, vertices: {polygon(quad)}}}")
        centroids.append((sum(p[0] for p in quad) / 4, sum(p[1] for p in quad) / 4))
        weights.append(22.0e3 * 0.5 * (b - a) * (outer ** 2 - inner ** 2))
    loaded = rng.randrange(count)
    force = rng.uniform(0.05, 1.0) * sum(weights)
    head = preamble("Random arch: semicircular voussoirs under their weight and a point load",
                    "stress", [("stone", "10.0e9", "0.2", "22.0e3")],
                    f"mortarless: {{kn: 5.0e10, ks: 2.0e10, {joint_strength(rng, 0.0)}}}")
    return head + f"""joints:
  default: mortarless
blocks:
{chr(10).join(blocks)}
supports:
  - {{line: [[{inner:.4f}, 0], [{outer:.4f}, 0]], type: fixed, joint: mortarless}}
  - {{line: [[{-outer:.4f}, 0], [{-inner:.4f}, 0]], type: fixed, joint: mortarless}}
monitors:
  - {{name: loaded, at: [{centroids[loaded][0]:.4f}, {centroids[loaded][1]:.4f}]}}
stages:
  - name: gravity
    increments: 2
    loads: {{gravity: [0, -1]}}
  - name: point load
    increments: 10
    loads:
      points:
        - {{at: [{centroids[loaded][0]:.4f}, {centroids[loaded][1]:.4f}], force: [0, {-force:.3f}]}}
"""


def footing(rng):
    width = rng.uniform(16.0, 30.0)
    depth = width / 2
    strip = rng.uniform(1.5, 4.0)
    sets = joint_sets(rng, 2, (0.8, 2.0), (3.0, 8.0))
    pressure = rng.uniform(2.0, 30.0) * 1e6
    x1, x2 = (width - strip) / 2, (width + strip) / 2
    pad = [(x1, depth - 0.5), (x2, depth - 0.5), (x2, depth + 1.0), (x1, depth + 1.0)]
    head = preamble("Random footing: a strip load on a jointed rock mass", "strain",
                    [("rock", *ROCK), ("pad", *ROCK)],
                    f"joint: {{kn: 10.0e9, ks: 4.0e9, {joint_strength(rng, 200e3)}}}")
    return head + f"""domain:
  outline: [[0, 0], [{width:.4f}, 0], [{width:.4f}, {depth:.4f}], [0, {depth:.4f}]]
  material: rock
  zones:  # cuts the top at the strip's ends
    - {{material: pad, outline: {polygon(pad)}}}
  joint_sets:
{sets}
supports:
  - {{line: [[0, 0], [{width:.4f}, 0]], type: fixed}}
  - {{line: [[0, 0], [0, {depth:.4f}]], type: roller}}
  - {{line: [[{width:.4f}, 0], [{width:.4f}, {depth:.4f}]], type: roller}}
monitors:
  - {{name: footing, at: [{width / 2:.4f}, {depth - 0.05:.4f}]}}
stages:
  - name: gravity
    loads: {{gravity: [0, -1]}}
  - name: footing
    increments: 10
    loads:
      tractions:
        - {{line: [[{x1:.4f}, {depth:.4f}], [{x2:.4f}, {depth:.4f}]], normal: {-pressure:.6e}}}
"""


def case_file(seed):
    rng = random.Random(seed)
    kind = KINDS[seed % len(KINDS)]
    return kind, globals()[kind](rng)


def outcome(summary):
    """One line: what the analysis says happened."""
    if summary.get("stopped"):
        s = summary["stopped"]
        return f"STOPPED in '{s['stage']}' at {s['carried_factor']:.6g}"
    fos = summary.get("factor_of_safety")
    if fos:
        upper = "none" if fos.get("upper") is None else f"{fos['upper']:.6g}"
        text = f"F in [{fos['lower']:.6g}, {upper}]"
    else:
        text = ""
    collapse = summary.get("collapse")
    if collapse:
        kind = "limit point" if collapse.get("limit_point") else "collapse"
        if collapse.get("unstable_at_first_load"):
            kind = "unstable under the first load"
        wide = ", undecided inside" if collapse.get("undecided_inside") else ""
        text = (f"{kind} in '{collapse['stage']}' [{collapse['carried_factor']:.6g}, "
                f"{collapse['failed_factor']:.6g}]{wide}; " + text)
    return text or "carried"


def run(bimrock, out, seed, limit):
    kind, text = case_file(seed)
    folder = os.path.join(out, f"{seed:05d}_{kind}")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "case.yaml")
    with open(path, "w") as f:
        f.write(text)
    results = os.path.join(folder, "results")
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    start = time.monotonic()
    try:
        proc = subprocess.run([bimrock, "run", path, "-o", results, "-q"], env=env,
                              capture_output=True, text=True, timeout=limit)
        rc = proc.returncode
        message = proc.stderr.strip().splitlines()[-1] if proc.stderr.strip() else ""
    except subprocess.TimeoutExpired:
        rc, message = None, f"ran past {limit} s"
    seconds = time.monotonic() - start
    summary_path = os.path.join(results, "summary.json")
    if os.path.exists(summary_path):
        with open(summary_path) as f:
            message = outcome(json.load(f))
    if rc == 0:
        shutil.rmtree(folder)
    return seed, kind, rc, seconds, message


def seeds_of(text):
    seeds = []
    for part in text.split(","):
        first, _, last = part.partition("-")
        seeds.extend(range(int(first), int(last or first) + 1))
    return seeds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bimrock", default="build/release/bimrock")
    parser.add_argument("--seeds", default="0-99", help="e.g. 0-99 or 3,7,10-20")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--limit", type=float, default=120.0, help="seconds per case")
    parser.add_argument("--out", default="sweep")
    parser.add_argument("--print", dest="print_seed", type=int,
                        help="print the case file of this seed and exit")
    args = parser.parse_args()
    if args.print_seed is not None:
        print(case_file(args.print_seed)[1], end="")
        return 0
    bimrock = os.path.abspath(args.bimrock)
    results = []
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        jobs = [pool.submit(run, bimrock, args.out, s, args.limit) for s in seeds_of(args.seeds)]
        for job in concurrent.futures.as_completed(jobs):
            seed, kind, rc, seconds, message = job.result()
            results.append((seed, kind, rc, seconds, message))
            print(f"{seed:5d} {kind:8s} rc={rc} {seconds:7.1f} s  {message}", flush=True)
    bad = [r for r in sorted(results) if r[2] != 0]
    total = sum(r[3] for r in results)
    print(f"\n{len(results)} cases, {len(results) - len(bad)} ended well, {total:.0f} s in all, "
          f"the longest {max(r[3] for r in results):.1f} s")
    for seed, kind, rc, seconds, message in bad:
        print(f"  not well: {seed} {kind} rc={rc} {seconds:.1f} s  {message}")
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
