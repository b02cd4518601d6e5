#!/usr/bin/env python3
"""Tutorial step 3: the cheap models against the ground truth. On the paper's surface A, the multi-plateaus
model and the analytic theories (GW-McCool, BGT, the BGT linear law, Persson) at a few loads, each A/A0 with
its error against the BEM's, and the load-area plot load_area_surface_a.png into --out.

  python3 examples/python/3_compare_theories.py [--out FOLDER] [--threads N]   (a few seconds; the BEM dominates)"""
import math

import contactbench as cb
from tutorial import arguments, pyplot

args = arguments(__doc__.splitlines()[0])

MODULUS = 100e9 / (1 - 0.3**2)  # E* [Pa] of the paper's material: E = 100 GPa, nu = 0.3
LOADS = [1e-3, 3e-3, 1e-2, 3e-2]  # P/(E* A0)

surface = cb.surface_a(seed=1, threads=args.threads)  # 256 x 256 over 200 um, periodic
moments = surface.moments()
sweep = cb.sweep(surface)  # every distinct height: the plateau model's integral is exact
curves = {
    "plateau": cb.plateau_curve_at_loads(sweep, cb.plateau_model(sweep), LOADS),
    "gw_mccool": cb.gw_mccool_curve(moments, LOADS),
    "bgt": cb.bgt_curve(moments, LOADS),
    "bgt_linear": cb.bgt_linear_curve(moments, LOADS),
    "persson": cb.persson_curve(moments, LOADS),
}
bem = [r.area_fraction_corrected for r in cb.BemSolver(surface, MODULUS, threads=args.threads).solve_loads(LOADS)]

print("A/A0 of surface A (BEM: perimeter-corrected node count)")
print(f"{'P/(E* A0)':>10} {'bem':>9}" + "".join(f" {name:>12}" for name in curves))
for k, load in enumerate(LOADS):
    cells = "".join(f" {c.area_fraction[k]:>6.4f} {c.area_fraction[k] / bem[k] - 1:+4.0%}" for c in curves.values())
    print(f"{load:>10.0e} {bem[k]:>9.5f}" + cells)
print("(each model's A/A0 and its relative error against the BEM)")

plt = pyplot()
if plt:
    figure, axes = plt.subplots(figsize=(6, 4.5))
    axes.plot(LOADS, bem, "ko", label="bem")
    for name, curve in curves.items():
        axes.plot(curve.load, curve.area_fraction, label=name)
    axes.set(xscale="log", yscale="log", xlabel="P / (E* A0)", ylabel="A / A0", title="surface A")
    axes.legend()
    figure.savefig(args.out / "load_area_surface_a.png", dpi=120, bbox_inches="tight")
    print(f"wrote {args.out / 'load_area_surface_a.png'}")
assert all(math.isfinite(a) for a in bem)
