#!/usr/bin/env python3
"""Tutorial step 1: a rough surface and its statistics. The paper's surface A (generated) and a measured AFM
topography (read from data/measured/), their rms height and gradient, spectral moments and Nayak's bandwidth,
and the radially averaged PSD, whose slope gives the Hurst exponent back. Plots psd.png into --out.

  pip install .   (or PYTHONPATH=build/release/python with /usr/bin/python3), then
  python3 examples/python/1_surface.py [--out FOLDER]"""
import pathlib

import numpy as np

import contactbench as cb
from tutorial import arguments, pyplot

args = arguments(__doc__.splitlines()[0])
data = pathlib.Path(__file__).resolve().parents[2] / "data" / "measured"

surfaces = {
    "surface A": cb.surface_a(seed=1, threads=args.threads),  # 256 x 256 over 200 um, periodic, H = 0.5
    "matrix-3 (AFM)": cb.read_topography(data / "matrix-3.txt"),  # sizes and units from the file's header
}
for name, surface in surfaces.items():
    m = surface.moments(threads=args.threads)
    print(f"{name}: {surface}")
    print(f"  Sq = {surface.rms_height:.4g} m, rms gradient = {surface.rms_gradient:.4g}, "
          f"m2x/m2y = {m.m2x / m.m2y:.3f}, Nayak's alpha (x) = {m.alpha_x:.3g}")

# The generator's PSD falls as q^(-2(1+H)) between qr and qs: a line fitted to log C(q) there gives H back.
surface = surfaces["surface A"]
q, c = cb.radial_psd(surface)
band = (q > 2 * cb.paper.surface_a().qr) & (q < 0.5 * surface.grid.nyquist) & (c > 0)
slope = np.polyfit(np.log(q[band]), np.log(c[band]), 1)[0]
print(f"surface A: PSD slope {slope:.2f} between 2 qr and qs/2, so H = {-slope / 2 - 1:.2f} (generated with 0.5)")

plt = pyplot()
if plt:
    figure, axes = plt.subplots(figsize=(6, 4.5))
    for name, s in surfaces.items():
        axes.loglog(*cb.radial_psd(s), label=name)
    axes.set(xlabel="q [1/m]", ylabel="C(q) [m^4]", title="radially averaged PSD")
    axes.legend()
    figure.savefig(args.out / "psd.png", dpi=120, bbox_inches="tight")
    print(f"wrote {args.out / 'psd.png'}")
