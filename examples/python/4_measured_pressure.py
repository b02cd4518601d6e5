#!/usr/bin/env python3
"""Tutorial step 4: a measured surface under load. An AFM topography exported by Gwyddion
(data/measured/matrix-3.txt: 256 x 256 over 10 um, not periodic) pressed by a rigid flat: the BEM's contact
statistics, and the heights and pressure field drawn to measured_pressure.png in --out.

  python3 examples/python/4_measured_pressure.py [--out FOLDER] [--threads N]"""
import pathlib

import numpy as np

import contactbench as cb
from tutorial import arguments, pyplot

args = arguments(__doc__.splitlines()[0])

MODULUS = 100e9 / (1 - 0.3**2)  # E* [Pa]
LOAD = 0.01  # P/(E* A0)

path = pathlib.Path(__file__).resolve().parents[2] / "data" / "measured" / "matrix-3.txt"
surface = cb.read_topography(path)  # sizes and units from the file's header; not periodic
print(surface, f"Sq = {surface.rms_height:.3e} m")
result = cb.BemSolver(surface, MODULUS, threads=args.threads).solve(LOAD)  # P/(E* A0)
pressure = result.pressure  # [Pa], shape (ny, nx): rows are y, as the heights
print(f"A/A0 = {result.area_fraction_corrected:.4f} (nodes {result.area_fraction:.4f}), {result.spots} spots, "
      f"max p = {result.max_pressure:.3e} Pa, {result.iterations} iterations, converged {result.converged}, "
      f"{result.seconds:.2f} s")
assert pressure.shape == surface.heights.shape and np.isclose(pressure.mean(), LOAD * MODULUS, rtol=1e-8)

plt = pyplot()
if plt:
    extent = [0, surface.lx * 1e6, 0, surface.ly * 1e6]  # [um]; origin="lower" puts row 0 (y = 0) at the bottom
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    image = left.imshow(surface.heights * 1e9, origin="lower", extent=extent, cmap="viridis")
    figure.colorbar(image, ax=left, label="height [nm]")
    # A few pixels carry far more than the rest (the tallest asperities): the colour scale stops at the 99th
    # percentile of the contact pressures so that the contact spots show.
    top = np.percentile(pressure[pressure > 0], 99) / 1e9
    image = right.imshow(pressure / 1e9, origin="lower", extent=extent, cmap="magma", vmax=top)
    figure.colorbar(image, ax=right, label="pressure [GPa] (clipped at the 99th percentile)")
    for axes, title in [(left, "heights"), (right, f"pressure at P/(E* A0) = {LOAD}")]:
        axes.set(xlabel="x [um]", ylabel="y [um]", title=title)
    figure.tight_layout()
    figure.savefig(args.out / "measured_pressure.png", dpi=120, bbox_inches="tight")
    print(f"wrote {args.out / 'measured_pressure.png'}")
