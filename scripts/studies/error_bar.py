#!/usr/bin/env python3
"""Calibration of the BEM reference's error bar (issue 40; docs/studies.md "Error bar of the reference").

Many periodic surfaces (Hurst 0.3-0.9, several seeds, two bands, isotropic and anisotropic), each generated on a
coarse grid of `--base` points a side (its spectrum cut at that grid's Nyquist, so every finer grid is the same
surface, Fourier-refined: docs/theory.md section 2), solved by the BEM at every load of 1e-4 ... 5e-2 on
base, 2 base, ... up to `--truth` points a side. For every case (surface x load) and every error estimate of
bem/grid_convergence.hpp (gci3: three grids n, 2n, 4n, the observed order clamped to [0.5, 1], Roache's factor
1.25 within 10 % of order 1, else 3; gci2: two grids 2n, 4n at the formal order 1, factor 3), of variants that
failed (gci3_roache: Roache's GCI at the observed order; gci3_fine: that bar on the 4n grid's count; gci_ext:
the bar on the change of the order-1 extrapolates) and of the former |extrapolated - corrected(4n)|, the estimate
made from the grids n = base is compared with the truth:

  truth = the three-grid Richardson extrapolation with the observed order from truth/4, truth/2 and truth
          points a side (when that order is outside [0.5, 2]: the order-1 extrapolation of the two finest);
          its own uncertainty is quoted from the spread of three independent truths (that one, the order-1
          extrapolation of the two finest, the perimeter-corrected area of the finest).

Coverage = fraction of cases whose true error |value - truth| is inside the bar; over-estimation = bar / true
error (median per load band). Writes results/studies/error_bar/{table.md, cases.csv, estimate.gp, estimate.png,
estimate.svg}.

Usage: PYTHONPATH=build/release/python /usr/bin/python3 scripts/studies/error_bar.py [--threads 2]
       [--base 64] [--truth 1024] [--seeds 2] [--reuse]
(--reuse reads the solves back from cases.csv's raw columns, to redo the analysis without solving.)
"""
import argparse
import math
import os
import platform
import subprocess
import sys
import time

from study_common import ROOT, gnuplot, write_atomically

OUT = os.path.join("results", "studies", "error_bar")
LOADS = [1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 5e-2]
BANDS = [("low", 1e-4, 3e-4), ("middle", 1e-3, 3e-3), ("high", 1e-2, 5e-2)]
LENGTH = 200e-6  # the paper's L (docs/theory.md section 2)
SIGMA = 0.5e-6
ESTAR = 1e11

# Surfaces: (name, Hurst, qr in units of 2 pi/L, qs as a fraction of the base grid's Nyquist, anisotropy m2x/m2y)
FAMILIES = [
    ("H0.3", 0.3, 4, 1.0, 1.0),
    ("H0.5", 0.5, 4, 1.0, 1.0),
    ("H0.7", 0.7, 4, 1.0, 1.0),
    ("H0.9", 0.9, 4, 1.0, 1.0),
    ("H0.5 narrow", 0.5, 8, 0.5, 1.0),  # band qr = 8 q0 ... qs = Nyquist/2: fewer, larger spots
    ("H0.6 aniso 3", 0.6, 4, 1.0, 3.0),
]


# --- the estimates, as bem/grid_convergence.cpp computes them (the C++ test tests/test_error_bar.cpp checks the
#     two against each other on the same numbers) ---
SMALLEST_ORDER, LARGEST_ORDER = 0.5, 2.0
FACTOR_THREE, FACTOR_TWO = 1.25, 3.0


def gci3_roache(coarse, medium, fine):
    """Roache's grid convergence index from three grids of ratio 2 at the observed order (not the code's):
    (value, bar, order).
    value = the finest grid extrapolated at the observed order; bar = 1.25 |fine - medium| / (2^p - 1), the GCI
    of the finest grid, applied to the extrapolated value as well (it contains the fine grid's value: see docs)."""
    d21, d32 = medium - coarse, fine - medium
    if d21 == 0 or d32 == 0 or d21 * d32 < 0:  # oscillating or flat: no observed order
        p = math.nan
    else:
        p = math.log(d21 / d32) / math.log(2)
    if p == p and SMALLEST_ORDER <= p <= LARGEST_ORDER:
        return fine + d32 / (2**p - 1), FACTOR_THREE * abs(d32) / (2**p - 1), p
    # No trusted order: the formal order 1, the factor 3 on the largest difference (Eca and Hoekstra 2014)
    return fine + d32, FACTOR_TWO * max(abs(d21), abs(d32)), p


def gci3(coarse, medium, fine):
    """As bem/grid_convergence.cpp: Roache's GCI as Oberkampf and Roy apply it (2010, section 8.7): the order used
    min(max(0.5, p), formal order 1); the factor 1.25 only when the observed order is within 10 % of the formal
    one, else 3; no monotone convergence, or an order above 2: order 1 and 3 x the largest difference.
    (value, bar, order)."""
    d21, d32 = medium - coarse, fine - medium
    if d21 == 0 or d32 == 0 or d21 * d32 < 0:
        return fine + d32, FACTOR_TWO * max(abs(d21), abs(d32)), math.nan
    p = math.log(d21 / d32) / math.log(2)
    if p > LARGEST_ORDER:  # far above the formal order: the last step is anomalously small
        return fine + d32, FACTOR_TWO * max(abs(d21), abs(d32)), p
    used = min(max(p, SMALLEST_ORDER), 1.0)
    factor = FACTOR_THREE if abs(p - 1) <= 0.1 else FACTOR_TWO
    return fine + d32 / (2**used - 1), factor * abs(d32) / (2**used - 1), p


def gci_extrapolates(coarse, medium, fine, factor):
    """The two-grid GCI applied to the order-1 extrapolates of the two pairs: value = 2 fine - medium, bar =
    factor |(2 fine - medium) - (2 medium - coarse)| (the extrapolates' remaining error assumed of order 1)."""
    value = 2 * fine - medium
    return value, factor * abs(value - (2 * medium - coarse))


def gci2(medium, fine):
    """Two grids at the formal order 1 and factor 3: (value, bar)."""
    d = fine - medium
    return fine + d, FACTOR_TWO * abs(d)


# --- the solves ---
def solve_case(cb, family, seed, base, truth, threads):
    name, hurst, qr, qs_fraction, aniso = family
    grid = cb.Grid(nx=base, ny=base, lx=LENGTH, ly=LENGTH, periodic=True)
    nyquist = math.pi * base / LENGTH
    psd = cb.SelfAffinePsd(sigma=SIGMA, hurst=hurst, qr=qr * 2 * math.pi / LENGTH, qs=qs_fraction * nyquist,
                           anisotropy=aniso)
    surface = cb.generate_surface(grid, psd, seed, threads=threads)
    rows = {}
    n = base
    while n <= truth:
        s = surface if n == base else cb.refine(surface, n, threads=threads)
        solver = cb.BemSolver(s, ESTAR, threads=threads)
        results = solver.solve_loads(LOADS)
        for r in results:
            if not r.converged:
                print("not converged: {} seed {} n {} load {}".format(name, seed, n, r.load), file=sys.stderr)
        rows[n] = [(r.area_fraction, r.area_fraction_corrected, r.converged) for r in results]
        n *= 2
    return rows


def stamp():
    commit = subprocess.run(["git", "rev-parse", "--short=12", "HEAD"], capture_output=True, text=True,
                            cwd=ROOT).stdout.strip()
    dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], capture_output=True,
                           text=True, cwd=ROOT).stdout.strip()
    cpu = "unknown cpu"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return "commit {}{}, {}, {} ({})".format(commit, " (with uncommitted changes)" if dirty else "",
                                             time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
                                             platform.node(), cpu)


def truth_of(grids, k, truth):
    a, b, c = (grids[truth // 4][k][0], grids[truth // 2][k][0], grids[truth][k][0])
    d21, d32 = b - a, c - b
    p = math.log(d21 / d32) / math.log(2) if d21 * d32 > 0 else math.nan
    first = 2 * c - b
    if p == p and SMALLEST_ORDER <= p <= LARGEST_ORDER:
        value = c + d32 / (2**p - 1)
    else:
        value = first
    others = [first, grids[truth][k][1]]
    return value, max(abs(o - value) for o in others), p


def pct(x):
    return "{:.2f} %".format(100 * x) if x == x else "-"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--base", type=int, default=64)
    parser.add_argument("--truth", type=int, default=1024)
    parser.add_argument("--seeds", type=int, default=2)
    parser.add_argument("--reuse", action="store_true")
    args = parser.parse_args()
    os.chdir(ROOT)
    sys.path.insert(0, os.path.join(ROOT, "build", "release", "python"))
    raw_path = os.path.join(OUT, "raw.csv")
    cases = {}  # (family name, seed) -> {n: [(nodes, corrected, converged) per load]}
    started = time.time()
    if args.reuse and os.path.exists(raw_path):
        for line in open(raw_path):
            if line.startswith("#") or line.startswith("family"):
                continue
            f, seed, n, k, nodes, corr, conv = line.strip().split(",")
            cases.setdefault((f, int(seed)), {}).setdefault(int(n), [None] * len(LOADS))[int(k)] = (
                float(nodes), float(corr), conv == "1")
    else:
        import contactbench as cb
        for family in FAMILIES:
            for seed in range(1, args.seeds + 1):
                t0 = time.time()
                cases[(family[0], seed)] = solve_case(cb, family, 100 + seed, args.base, args.truth, args.threads)
                print("{} seed {}: {:.0f} s".format(family[0], seed, time.time() - t0), file=sys.stderr)
        raw = ["# error_bar study raw solves: scripts/studies/error_bar.py ({})".format(stamp()),
               "family,seed,n,load_index,area_fraction_nodes,area_fraction_corrected,converged"]
        for (f, seed), grids in cases.items():
            for n, rows in sorted(grids.items()):
                for k, (nodes, corr, conv) in enumerate(rows):
                    raw.append("{},{},{},{},{!r},{!r},{}".format(f, seed, n, k, nodes, corr, int(conv)))
        write_atomically(raw_path, "\n".join(raw) + "\n")
    elapsed = time.time() - started

    estimates = ["gci3", "gci3_roache", "gci3_fine", "gci_ext3", "gci_ext1.25", "gci2", "former"]
    records = []  # one per case and estimate
    for (f, seed), grids in cases.items():
        for k, load in enumerate(LOADS):
            true, true_unc, true_order = truth_of(grids, k, args.truth)
            n = args.base
            c, m, fi = grids[n][k][0], grids[2 * n][k][0], grids[4 * n][k][0]
            vr, br, pr = gci3_roache(c, m, fi)
            v2, b2 = gci2(m, fi)
            v3, b3, p3 = gci3(c, m, fi)
            ve, be3 = gci_extrapolates(c, m, fi, FACTOR_TWO)
            _, be1 = gci_extrapolates(c, m, fi, FACTOR_THREE)
            former_value = 2 * fi - m
            former_bar = abs(former_value - grids[4 * n][k][1])
            for name, value, bar, order in (("gci3", v3, b3, p3), ("gci3_roache", vr, br, pr),
                                            ("gci3_fine", fi, br, pr), ("gci_ext3", ve, be3, math.nan),
                                            ("gci_ext1.25", ve, be1, math.nan), ("gci2", v2, b2, math.nan),
                                            ("former", former_value, former_bar, math.nan)):
                err = abs(value - true)
                records.append(dict(family=f, seed=seed, load=load, estimate=name, truth=true,
                                    truth_uncertainty=true_unc, truth_order=true_order, value=value, bar=bar,
                                    order=order, error=err, covered=err <= bar,
                                    ratio=bar / err if err > 0 else math.inf))

    md = ["# Calibration of the BEM reference's error bar", "",
          "Surfaces generated on {0} points a side (L = 200 um, sigma = 0.5 um, spectrum cut at that grid's "
          "Nyquist or half of it), Fourier-refined; BEM (active_set, tolerance 1e-8) on {0} ... {1} points a side "
          "at P/(E* A0) = {2}. The estimates are made from the grids {0}, {3}, {4}; the truth is the three-grid "
          "extrapolation from {5}, {6}, {1} (docs/studies.md). Families: {7}; seeds 101 ... {8}.".format(
              args.base, args.truth, ", ".join("{:g}".format(l) for l in LOADS), 2 * args.base, 4 * args.base,
              args.truth // 4, args.truth // 2, "; ".join(
                  "{} (H {}, qr {} q0, qs {} x Nyquist, m2x/m2y {})".format(*fam) for fam in FAMILIES),
              100 + args.seeds), ""]
    md += ["## Coverage and over-estimation per load band", "",
           "| estimate | load band | cases | coverage | median bar / true error | worst true error / bar | "
           "median true error | median truth uncertainty |", "|---|---|---:|---:|---:|---:|---:|---:|"]
    for name in estimates:
        for band, lo, hi in BANDS + [("all", 0, 1)]:
            sel = [r for r in records if r["estimate"] == name and lo <= r["load"] <= hi]
            cov = sum(r["covered"] for r in sel) / len(sel)
            ratios = sorted(r["ratio"] for r in sel)
            worst = max(r["error"] / r["bar"] if r["bar"] > 0 else math.inf for r in sel)
            md.append("| {} | {} | {} | {:.1f} % | {:.2f} | {:.2f} | {} | {} |".format(
                name, band if band == "all" else "{} ({:g}-{:g})".format(band, lo, hi), len(sel), 100 * cov,
                median(ratios), worst, pct(median([r["error"] / r["truth"] for r in sel])),
                pct(median([r["truth_uncertainty"] / r["truth"] for r in sel]))))
    md.append("")
    hardest = sorted([r for r in records if r["estimate"] == "gci3"], key=lambda r: r["bar"] / max(r["error"], 1e-300))[:5]
    md += ["## The gci3 cases closest to the bar (the tests' cases)", "",
           "| family | seed | load | value | bar | truth | true error / bar | observed order |",
           "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for r in hardest:
        md.append("| {} | {} | {:g} | {:.6f} | {:.6f} | {:.6f} | {:.2f} | {:.2f} |".format(
            r["family"], r["seed"] + 100, r["load"], r["value"], r["bar"],
            r["truth"], r["error"] / r["bar"] if r["bar"] > 0 else math.inf, r["order"]))
    md += ["", "![true error against the estimate](estimate.png)", "",
           ("Solves read back from raw.csv (its first line: the commit and date they were made at)." if args.reuse
            else "Solves: {:.0f} s.".format(elapsed)), "",
           "Made by `PYTHONPATH=build/release/python /usr/bin/python3 scripts/studies/error_bar.py --threads {} "
           "--base {} --truth {} --seeds {}{}` ({}, {} threads).".format(
               args.threads, args.base, args.truth, args.seeds, " --reuse" if args.reuse else "", stamp(),
               args.threads), ""]
    write_atomically(os.path.join(OUT, "table.md"), "\n".join(md))
    csv = ["# error_bar study: scripts/studies/error_bar.py ({})".format(stamp()),
           "family,seed,load,estimate,value,bar,order,truth,truth_uncertainty,truth_order,true_error,covered"]
    for r in records:
        csv.append("{},{},{:g},{},{!r},{!r},{!r},{!r},{!r},{!r},{!r},{}".format(
            r["family"], r["seed"] + 100, r["load"], r["estimate"], r["value"], r["bar"], r["order"], r["truth"],
            r["truth_uncertainty"], r["truth_order"], r["error"], int(r["covered"])))
    write_atomically(os.path.join(OUT, "cases.csv"), "\n".join(csv) + "\n")
    script = """# Made by scripts/studies/error_bar.py: `gnuplot estimate.gp` in this folder redraws from cases.csv.
set datafile separator ','
set termoption noenhanced
set logscale xy
set xlabel 'error bar (estimate) in A/A0'
set ylabel 'true error |value - truth| in A/A0'
set key top left
set grid
set title 'BEM reference: true error against its error bar, base grid {base}, truth {truth}'
do for [t in "pngcairo svg"] {{
  if (t eq "pngcairo") {{ set terminal pngcairo noenhanced size 900,750 font ',11'; set output 'estimate.png' }}
  else {{ set terminal svg noenhanced size 900,750 dynamic font ',11'; set output 'estimate.svg' }}
  plot [1e-6:1] [1e-7:1] x with lines lc rgb 'black' title 'true error = bar', \\
       'cases.csv' using (strcol(4) eq 'gci3' ? $6 : NaN):11 with points pt 7 ps 0.8 title 'gci3', \\
       'cases.csv' using (strcol(4) eq 'gci2' ? $6 : NaN):11 with points pt 5 ps 0.6 title 'gci2', \\
       'cases.csv' using (strcol(4) eq 'former' ? $6 : NaN):11 with points pt 2 ps 0.8 title 'former |ext - corrected|'
}}
unset output
""".format(base=args.base, truth=args.truth)
    gnuplot(script, OUT, "estimate")
    print("\n".join(md))


def median(values):
    values = sorted(v for v in values if v == v)
    if not values:
        return math.nan
    m = len(values) // 2
    return values[m] if len(values) % 2 else 0.5 * (values[m - 1] + values[m])


if __name__ == "__main__":
    main()
