#!/usr/bin/env python3
"""The seeds study (issue 14): every method's error against the BEM as mean and spread over realisations, so that
no conclusion rests on one surface. Families (scenes/studies/seeds_<family>.toml, each written for seed 1):
surfaces A and B over 8 seeds; Hurst exponents 0.3 and 0.9 and two narrower bands over 3 seeds; the measured
surfaces matrix-2, -3, -4 (non-periodic: the BEM on the file's grid is the reference).
Runs every scene into results/studies/seeds/runs/<family>_<seed or file>/, then writes
results/studies/seeds/{table.md, errors.csv, errors.gp, errors.png, errors.svg}.
Usage: scripts/studies/seeds.py [--threads 2] [--reuse] [--seeds 8] [--other-seeds 3]
"""
import argparse
import math
import os
import re
import tempfile

from study_common import ROOT, build, gnuplot, pct, run_scene, write_atomically

OUT = os.path.join("results", "studies", "seeds")
# Labels compared in every family (the measured family's own labels mapped onto them).
METHODS = [("plateau_256", "plateau model, 256 (as the paper)"),
           ("plateau_1024", "plateau model, 1024 (converged)"),
           ("hertz_1024", "Hertz-consistent plateaus, 1024 (this project)"),
           ("bem_256", "BEM 256, perimeter-corrected"),
           ("gw_mccool", "gw_mccool"), ("bgt", "bgt"), ("bgt_linear", "bgt_linear"), ("persson", "persson")]
MEASURED_LABELS = {"plateau_256": "plateau", "hertz_1024": "hertz"}


def mean_spread(values):
    values = [v for v in values if v == v]
    if not values:
        return math.nan, math.nan, math.nan, math.nan
    mean = sum(values) / len(values)
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1)) if len(values) > 1 else 0.0
    return mean, sd, min(values), max(values)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--reuse", action="store_true")
    parser.add_argument("--seeds", type=int, default=8)
    parser.add_argument("--other-seeds", type=int, default=3)
    args = parser.parse_args()
    os.chdir(ROOT)
    build()
    families = [("A", args.seeds), ("B", args.seeds), ("H03", args.other_seeds), ("H09", args.other_seeds),
                ("narrow_qs", args.other_seeds), ("narrow_qr", args.other_seeds), ("measured", 3)]
    errors = {}  # (family, label) -> per load list of errors over realisations
    kappas = {}
    ref_unc = {}
    loads = None
    stamp = None
    scratch = tempfile.mkdtemp(prefix="contactbench_seeds_")
    for family, count in families:
        template = open(os.path.join("scenes", "studies", "seeds_{}.toml".format(family))).read()
        for k in range(count):
            if family == "measured":
                name = "matrix-{}".format(k + 2)
                text = template.replace('"../../data/measured/matrix-2.txt"',
                                        '"{}"'.format(os.path.join(ROOT, "data", "measured", name + ".txt")))
            else:
                name = "seed{}".format(k + 1)
                text = re.sub(r"seed = 1 \}", "seed = {} }}".format(k + 1), template)
            scene = os.path.join(scratch, "seeds_{}_{}.toml".format(family, name))
            write_atomically(scene, text)
            run = run_scene(scene, os.path.join(OUT, "runs", "{}_{}".format(family, name)), args.threads, args.reuse,
                            plots=False)  # 31 runs: their tables, not 31 plots
            loads = run.loads
            stamp = stamp or run.stamp()
            ref_label = run.summary["reference"]
            ref = run.column(ref_label)
            unc = run.column(ref_label, "area_fraction_error") if family != "measured" else [math.nan] * len(ref)
            ref_unc.setdefault(family, []).append([u / r for u, r in zip(unc, ref)])
            kappas.setdefault((family, "BEM reference"), []).append(run.kappa(ref[0]))
            for label, _ in METHODS:
                source = MEASURED_LABELS.get(label, label) if family == "measured" else label
                if source not in run.rows:
                    continue
                area = run.column(source)
                errors.setdefault((family, label), []).append([a / r - 1 for a, r in zip(area, ref)])
                kappas.setdefault((family, label), []).append(run.kappa(area[0]))

    md = ["# Every method against the BEM over many surfaces", "",
          "Relative error in A/A0 against the reference, over realisations: mean ± standard deviation [min, max]. "
          "Reference for the generated surfaces: the BEM Richardson-extrapolated from 512 and 1024 points a side "
          "(docs/theory.md section 9); its own estimated error is given per family. Measured surfaces "
          "(non-periodic): the BEM on the file's grid, perimeter-corrected, no error estimate. The Hertz-consistent "
          "plateaus are this project's variant (docs/theory.md section 8.3), not the paper's model; on the measured "
          "surfaces they and the plateau model are swept on the file's grid (no refinement possible).", ""]
    csv = ["family,method,load,mean_error,sd_error,min_error,max_error,realisations"]
    for family, count in families:
        unc = ref_unc[family]
        md += ["## {} ({} {})".format(family, count, "files" if family == "measured" else "seeds"), ""]
        if family != "measured":
            md.append("Reference's own error estimate, mean over seeds: " + ", ".join(
                "{} at {:g}".format(pct(sum(u[k] for u in unc) / len(unc), False), l) for k, l in enumerate(loads)) + ".")
            md.append("")
        md += ["| method | " + " | ".join("error at {:g}".format(l) for l in loads) + " | kappa at {:g} |".format(loads[0]),
               "|---|" + "---:|" * (len(loads) + 1)]
        km = mean_spread(kappas[(family, "BEM reference")])
        md.append("| BEM reference |" + " |" * len(loads) + " {:.3f} ± {:.3f} |".format(km[0], km[1]))
        for label, title in METHODS:
            if (family, label) not in errors:
                continue
            if family == "measured":  # no refinement of a non-periodic file: every method on the file's grid
                title = title.replace("256 (as the paper)", "file's grid").replace("1024", "file's grid")
            per_seed = errors[(family, label)]
            cells = []
            for k, load in enumerate(loads):
                mean, sd, lo, hi = mean_spread([e[k] for e in per_seed])
                if mean != mean:
                    cells.append("no answer (the cut reaches the lowest level: full contact of the paper's model)")
                    continue
                cells.append("{} ± {} [{}, {}]".format(pct(mean), pct(sd, False), pct(lo), pct(hi)))
                csv.append("{},{},{},{},{},{},{},{}".format(family, label, load, mean, sd, lo, hi, len(per_seed)))
            km = mean_spread(kappas[(family, label)])
            md.append("| {} | {} | {:.3f} ± {:.3f} |".format(title, " | ".join(cells), km[0], km[1]))
        md.append("")
    md += ["Each realisation's own table: runs/<family>_<seed>/table.md.", "", "![errors](errors.png)", "",
           "Made by `scripts/studies/seeds.py --threads {} --seeds {} --other-seeds {}` ({}).".format(
               args.threads, args.seeds, args.other_seeds, stamp), ""]
    write_atomically(os.path.join(OUT, "table.md"), "\n".join(md))
    write_atomically(os.path.join(OUT, "errors.csv"),
                     "# seeds study: scripts/studies/seeds.py ({})\n".format(stamp) + "\n".join(csv) + "\n")

    # errors.gp: mean ± sd of the error at the middle load, one cluster per family, one colour per method.
    shown = ["plateau_256", "plateau_1024", "hertz_1024", "bem_256", "bgt_linear", "persson"]
    plots = []
    for i, label in enumerate(shown):
        plots.append("'errors.csv' using (fam(strcol(1)) + {off}):(strcol(2) eq '{label}' && $3 == {load!r} ? 100*$4 : NaN)"
                     ":(100*$5) with yerrorbars pt {pt} ps 1.3 lw 2 title '{title}'".format(
                         off=(i - len(shown) / 2) * 0.1, label=label, load=loads[1], pt=5 + i,
                         title=dict(METHODS)[label]))
    fams = [f for f, _ in families]
    script = """# Made by scripts/studies/seeds.py: `gnuplot errors.gp` in this folder redraws from errors.csv.
set datafile separator ','
set termoption noenhanced
fam(s) = {fam_expr}
set xtics ({xtics})
set xrange [-0.6:{xmax}]
set ylabel 'error in A/A0 against the BEM at P/(E* A0) = {load:g} [%] (mean ± sd over realisations)'
set grid ytics
set key outside right
set title 'Every method against the BEM, over seeds and surface families'
do for [t in "pngcairo svg"] {{
  if (t eq "pngcairo") {{ set terminal pngcairo noenhanced size 1400,650 font ',11'; set output 'errors.png' }}
  else {{ set terminal svg noenhanced size 1400,650 dynamic font ',11'; set output 'errors.svg' }}
  plot 0 with lines lc rgb 'black' notitle, \\
       {plots}
}}
unset output
""".format(fam_expr=" : ".join("s eq '{}' ? {}".format(f, i) for i, f in enumerate(fams)) + " : NaN",
           xtics=", ".join("'{}' {}".format(f, i) for i, f in enumerate(fams)), xmax=len(fams) - 0.4,
           load=loads[1], plots=", \\\n       ".join(plots))
    gnuplot(script, OUT, "errors")
    print("seeds: {} written".format(OUT))


if __name__ == "__main__":
    main()
