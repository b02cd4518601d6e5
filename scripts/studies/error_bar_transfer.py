#!/usr/bin/env python3
"""Does the error bar calibrated on the grids 64/128/256 still cover at finer grids (issue 40, step "transfer")?

Fresh surfaces (seeds 201 ..., never used by scripts/studies/error_bar.py), a few families, generated on a
`--base` grid (the spectrum cut at its Nyquist, so every finer grid is the same surface, Fourier-refined), solved
at the study's six loads (two per load band) on base ... `--truth` points a side. The estimates come from the
grids base, 2 base, 4 base; the truth is error_bar.py's truth_of from truth/4, truth/2, truth (its own uncertainty
u quoted beside: the spread of three independent truths). The scenes solve at 256-1024: --base 256 --truth 2048
is their regime (estimate from 256/512/1024, truth from 512/1024/2048); --base 128 --truth 1024 is one step
finer than the calibration (estimate from 128/256/512, truth from 256/512/1024).

Writes results/studies/error_bar/transfer_<base>_<truth>.md and .csv (the raw solves).
Usage: OMP_WAIT_POLICY=PASSIVE PYTHONPATH=build/release/python /usr/bin/python3 \
       scripts/studies/error_bar_transfer.py [--threads 2] [--base 128] [--truth 1024] [--seeds 1] [--reuse]
"""
import argparse
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from error_bar import (FAMILIES, HOLDOUT_FAMILIES, LOADS, BANDS, OUT, calibrated3, gci3, solve_case,  # noqa: E402
                       stamp, truth_of, median)
from study_common import ROOT, write_atomically  # noqa: E402

# Four families that span the calibration's range: rough and smooth, a narrow band, an anisotropy.
TRANSFER_FAMILIES = [f for f in FAMILIES + HOLDOUT_FAMILIES
                     if f[0] in ("H0.3", "H0.7", "H0.8 narrow", "H0.6 aniso 3")]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--base", type=int, default=128)
    parser.add_argument("--truth", type=int, default=1024)
    parser.add_argument("--seeds", type=int, default=1)
    parser.add_argument("--reuse", action="store_true")
    args = parser.parse_args()
    os.chdir(ROOT)
    sys.path.insert(0, os.path.join(ROOT, "build", "release", "python"))
    name = "transfer_{}_{}".format(args.base, args.truth)  # one pair of files per pair of grids
    raw_path = os.path.join(OUT, name + ".csv")
    cases = {}
    if args.reuse and os.path.exists(raw_path):
        for line in open(raw_path):
            if line.startswith("#") or line.startswith("family"):
                continue
            f, seed, n, k, nodes, corr, conv = line.strip().split(",")
            cases.setdefault((f, int(seed)), {}).setdefault(int(n), [None] * len(LOADS))[int(k)] = (
                float(nodes), float(corr), conv == "1")
    else:
        import contactbench as cb
        raw = ["# error_bar transfer raw solves: scripts/studies/error_bar_transfer.py ({}, {} threads, base {}, "
               "truth {})".format(stamp(), args.threads, args.base, args.truth),
               "family,seed,n,load_index,area_fraction_nodes,area_fraction_corrected,converged"]
        for seed in range(201, 201 + args.seeds):
            for family in TRANSFER_FAMILIES:
                t0 = time.time()
                grids = solve_case(cb, family, seed, args.base, args.truth, args.threads)
                print("{} seed {}: {:.0f} s".format(family[0], seed, time.time() - t0), file=sys.stderr)
                cases[(family[0], seed)] = grids
                for n, rows in sorted(grids.items()):
                    for k, (nodes, corr, conv) in enumerate(rows):
                        raw.append("{},{},{},{},{!r},{!r},{}".format(family[0], seed, n, k, nodes, corr, int(conv)))
                write_atomically(raw_path, "\n".join(raw) + "\n")  # after every surface: a partial run is kept
    base = args.base
    records = []  # (band, estimate, covered strictly, covered within u, bar / true error)
    lines = []
    for (f, seed), grids in sorted(cases.items()):
        for k, load in enumerate(LOADS):
            true, u, _ = truth_of(grids, k, args.truth)
            f1, f2, f3 = (grids[n][k][0] for n in (base, 2 * base, 4 * base))
            band = next(b for b, lo, hi in BANDS if lo <= load <= hi)
            for estimate, (value, bar, _) in (("calibrated3", calibrated3(f1, f2, f3, (4 * base) ** 2, load)),
                                          ("gci3", gci3(f1, f2, f3))):
                err = abs(value - true)
                records.append((band, estimate, err <= bar, err - u <= bar, bar / err if err > 0 else math.inf))
                lines.append("| {} | {} | {:g} | {} | {:.5g} | {:.5g} | {:.2g} | {:.2g} | {:.2g} | {} |".format(
                    f, seed, load, estimate, value, true, u, err, bar, "yes" if err <= bar else "NO"))
    md = ["# Transfer of the error bar to finer grids (estimate from {}/{}/{}, truth from {}/{}/{})".format(
              base, 2 * base, 4 * base, args.truth // 4, args.truth // 2, args.truth), "",
          "| band | estimate | cases | coverage | judgeable coverage (within u) | median bar / true error |",
          "|---|---|---:|---:|---:|---:|"]
    for b, _, _ in BANDS:
        for estimate in ("calibrated3", "gci3"):
            sel = [r for r in records if r[0] == b and r[1] == estimate]
            if sel:
                md.append("| {} | {} | {} | {:.0f} % | {:.0f} % | {:.2f} |".format(
                    b, estimate, len(sel), 100 * sum(r[2] for r in sel) / len(sel),
                    100 * sum(r[3] for r in sel) / len(sel), median([r[4] for r in sel])))
    md += ["", "Every case (u = the truth's own uncertainty):", "",
           "| family | seed | P/(E* A0) | estimate | value | truth | u | true error | bar | covered |",
           "|---|---:|---:|---|---:|---:|---:|---:|---:|---|"] + lines
    md += ["", "Made by `OMP_WAIT_POLICY=PASSIVE PYTHONPATH=build/release/python /usr/bin/python3 "
           "scripts/studies/error_bar_transfer.py --threads {} --base {} --truth {} --seeds {}` ({}).".format(
               args.threads, base, args.truth, args.seeds, stamp()), ""]
    write_atomically(os.path.join(OUT, name + ".md"), "\n".join(md))
    print("\n".join(md))


if __name__ == "__main__":
    main()
