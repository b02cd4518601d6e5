#!/usr/bin/python3
"""The peer's side of the sphere comparisons (scripts/peers/side_by_side.py, docs/peers.md): a paraboloid on a
periodic grid, solved by ContactMechanics / Adhesion; reads the heights from a .npy file (rows along y, as
contactbench's), prints one JSON document on stdout. Run with the peer on PYTHONPATH:

  PYTHONPATH=PEER /usr/bin/python3 scripts/peers/contactmechanics_sphere.py adhesion HEIGHTS.npy --size L
      --modulus E --work W --range RHO --indentations=D1,D2,...
  PYTHONPATH=PEER /usr/bin/python3 scripts/peers/contactmechanics_sphere.py plastic HEIGHTS.npy --size L
      --modulus E --hardness H --loads P1,P2,...

adhesion: Adhesion's exponential interaction V(g) = -w exp(-g/rho) (attraction (w/rho) exp(-g/rho), the
project's exponential law) with the bound-constrained system (BoundedSmoothContactSystem, L-BFGS-B, its
default), under displacement control along the given indentations (the apex's penetration with no
deformation, [m]), each state starting from the last. Solved in units of um and MPa (force uN) so that
L-BFGS-B's absolute tolerances see numbers of order one; reported in SI. Per state: net force [N], contact
area fraction (gap 0), mean gap [m], iterations, seconds.
plastic: ContactMechanics' PlasticSystem (make_plastic_system, PlasticTopography with the hardness) under load
control, a fresh system per load (monotonic loading from the flat state), constrained conjugate gradients with
the hardness cap. Per load: contact and plastic area fractions (plastic: the pressure at the cap), iterations,
seconds.
"""
import argparse
import json
import time

import numpy as np

UM = 1e-6  # m
MPA = 1e6  # Pa
UN = UM * UM * MPA  # force unit of (um, MPa): 1e-6 N


def adhesion(args, heights):
    from Adhesion.Interactions import Exponential
    from Adhesion.System import BoundedSmoothContactSystem
    from ContactMechanics import PeriodicFFTElasticHalfSpace
    from SurfaceTopography import Topography

    n = heights.shape[0]
    size = args.size / UM
    h = np.ascontiguousarray(heights.T) / UM
    topography = Topography(h, physical_sizes=(size, size), periodic=True)
    substrate = PeriodicFFTElasticHalfSpace((n, n), args.modulus / MPA, (size, size))
    interaction = Exponential(args.work / (MPA * UM), args.range / UM)
    system = BoundedSmoothContactSystem(substrate, interaction, topography)
    pixel = (size / n) ** 2
    gtol = args.gtol * (args.work / args.range / MPA) * pixel  # projected-gradient tolerance: a pixel force
    h_max = h.max()
    displacement = None
    states = []
    for indentation in args.indentations:
        offset = indentation / UM - h_max  # the rigid surface is heights + offset; gap = u - (h + offset)
        begin = time.perf_counter()
        result = system.minimize_proxy(offset=offset, initial_displacements=displacement,
                                       options=dict(gtol=gtol, ftol=0, maxiter=100000, maxcor=10))
        seconds = time.perf_counter() - begin
        displacement = result.x.reshape(system.substrate.nb_subdomain_grid_pts)
        states.append({"indentation": indentation, "force": float(system.compute_normal_force()) * UN,
                       "contact_fraction": float(system.compute_nb_contact_pts()) / n**2,
                       "mean_gap": float(np.mean(system.gap)) * UM,
                       "iterations": int(result.nit), "converged": bool(result.success),
                       "message": str(result.message), "seconds": seconds})
    return {"states": states}


def plastic(args, heights):
    from ContactMechanics import PeriodicFFTElasticHalfSpace
    from ContactMechanics.Factory import make_plastic_system
    from SurfaceTopography import PlasticTopography, Topography

    n = heights.shape[0]
    size = args.size / UM
    h = np.ascontiguousarray(heights.T) / UM
    answers = []
    for load in args.loads:  # P/(E* A0)
        topography = Topography(h.copy(), physical_sizes=(size, size), periodic=True)
        surface = PlasticTopography(topography, args.hardness / MPA)
        substrate = PeriodicFFTElasticHalfSpace((n, n), args.modulus / MPA, (size, size))
        system = make_plastic_system(substrate=substrate, surface=surface)
        force = load * args.modulus / MPA * size * size
        begin = time.perf_counter()
        result = system.minimize_proxy(external_force=force, pentol=args.pentol,
                                       forcetol=args.forcetol * force / n**2, maxiter=100000)
        seconds = time.perf_counter() - begin
        forces = result.jac
        cap = args.hardness / MPA * (size / n) ** 2  # the hardness as a pixel force
        # Plastic: the pressure at the cap (to round-off). The solver's own `plastic` flags every point of
        # negative gap, which includes elastic contact points inside its penetration tolerance; it is reported
        # apart as penetrating_fraction.
        answers.append({"load": load, "contact_fraction": float(np.count_nonzero(forces > 0)) / n**2,
                        "plastic_fraction": float(np.count_nonzero(forces >= cap * (1 - 1e-9))) / n**2,
                        "penetrating_fraction": float(np.count_nonzero(result.plastic)) / n**2,
                        "iterations": int(result.nit), "converged": bool(result.success), "seconds": seconds})
    return {"loads": answers}


def floats(text):
    return [float(item) for item in text.split(",")]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", choices=["adhesion", "plastic"])
    parser.add_argument("heights", help=".npy, [m], rows along y, square")
    parser.add_argument("--size", type=float, required=True, help="[m]")
    parser.add_argument("--modulus", type=float, required=True, help="E* [Pa]")
    parser.add_argument("--work", type=float, help="w [J/m^2]")
    parser.add_argument("--range", type=float, help="rho [m]")
    parser.add_argument("--gtol", type=float, default=1e-6,
                        help="L-BFGS-B's projected-gradient tolerance relative to the peak stress's pixel force")
    parser.add_argument("--indentations", type=floats, help="[m], comma-separated (negative: apart)")
    parser.add_argument("--hardness", type=float, help="[Pa]")
    parser.add_argument("--loads", type=floats, help="P/(E* A0), comma-separated")
    parser.add_argument("--pentol", type=float, default=None, help="[um]; default ContactMechanics' Sq/(10 n)")
    parser.add_argument("--forcetol", type=float, default=1e-5,
                        help="largest pixel force outside the contact, relative to the mean pixel force")
    args = parser.parse_args()
    heights = np.load(args.heights)
    import ContactMechanics
    begin = time.perf_counter()
    answer = adhesion(args, heights) if args.case == "adhesion" else plastic(args, heights)
    answer["seconds"] = time.perf_counter() - begin
    answer["peer_version"] = ContactMechanics.__version__
    print(json.dumps(answer))


if __name__ == "__main__":
    main()
