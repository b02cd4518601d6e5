#!/usr/bin/env python3
"""Edges of non-periodic records (issue 40; docs/studies.md "Edges of non-periodic records").

A measured record is a finite patch pressed into a half-space: the BEM solves it non-periodically, and its edges
act like a punch's. Here the truth is known: a patch of `--patch` points a side is cut out of a periodic surface
of `--large` points a side (the same pixel), the large surface is solved periodically, and the patch is solved
each way, at the mean pressure the large solve carries inside the patch (so that only the edge treatment
differs, not the load the patch happens to carry):

  as_is     the patch, non-periodic, statistics over the whole patch;
  guard_w   the same solve, statistics only inside a guard band of w pixels (w = 8, 16, 32, 48);
  mirror    the patch mirrored evenly to twice its points a side (a periodic surface with no step at the seams),
            solved periodically, statistics on the original quadrant;
  taper     the patch's heights multiplied by a Tukey window (cosine over the outer 1/8 of each side, mean
            removed first), solved periodically, statistics inside the tapered band.

The error is that of the contact fraction (node count) inside the judged region against the large solve's
node count in the same region. Also reported for as_is: the share of the contact and of the load carried by the
outer 20-pixel ring, and the contact fraction against the distance to the edge.
Writes results/studies/edges/{table.md, cases.csv}.

Usage: PYTHONPATH=build/release/python /usr/bin/python3 scripts/studies/edges.py [--threads 2] [--large 512]
       [--patch 256] [--seeds 2]
"""
import argparse
import math
import os
import sys
import time

import numpy as np

from study_common import ROOT, write_atomically
from error_bar import stamp

OUT = os.path.join("results", "studies", "edges")
LOADS = [1e-3, 5e-3, 2e-2]
GUARDS = [8, 16, 32, 48]
RING = 20  # the ring of the measurement, and of the edge-share columns (bem/contact_statistics.hpp)
ESTAR = 1e11
SIGMA = 0.5e-6
FAMILIES = [("H0.5", 0.5), ("H0.8", 0.8), ("H0.3", 0.3)]


def tukey(n, fraction):
    w = np.ones(n)
    m = int(round(fraction * n))
    x = np.arange(m)
    ramp = 0.5 * (1 - np.cos(math.pi * (x + 0.5) / m))
    w[:m] = ramp
    w[n - m:] = ramp[::-1]
    return w, m


def inner(a, w):
    return a[w:a.shape[0] - w, w:a.shape[1] - w] if w > 0 else a


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--large", type=int, default=512)
    parser.add_argument("--patch", type=int, default=256)
    parser.add_argument("--seeds", type=int, default=2)
    args = parser.parse_args()
    os.chdir(ROOT)
    sys.path.insert(0, os.path.join(ROOT, "build", "release", "python"))
    import contactbench as cb
    started = time.time()
    pixel = 200e-6 / 256  # the paper's pixel (L = 200 um on 256 points)
    length = args.large * pixel
    rows = []  # (family, seed, load, treatment, region pixels, error, edge_contact_share, edge_load_share)
    profile = {}  # distance to the edge (bins) -> [as_is fraction, truth fraction] sums at load 2e-2
    for name, hurst in FAMILIES:
        for seed in range(1, args.seeds + 1):
            grid = cb.Grid(nx=args.large, ny=args.large, lx=length, ly=length, periodic=True)
            psd = cb.SelfAffinePsd(sigma=SIGMA, hurst=hurst, qr=8 * 2 * math.pi / length)
            big = cb.generate_surface(grid, psd, 200 + seed, threads=args.threads).centred()
            h = np.asarray(big.heights)
            p = args.patch
            o = (args.large - p) // 2
            patch = np.ascontiguousarray(h[o:o + p, o:o + p])
            truth_solver = cb.BemSolver(big, ESTAR, threads=args.threads)
            truths = [truth_solver.solve(load) for load in LOADS]
            truth_p = [np.array(t.pressure[o:o + p, o:o + p]) for t in truths]
            # The patch's own mean pressure in the large solve [Pa]
            pressures = [float(tp.mean()) for tp in truth_p]
            as_is = cb.BemSolver(cb.Surface(patch, lx=p * pixel, periodic=False), ESTAR, threads=args.threads)
            mirrored_h = np.block([[patch, patch[:, ::-1]], [patch[::-1, :], patch[::-1, ::-1]]])
            mirror = cb.BemSolver(cb.Surface(np.ascontiguousarray(mirrored_h), lx=2 * p * pixel, periodic=True),
                                  ESTAR, threads=args.threads)
            wx, band = tukey(p, 1 / 8)
            tapered = (patch - patch.mean()) * wx[None, :] * wx[:, None]
            taper = cb.BemSolver(cb.Surface(np.ascontiguousarray(tapered), lx=p * pixel, periodic=True), ESTAR,
                                 threads=args.threads)
            for k, load in enumerate(LOADS):
                truth_contact = truth_p[k] > 0
                r = as_is.solve(mean_pressure=pressures[k])
                c = np.array(r.pressure) > 0
                pr = np.array(r.pressure)
                ring = np.ones_like(c, dtype=bool)
                ring[RING:p - RING, RING:p - RING] = False
                share_c = c[ring].sum() / max(c.sum(), 1)
                share_p = pr[ring].sum() / pr.sum()
                truth_share_c = truth_contact[ring].sum() / max(truth_contact.sum(), 1)
                truth_share_p = truth_p[k][ring].sum() / truth_p[k].sum()

                def err(a, w):
                    t = inner(truth_contact, w).mean()
                    return inner(a, w).mean() / t - 1

                rows.append((name, seed, load, "as_is", p, err(c, 0), share_c, share_p, truth_share_c,
                             truth_share_p))
                for w in [g for g in GUARDS if 4 * g < p]:  # judged region at least half the side
                    rows.append((name, seed, load, "guard_{}".format(w), p - 2 * w, err(c, w), math.nan, math.nan,
                                 math.nan, math.nan))
                m = np.array(mirror.solve(mean_pressure=pressures[k]).pressure)[:p, :p] > 0
                rows.append((name, seed, load, "mirror", p, err(m, 0), math.nan, math.nan, math.nan, math.nan))
                t = np.array(taper.solve(mean_pressure=pressures[k] * 1.0).pressure) > 0
                rows.append((name, seed, load, "taper (inside)", p - 2 * band, err(t, band), math.nan, math.nan,
                             math.nan, math.nan))
                if load == 2e-2:
                    yy, xx = np.mgrid[0:p, 0:p]
                    dist = np.minimum(np.minimum(xx, p - 1 - xx), np.minimum(yy, p - 1 - yy))
                    for lo, hi in [b for b in ((0, 4), (4, 8), (8, 16), (16, 32), (32, 64), (64, p // 2)) if b[1] <= p // 2]:
                        sel = (dist >= lo) & (dist < hi)
                        acc = profile.setdefault((lo, hi), [0.0, 0.0, 0])
                        acc[0] += c[sel].mean()
                        acc[1] += truth_contact[sel].mean()
                        acc[2] += 1
            print("{} seed {}: {:.0f} s".format(name, seed, time.time() - started), file=sys.stderr)

    treatments = ["as_is"] + ["guard_{}".format(w) for w in GUARDS if 4 * w < args.patch] + ["mirror",
                                                                                          "taper (inside)"]
    md = ["# Edges of non-periodic records: each treatment against the periodic truth", "",
          "A patch of {p} points a side cut from the middle of a periodic surface of {L} points a side (pixel "
          "0.78 um, sigma 0.5 um, qr = 8 x 2 pi/L of the large surface, qs = Nyquist; families {f}; seeds 201 ... "
          "{s}), solved at the mean pressure the large periodic solve carries inside the patch. Error: contact "
          "fraction (node count) inside the judged region against the large solve's in the same region, mean "
          "[min, max] over surfaces and seeds (docs/studies.md).".format(
              p=args.patch, L=args.large, f=", ".join(n for n, _ in FAMILIES), s=200 + args.seeds), "",
          "| treatment | judged region | " + " | ".join("error at {:g}".format(l) for l in LOADS) + " |",
          "|---|---:|" + "---:|" * len(LOADS)]
    for t in treatments:
        cells = []
        region = None
        for load in LOADS:
            e = [r[5] for r in rows if r[3] == t and r[2] == load]
            region = [r[4] for r in rows if r[3] == t][0]
            cells.append("{:+.1f} % [{:+.1f}, {:+.1f}]".format(100 * np.mean(e), 100 * min(e), 100 * max(e)))
        md.append("| {} | {}^2 | {} |".format(t, region, " | ".join(cells)))
    md += ["", "As is: share of the contact and of the load in the outer {} pixels (which are {:.0f} % of the "
           "patch), non-periodic solve against the periodic truth, mean over surfaces and seeds:".format(
               RING, 100 * (1 - (1 - 2 * RING / args.patch) ** 2)), "",
           "| load | contact share | truth | load share | truth |", "|---:|---:|---:|---:|---:|"]
    for load in LOADS:
        sel = [r for r in rows if r[3] == "as_is" and r[2] == load]
        md.append("| {:g} | {:.1f} % | {:.1f} % | {:.1f} % | {:.1f} % |".format(
            load, *[100 * np.mean([r[i] for r in sel]) for i in (6, 8, 7, 9)]))
    md += ["", "As is at 2e-2: contact fraction against the distance to the edge, mean over surfaces and seeds:", "",
           "| pixels from the edge | non-periodic patch | periodic truth | ratio |", "|---|---:|---:|---:|"]
    for (lo, hi), (a, t, n) in sorted(profile.items()):
        md.append("| {}-{} | {:.4f} | {:.4f} | {:.2f} |".format(lo, hi - 1, a / n, t / n, a / t))
    md += ["", "Solves: {:.0f} s.".format(time.time() - started), "",
           "Made by `PYTHONPATH=build/release/python /usr/bin/python3 scripts/studies/edges.py --threads {} --large {} "
           "--patch {} --seeds {}` ({}, {} threads).".format(args.threads, args.large, args.patch, args.seeds,
                                                             stamp(), args.threads), ""]
    write_atomically(os.path.join(OUT, "table.md"), "\n".join(md))
    csv = ["# edges study: scripts/studies/edges.py ({})".format(stamp()),
           "family,seed,load,treatment,region_points,error,edge_contact_share,edge_load_share,"
           "truth_edge_contact_share,truth_edge_load_share"]
    for r in rows:
        csv.append(",".join(str(x) for x in r))
    write_atomically(os.path.join(OUT, "cases.csv"), "\n".join(csv) + "\n")
    print("\n".join(md))


if __name__ == "__main__":
    main()
