#!/usr/bin/python3
"""The equal-accuracy yardstick of bench/bench_bem_solvers.cpp for one case, with the errors shown: which
tolerance a solver needs for its contact area (node count) within 1e-4 relative and its pressure within 1e-4
relative L2 of a tight reference solve, and which of the two binds at each rung (docs/solvers.md, "Stopping
criteria and what the tolerance buys" and "Growth on the rough surface, at a fixed tolerance").

The case is the benchmark's (the same surfaces, bit for bit, and the same nominal loads): surface_a, the
paper's surface A refined to n x n; h08, H = 0.8 with roll-off at 4 (2 pi/L), pixel-rough at every n; the load
P/(E* A0) = (contact/100) gbar/2. Or any topography file with --file and --load. Each rung is a cold solve
(a new solver), like the benchmark's; the reference is plain Polonsky-Keer at 1e-12 unless told otherwise
(at 2048^2 and 30 % contact it takes minutes; `--reference-solver active_set --reference-tolerance 1e-11`
takes seconds and gave the same errors to the printed digits on the h08 surface at 2048^2, periodic, 10 and
30 %).

Prints one Markdown row per rung: tolerance, iterations, seconds, converged, area error (signed: + too many
nodes), pressure error; stops at the first rung that meets the accuracy (--all: runs every rung).

Run: PYTHONPATH=build/release/python /usr/bin/python3 scripts/studies/tolerance_ladder.py \
       --surface h08 --n 2048 --contact 10 --periodic [--solver active_set] [--threads 2]
"""
import argparse
import math
import sys

import numpy as np

import contactbench as cb

E_STAR = 100e9 / (1 - 0.3 * 0.3)  # the benchmark's modulus [Pa]
PAPER_SIZE = 200e-6  # the paper's 256 x 256 grid is 200 um a side


def case_surface(kind, n, threads):
    """The benchmark's surfaces (bench/bench_bem_solvers.cpp, case_surface)."""
    if kind == "surface_a":
        paper = cb.Grid(nx=256, ny=256, lx=PAPER_SIZE, ly=PAPER_SIZE)
        psd = cb.SelfAffinePsd(sigma=0.5e-6, hurst=0.5, qr=3.14e4)
        return cb.generate_surface(paper, psd, 1, refine=n, threads=threads)
    fine = cb.Grid(nx=n, ny=n, lx=PAPER_SIZE, ly=PAPER_SIZE)
    psd = cb.SelfAffinePsd(sigma=0.5e-6, hurst=0.8, qr=4 * 2 * math.pi / PAPER_SIZE)
    return cb.generate_surface(fine, psd, 2, threads=threads)


def solve(surface, periodic, load, solver, tolerance, threads, single):
    bem = cb.BemSolver(surface, E_STAR, tolerance=tolerance, max_iterations=100000, solver=solver,
                       periodic=periodic, precision="single" if single else "double", threads=threads)
    result = bem.solve(load)
    return result, np.array(result.pressure)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--surface", choices=["surface_a", "h08"], default="h08")
    parser.add_argument("--n", type=int, default=256, help="points a side (benchmark surfaces)")
    parser.add_argument("--contact", type=float, default=10, help="nominal contact %% (benchmark load)")
    parser.add_argument("--file", help="a topography file instead of a benchmark surface")
    parser.add_argument("--load", type=float, help="P/(E* A0) (required with --file)")
    boundary = parser.add_mutually_exclusive_group(required=True)
    boundary.add_argument("--periodic", action="store_true")
    boundary.add_argument("--non-periodic", action="store_true")
    parser.add_argument("--solver", default="active_set")
    parser.add_argument("--float", action="store_true", help="the solver in single precision (to 1e-6)")
    parser.add_argument("--reference-solver", default="polonsky_keer")
    parser.add_argument("--reference-tolerance", type=float, default=1e-12)
    parser.add_argument("--accuracy", type=float, default=1e-4, help="relative, area and L2 pressure")
    parser.add_argument("--all", action="store_true", help="run every rung, not only up to the first met")
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    if args.file and args.load is None:
        parser.error("--file needs --load")
    if args.load is not None and not (args.load > 0 and math.isfinite(args.load)):
        parser.error(f"--load: expected a finite P/(E* A0) > 0, got {args.load}")
    if not 0 < args.contact < 100:
        parser.error(f"--contact: expected a nominal contact in (0, 100) %, got {args.contact}")
    if args.n < 2:
        parser.error(f"--n: expected at least 2 points a side, got {args.n}")
    # The reference must be far tighter than the rungs it judges (and the errors' 1e-4).
    if not 1e-13 <= args.reference_tolerance <= 1e-8:
        parser.error(f"--reference-tolerance: expected 1e-13 to 1e-8, got {args.reference_tolerance}")
    if not 0 < args.accuracy < 1:
        parser.error(f"--accuracy: expected a relative accuracy in (0, 1), got {args.accuracy}")
    try:
        # Unknown solver names fail here, before the reference solve (the message lists the known ones).
        tiny = cb.Surface(np.zeros((2, 2)), lx=1e-6, periodic=True)
        for option, name in (("--solver", args.solver), ("--reference-solver", args.reference_solver)):
            try:
                cb.BemSolver(tiny, E_STAR, solver=name)
            except cb.Error as error:
                parser.error(f"{option}: {error}")
        run(args)
    except cb.Error as error:  # the library's message names the file, key or value
        sys.exit(f"tolerance_ladder.py: {error}")


def run(args):
    if args.file:
        surface = cb.read_topography(args.file)
        load, label = args.load, args.file
    else:
        # As the benchmark: the load from the rms gradient of the surface as solved (periodic or not; the
        # non-periodic estimate differs in the third digit).
        surface = case_surface(args.surface, args.n, args.threads).with_periodic(bool(args.periodic))
        gbar = cb.spectral_moments(surface, threads=args.threads).rms_gradient
        load = args.contact / 100 * gbar / 2
        label = f"{args.surface}, {args.n}^2, contact {args.contact:g} %"
    periodic = bool(args.periodic)
    reference, p_ref = solve(surface, periodic, load, args.reference_solver, args.reference_tolerance,
                             args.threads, False)
    if not reference.converged:
        sys.exit("tolerance_ladder.py: the reference solve did not converge (its cap is 100000 iterations)")
    nodes_ref, norm_ref = reference.contact_points, np.linalg.norm(p_ref)
    print(f"{label}, {'periodic' if periodic else 'non-periodic'}, load {load:.6g}; reference "
          f"{args.reference_solver} at {args.reference_tolerance:g}: {nodes_ref} nodes, "
          f"{reference.iterations} iterations, {reference.seconds:.3g} s")
    print(f"\n| {args.solver} tolerance | iterations | seconds | converged | area error | pressure error |")
    print("|---|---|---|---|---|---|")
    last_exponent = 6 if args.float else 11
    for exponent in range(3, last_exponent + 1):
        tolerance = 10.0**-exponent
        result, p = solve(surface, periodic, load, args.solver, tolerance, args.threads, args.float)
        area_error = (result.contact_points - nodes_ref) / nodes_ref  # signed: + too many nodes
        pressure_error = np.linalg.norm(p - p_ref) / norm_ref
        met = abs(area_error) <= args.accuracy and pressure_error <= args.accuracy
        print(f"| {tolerance:.0e}{' (met)' if met else ''} | {result.iterations} | {result.seconds:.3g} | "
              f"{int(result.converged)} | {area_error:+.2e} | {pressure_error:.2e} |", flush=True)
        if met and not args.all:
            break


if __name__ == "__main__":
    main()
