#!/usr/bin/env python3
"""Factor of safety of the dry slope of the slope stability example (examples/slope_stability)
against the friction angle of its bedding joint, by strength reduction with bimrock's Python
API, beside the limit equilibrium of the block sliding on the joint (Hoek & Bray's plane
failure, dry tension crack). Units: SI (m, N, Pa); angles in degrees.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/friction_sweep.py \
        [--angles 10] [--plot friction_sweep.png] [--check 0.005]

The blocks and interfaces are built once; each angle changes the joint material only
(Case.update), so each costs its analysis alone. Prints one line per angle and saves the plot;
with --check, exits 1 if any F differs from limit equilibrium by more than that fraction.
"""
import argparse
import math
import pathlib
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after the backend is chosen)

import bimrock  # noqa: E402

CASE = pathlib.Path(__file__).resolve().parents[1] / "slope_stability" / "dry.yaml"


def limit_equilibrium(document, friction_deg):
    """F = (c A + W cos(a) tan(phi)) / (W sin(a)) of the sliding block (blocks[0]) on the bedding
    (its first edge, dipping at a, of length A), from the case's own geometry and materials."""
    block = document["blocks"][0]["vertices"]
    n = len(block)
    area = 0.5 * abs(sum(block[k][0] * block[(k + 1) % n][1] - block[(k + 1) % n][0] * block[k][1]
                         for k in range(n)))
    weight = document["materials"]["rock"]["unit_weight"] * area  # per metre of thickness
    (x0, y0), (x1, y1) = block[0], block[1]
    length = math.hypot(x1 - x0, y1 - y0)
    dip = math.atan2(y1 - y0, x1 - x0)
    cohesion = document["joint_materials"]["bedding"]["cohesion"]
    resisting = cohesion * length + weight * math.cos(dip) * math.tan(math.radians(friction_deg))
    return resisting / (weight * math.sin(dip))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--angles", type=int, default=10, help="friction angles from 0 to 45 deg")
    parser.add_argument("--plot", default="friction_sweep.png", help="the plot (PNG)")
    parser.add_argument("--check", type=float, default=None,
                        help="largest relative difference from limit equilibrium allowed")
    args = parser.parse_args()

    case = bimrock.Case.from_file(CASE)
    document = case.document
    joints = document["joint_materials"]
    angles = [45.0 * k / max(args.angles - 1, 1) for k in range(args.angles)]
    rows = []
    start = time.perf_counter()
    print(" phi [deg]   F lower   F upper   limit equilibrium")
    for phi in angles:
        joints["bedding"]["friction"] = phi
        case.update(joint_materials=joints)
        f = case.run().factor_of_safety
        le = limit_equilibrium(document, phi)
        upper = f["upper"] if f["upper"] is not None else math.nan
        rows.append((phi, f["lower"], upper, le))
        print(f"{phi:10.2f}  {f['lower']:8.4f}  {upper:8.4f}  {le:10.4f}")
    seconds = time.perf_counter() - start
    print(f"{len(angles)} analyses in {seconds:.2f} s")

    figure, axes = plt.subplots(figsize=(6, 4))
    axes.plot([r[0] for r in rows], [r[3] for r in rows], "-", color="grey",
              label="limit equilibrium")
    axes.plot([r[0] for r in rows], [r[1] for r in rows], "o", label="bimrock (largest F carried)")
    axes.set_xlabel("friction angle of the bedding joint [deg]")
    axes.set_ylabel("factor of safety F")
    axes.set_title("Plane failure with a tension crack: F by strength reduction")
    axes.grid(True, alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(args.plot, dpi=120)
    print(f"plot: {args.plot}")

    if args.check is not None:
        worst = max(abs(r[1] - r[3]) / r[3] for r in rows)
        print(f"largest difference from limit equilibrium: {100 * worst:.3f}%")
        if worst > args.check:
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
