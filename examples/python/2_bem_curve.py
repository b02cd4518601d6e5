#!/usr/bin/env python3
"""Tutorial step 2: the boundary-element ground truth. A load-area curve of surface A: each load P/(E* A0) solved
in turn (warm-started), the contact area by nodes and perimeter-corrected, the spot count, and the areal kappa
(A/A0)/(P/(E* A0 gbar)) that small-load theories predict constant. Plots bem_curve.png into --out.

  python3 examples/python/2_bem_curve.py [--out FOLDER] [--threads N]"""
import numpy as np

import contactbench as cb
from tutorial import arguments, pyplot

args = arguments(__doc__.splitlines()[0])
MODULUS = 100e9 / (1 - 0.3**2)  # E* [Pa] of the paper's material: E = 100 GPa, nu = 0.3
LOADS = np.geomspace(1e-4, 2e-2, 6)  # P/(E* A0), the dimensionless load of every load argument

surface = cb.surface_a(seed=1, threads=args.threads)
gradient = surface.rms_gradient
solver = cb.BemSolver(surface, MODULUS, threads=args.threads)  # the CLI's defaults: tolerance 1e-8
results = solver.solve_loads(LOADS)

print(f"{'P/(E* A0)':>10} {'A/A0':>9} {'nodes':>9} {'spots':>6} {'kappa':>6} {'iterations':>10}")
for load, r in zip(LOADS, results):
    kappa = r.area_fraction_corrected / (load / gradient)
    print(f"{load:>10.3g} {r.area_fraction_corrected:>9.5f} {r.area_fraction:>9.5f} {r.spots:>6} {kappa:>6.3f} "
          f"{r.iterations:>10}")
assert all(r.converged for r in results)
# One load can also be given as a mean pressure in Pa, by keyword only: the same solve.
same = cb.BemSolver(surface, MODULUS, threads=args.threads).solve(mean_pressure=LOADS[0] * MODULUS)
print(f"solve(mean_pressure={LOADS[0] * MODULUS:.4g} Pa): A/A0 = {same.area_fraction_corrected:.5f}, "
      f"load = {same.load:.3g}")

plt = pyplot()
if plt:
    figure, axes = plt.subplots(figsize=(6, 4.5))
    axes.loglog(LOADS, [r.area_fraction_corrected for r in results], "ko-", label="BEM (perimeter-corrected)")
    axes.loglog(LOADS, [r.area_fraction for r in results], "k.:", label="BEM (nodes)")
    axes.set(xlabel="P / (E* A0)", ylabel="A / A0", title="surface A, boundary elements")
    axes.legend()
    figure.savefig(args.out / "bem_curve.png", dpi=120, bbox_inches="tight")
    print(f"wrote {args.out / 'bem_curve.png'}")
