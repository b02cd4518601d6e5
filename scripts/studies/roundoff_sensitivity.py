#!/usr/bin/python3
"""How far round-off alone moves a BEM answer stopped at a given tolerance (issue 39's one known difference).

Under mpiexec every scene's BEM agrees with one process to 1e-12 except `bem_512_1e-4` of
scenes/studies/accuracy_vs_time.toml (tolerance 1e-4): equal areas, spots and iterations, pressures and
separation 1e-10 apart (tests/mpi/test_mpi_scenes.py). The distributed solver takes the serial iteration step
for step; only the order of its global sums differs. This study asks whether the serial solver alone moves
that much under an equally small change: the same solve on 1 and on 2 threads (the threads' partial sums
combine in another order), and on heights perturbed by a seeded relative 1e-15 (a few ulp). If both move the
pressures as much as the ranks do, the difference is the stopped iterate's sensitivity to round-off, not a
flaw of the distributed path, and the right bound for an equality test scales with the tolerance.

Surface A of the seed paper (256 x 256 over 200 um, seed 1) Fourier-refined to n, periodic and not, loads
P/(E* A0) = 0.002 and 0.02 (about 2 % and 14 % contact), the default solver, a cold solve each. Reports per
tolerance the largest of: |p_a - p_b|_max / p_max over the field, the relative difference of the largest
pressure and of the separation, and whether iterations and contact points were equal.

Run: OMP_WAIT_POLICY=PASSIVE PYTHONPATH=$PWD/build/release/python /usr/bin/python3 \
       scripts/studies/roundoff_sensitivity.py [--grids 256,512,1024] [--out results/studies/roundoff]
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from study_common import ROOT, write_atomically  # noqa: E402
from error_bar import stamp  # noqa: E402

import contactbench as cb  # noqa: E402

E_STAR = 100e9 / (1 - 0.3 * 0.3)
TOLERANCES = (1e-4, 1e-6, 1e-8, 1e-10)
LOADS = (0.002, 0.02)
PERTURBATION = 1e-15


def relative(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


def differences(reference, other):
    p0, p1 = np.asarray(reference.pressure), np.asarray(other.pressure)
    return (np.abs(p1 - p0).max() / p0.max(), relative(reference.max_pressure, other.max_pressure),
            relative(reference.separation, other.separation),
            reference.iterations == other.iterations and reference.contact_points == other.contact_points)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grids", default="256,512,1024")
    parser.add_argument("--out", default=os.path.join(ROOT, "results", "studies", "roundoff"))
    args = parser.parse_args()
    grids = [int(g) for g in args.grids.split(",")]
    paper = cb.generate_surface(cb.Grid(nx=256, ny=256, lx=200e-6, ly=200e-6),
                                cb.SelfAffinePsd(sigma=0.5e-6, hurst=0.5, qr=3.14e4), 1)
    rows = []
    for n in grids:
        refined = paper if n == 256 else cb.refine(paper, n)
        heights = np.asarray(refined.heights)
        noise = np.random.default_rng(2026).standard_normal(heights.shape)
        for periodic in (True, False):
            surface = cb.Surface(heights, lx=refined.lx, periodic=periodic)
            perturbed = cb.Surface(heights * (1 + PERTURBATION * noise), lx=refined.lx, periodic=periodic)
            for tolerance in TOLERANCES:
                worst = {"threads": [0, 0, 0, True], "perturbed": [0, 0, 0, True]}
                iterations = []
                for load in LOADS:
                    one = cb.BemSolver(surface, E_STAR, tolerance=tolerance, threads=1).solve(load)
                    two = cb.BemSolver(surface, E_STAR, tolerance=tolerance, threads=2).solve(load)
                    moved = cb.BemSolver(perturbed, E_STAR, tolerance=tolerance, threads=1).solve(load)
                    iterations.append(one.iterations)
                    for key, other in (("threads", two), ("perturbed", moved)):
                        d = differences(one, other)
                        w = worst[key]
                        worst[key] = [max(w[0], d[0]), max(w[1], d[1]), max(w[2], d[2]), w[3] and d[3]]
                rows.append((n, periodic, tolerance, iterations, worst))
                print(n, periodic, tolerance, iterations, worst, file=sys.stderr)
    lines = ["# Round-off sensitivity of a stopped BEM solve", "",
             "Made by `OMP_WAIT_POLICY=PASSIVE PYTHONPATH=$PWD/build/release/python /usr/bin/python3 "
             "scripts/studies/roundoff_sensitivity.py --grids {}` ({}).".format(args.grids, stamp()), "",
             "Surface A (seed 1) refined to n, default solver, cold solves at P/(E* A0) = {}; per row the "
             "largest over the loads. 'threads': 1 against 2 threads; 'perturbed': heights times "
             "(1 + {:g} N(0,1)), seeded. Field = max |dp| / max p; pmax, separation: relative "
             "differences; equal = iterations and contact points equal.".format(
                 " and ".join(str(x) for x in LOADS), PERTURBATION), "",
             "| n | periodic | tolerance | iterations | threads: field | pmax | separation | equal "
             "| perturbed: field | pmax | separation | equal |",
             "|---:|---|---:|---|---:|---:|---:|---|---:|---:|---:|---|"]
    for n, periodic, tolerance, iterations, worst in rows:
        t, p = worst["threads"], worst["perturbed"]
        lines.append("| {} | {} | {:g} | {} | {:.1e} | {:.1e} | {:.1e} | {} | {:.1e} | {:.1e} | {:.1e} | {} |".format(
            n, "yes" if periodic else "no", tolerance, "/".join(str(i) for i in iterations), t[0], t[1], t[2],
            "yes" if t[3] else "NO", p[0], p[1], p[2], "yes" if p[3] else "NO"))
    os.makedirs(args.out, exist_ok=True)
    write_atomically(os.path.join(args.out, "table.md"), "\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
