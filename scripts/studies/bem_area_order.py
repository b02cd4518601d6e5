#!/usr/bin/python3
"""Convergence order of the BEM contact area in the pixel size, on cases with an exact answer
(docs/theory.md section 9.1). Prints a Markdown table of the errors of the node-count area and of the
perimeter-corrected area, and the observed orders between successive grids.

  - Hertz: a paraboloid h = -r^2/(2R) sampled on a non-periodic grid of 4a a side, a/dx = 8 ... 64.
  - Westergaard: h = D cos(2 pi x/lambda) on a periodic grid, 8 ... 128 points a wavelength, pbar/p* = 0.3.
  - Westergaard refined: the same wave on 16 points, Fourier-refined to 32 ... 256 (what `refine` does).
  - Hertz bump: a periodic band-limited bump, paraboloidal at its crest, on 128 points Fourier-refined to 256
    and 512, 8 loads (a = L/16 ... L/10); and Westergaard over 8 loads: the mean error is the systematic part
    (the order), the rms over loads adds the lattice scatter of a single contact edge.

Run: PYTHONPATH=build/release/python /usr/bin/python3 scripts/studies/bem_area_order.py [threads]
"""
import math
import sys

import numpy as np

import contactbench as cb

THREADS = int(sys.argv[1]) if len(sys.argv) > 1 else 2
E_STAR = 1e11


def hertz_rows():
    radius, a = 1e-3, 16e-6
    load = 4 * E_STAR * a**3 / (3 * radius)  # P [N] for contact radius a
    exact = math.pi * a * a
    rows = []
    for per_radius in (8, 16, 32, 64):
        n = 4 * per_radius
        dx = 4 * a / n
        x = (np.arange(n) - n // 2) * dx
        h = -(x[None, :] ** 2 + x[:, None] ** 2) / (2 * radius)
        s = cb.Surface(np.ascontiguousarray(h), lx=n * dx, periodic=False)
        r = cb.BemSolver(s, E_STAR, tolerance=1e-12, threads=THREADS).solve(mean_pressure=load / (n * dx) ** 2)
        area0 = (n * dx) ** 2
        rows.append((f"a/dx = {per_radius}", dx / a, r.area_fraction * area0 / exact - 1,
                     r.area_fraction_corrected * area0 / exact - 1))
    return rows


def westergaard_exact(ratio):
    # contact strips of half-width a: sin^2(pi a/lambda) = pbar/p*; A/A0 = 2a/lambda
    return 2 * math.asin(math.sqrt(ratio)) / math.pi


def wave(n, wavelength, amplitude):
    x = np.arange(n) * wavelength / n
    return np.ascontiguousarray(np.tile(amplitude * np.cos(2 * math.pi * x / wavelength), (n, 1)))


def westergaard_rows(refined):
    wavelength, amplitude, ratio = 1e-4, 1e-7, 0.3
    p_star = math.pi * E_STAR * amplitude / wavelength
    exact = westergaard_exact(ratio)
    rows = []
    for n in (32, 64, 128, 256) if refined else (8, 16, 32, 64, 128):
        if refined:
            base = cb.Surface(wave(16, wavelength, amplitude), lx=wavelength, periodic=True)
            s = cb.refine(base, n)
        else:
            s = cb.Surface(wave(n, wavelength, amplitude), lx=wavelength, periodic=True)
        r = cb.BemSolver(s, E_STAR, tolerance=1e-12, threads=THREADS).solve(mean_pressure=ratio * p_star)
        rows.append((f"{n} points a wavelength", 1 / n, r.area_fraction / exact - 1,
                     r.area_fraction_corrected / exact - 1))
    return rows


def bump(n, length, radius):
    # periodic, band-limited, a paraboloid -r^2/(2R) at its crest to O(r^6): h = -(L^2/(4 pi^2 R)) sum over x, y
    # of (4/3)(1 - cos u) - (1/12)(1 - cos 2u), u = 2 pi x/L
    u = 2 * math.pi * np.arange(n) / n
    u = np.where(u > math.pi, u - 2 * math.pi, u)
    f = (4 / 3) * (1 - np.cos(u)) - (1 / 12) * (1 - np.cos(2 * u))
    return np.ascontiguousarray(-(length**2 / (4 * math.pi**2 * radius)) * (f[None, :] + f[:, None]))


def hertz_bump_rows(coarse, radii):
    """Mean and spread over several loads of the area errors, the bump sampled on `coarse` points and
    Fourier-refined to 2 and 4 times as many (what `refine` and `extrapolate` do)."""
    radius, length = 1e-3, 1e-3 / 16 * 16  # L = 1 mm
    base = cb.Surface(bump(coarse, length, radius), lx=length, periodic=True)
    rows = []
    for factor in (1, 2, 4):
        n = coarse * factor
        s = base if factor == 1 else cb.refine(base, n)
        solver = cb.BemSolver(s, E_STAR, tolerance=1e-12, threads=THREADS)
        nodes, corr = [], []
        for a in radii:
            load = 4 * E_STAR * a**3 / (3 * radius)
            r = solver.solve(mean_pressure=load / length**2)
            exact = math.pi * a * a / length**2
            nodes.append(r.area_fraction / exact - 1)
            corr.append(r.area_fraction_corrected / exact - 1)
        rows.append((n, np.array(nodes), np.array(corr)))
    return rows


def order(e0, e1):
    return math.log2(abs(e0 / e1)) if e0 and e1 else float("nan")


def table(title, rows):
    print(f"\n{title}\n")
    print("| grid | dx/scale | error nodes | order | error corrected | order |")
    print("|---|---:|---:|---:|---:|---:|")
    for k, (name, h, nodes, corr) in enumerate(rows):
        on = f"{order(rows[k - 1][2], nodes):.2f}" if k else ""
        oc = f"{order(rows[k - 1][3], corr):.2f}" if k else ""
        print(f"| {name} | {h:.4g} | {nodes:+.3e} | {on} | {corr:+.3e} | {oc} |")


print("\nHertz bump (periodic, L = 1 mm, R = 1 mm), coarse 128 points, a = L/16 ... L/10 (8 loads)\n")
print("| n | a/dx | mean error nodes | rms | mean error corrected | rms | Richardson p=1 from n/2 mean | rms |")
print("|---:|---|---:|---:|---:|---:|---:|---:|")
radii = np.linspace(1e-3 / 16, 1e-3 / 10, 8)
rows = hertz_bump_rows(128, radii)
for k, (n, nodes, corr) in enumerate(rows):
    ext = 2 * nodes - rows[k - 1][1] if k else None
    e = f"{ext.mean():+.3e} | {np.sqrt((ext**2).mean()):.3e}" if k else " | "
    print(f"| {n} | {radii[0] * n / 1e-3:.0f}-{radii[-1] * n / 1e-3:.0f} | {nodes.mean():+.3e} | "
          f"{np.sqrt((nodes**2).mean()):.3e} | {corr.mean():+.3e} | {np.sqrt((corr**2).mean()):.3e} | {e} |")
table("Hertz (R = 1 mm, a = 16 um, box 4a, non-periodic)", hertz_rows())
table("Westergaard (pbar/p* = 0.3, periodic, sampled)", westergaard_rows(False))
table("Westergaard (16 points Fourier-refined)", westergaard_rows(True))

print("\nWestergaard, mean and rms over 8 loads pbar/p* = 0.1 ... 0.6 (periodic, sampled)\n")
print("| points a wavelength | mean error nodes | rms | mean error corrected | rms | Richardson p=1 from n/2 mean | rms |")
print("|---:|---:|---:|---:|---:|---:|---:|")
wavelength, amplitude = 1e-4, 1e-7
p_star = math.pi * E_STAR * amplitude / wavelength
ratios = np.linspace(0.1, 0.6, 8)
previous = None
for n in (16, 32, 64, 128, 256):
    s = cb.Surface(wave(n, wavelength, amplitude), lx=wavelength, periodic=True)
    solver = cb.BemSolver(s, E_STAR, tolerance=1e-12, threads=THREADS)
    nodes, corr = [], []
    for ratio in ratios:
        r = solver.solve(mean_pressure=ratio * p_star)
        nodes.append(r.area_fraction / westergaard_exact(ratio) - 1)
        corr.append(r.area_fraction_corrected / westergaard_exact(ratio) - 1)
    nodes, corr = np.array(nodes), np.array(corr)
    ext = 2 * nodes - previous if previous is not None else None
    e = f"{ext.mean():+.3e} | {np.sqrt((ext**2).mean()):.3e}" if ext is not None else " | "
    print(f"| {n} | {nodes.mean():+.3e} | {np.sqrt((nodes**2).mean()):.3e} | {corr.mean():+.3e} | "
          f"{np.sqrt((corr**2).mean()):.3e} | {e} |")
    previous = nodes
