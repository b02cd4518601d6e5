#!/usr/bin/python3
"""The peer's whole command: reads a contactbench surface file and solves its non-adhesive periodic contact with
ContactMechanics (its PeriodicFFTElasticHalfSpace and constrained conjugate gradients, Polonsky-Keer), one
JSON line per load on stdout. What `contactbench bem FILE --periodic --loads ...` does, for the side-by-side
timing (scripts/peers/side_by_side.py, docs/peers.md). Run with the peer on PYTHONPATH:

  PYTHONPATH=/work/peer/site /usr/bin/python3 scripts/peers/contactmechanics_bem.py FILE --loads 0.001 0.004

Loads are the project's P/(E* A0); E* defaults to the CLI's (E = 100 GPa, nu = 0.3). The tolerances are
ContactMechanics' own criteria: pentol [m] (its default: Sq / (10 n)), forcetol [N per pixel] given here
relative to the mean pixel force of the load (so that it means the same at every load and unit), thermotol its
default. The file is the project's text format (`# contactbench surface v1`, rows along y), read by numpy.
"""
import argparse
import json
import sys
import time

START = time.perf_counter()

import numpy as np  # noqa: E402


def read_contactbench_surface(path):
    """Heights [m] (rows along y) and the lateral sizes [m] from the project's text format."""
    with open(path) as f:
        first = f.readline().strip()
        second = f.readline().strip()
    if first != "# contactbench surface v1":
        sys.exit(f"{path}: not a contactbench surface file (first line {first!r})")
    fields = dict(item.split("=", 1) for item in second.lstrip("# ").split())
    heights = np.loadtxt(path, comments="#")
    if heights.shape != (int(fields["ny"]), int(fields["nx"])) or fields.get("unit", "m") != "m":
        sys.exit(f"{path}: header says nx={fields['nx']} ny={fields['ny']} unit={fields.get('unit')}, "
                 f"read {heights.shape}")
    return heights, float(fields["lx"]), float(fields["ly"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file")
    parser.add_argument("--loads", type=float, nargs="+", required=True, help="P/(E* A0)")
    parser.add_argument("--modulus", type=float, default=100e9 / (1 - 0.3**2), help="E* [Pa]")
    parser.add_argument("--pentol", type=float, default=None, help="[m]; default ContactMechanics' Sq/(10 n)")
    parser.add_argument("--forcetol", type=float, default=1e-5,
                        help="largest pixel force outside the contact, relative to the mean pixel force")
    parser.add_argument("--maxiter", type=int, default=100000)
    parser.add_argument("--pressure-out", help="write each load's pressure [Pa] (rows along y) to PREFIX_<k>.npy")
    args = parser.parse_args()

    from ContactMechanics import PeriodicFFTElasticHalfSpace, make_system
    from SurfaceTopography import Topography
    import ContactMechanics

    heights, lx, ly = read_contactbench_surface(args.file)
    # ContactMechanics indexes heights[ix, iy]: the transpose of the file's rows along y.
    topography = Topography(np.ascontiguousarray(heights.T), physical_sizes=(lx, ly), periodic=True)
    substrate = PeriodicFFTElasticHalfSpace(topography.nb_grid_pts, args.modulus, topography.physical_sizes)
    system = make_system(substrate=substrate, surface=topography)
    nodes = heights.size
    pixel_area = lx * ly / nodes
    for k, load in enumerate(args.loads):
        total_force = load * args.modulus * lx * ly
        forcetol = args.forcetol * total_force / nodes
        begin = time.perf_counter()
        result = system.minimize_proxy(external_force=total_force, pentol=args.pentol, forcetol=forcetol,
                                       maxiter=args.maxiter)
        seconds = time.perf_counter() - begin
        forces = result.jac
        gap = result.x - (topography.heights() + result.offset)  # ContactMechanics: gap = u - (h + offset)
        if args.pressure_out:
            np.save(f"{args.pressure_out}_{k}.npy", np.ascontiguousarray(forces.T) / pixel_area)
        print(json.dumps({
            "load": load, "area_fraction": float(np.count_nonzero(forces > 0)) / nodes,
            "mean_pressure": float(forces.sum() / (lx * ly)), "max_pressure": float(forces.max() / pixel_area),
            "mean_gap": float(gap.mean()),
            "iterations": int(result.nit), "converged": bool(result.success), "solve_seconds": seconds,
            "seconds_since_start": time.perf_counter() - START, "peer_version": ContactMechanics.__version__,
        }), flush=True)


if __name__ == "__main__":
    main()
