#!/usr/bin/env python3
"""The resolution study (issue 14): surface A at the paper's 256 x 256 and the same surface Fourier-refined to
512, 1024, 2048 points a side. Runs scenes/studies/resolution.toml into results/studies/resolution/run/, then
writes results/studies/resolution/{table.md, kappa.csv, kappa.gp, kappa.png, kappa.svg}: the areal kappa (at
P/(E* A0) = 1e-4) and A/A0 at 1e-3 and 1e-2 against the pixel size, for the BEM (node count, perimeter-corrected,
Richardson-extrapolated from n and 2n), the plateau model (4, 8), the Hertz-consistent variant (this project's,
not the paper's) and the theories.
Usage: scripts/studies/resolution.py [--threads 2] [--reuse]   (--reuse: keep an existing run, redo the tables)
"""
import argparse
import os

from study_common import ROOT, Run, build, fmt, gnuplot, pct, run_scene, write_atomically

OUT = os.path.join("results", "studies", "resolution")
LENGTH_UM = 200.0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--reuse", action="store_true")
    args = parser.parse_args()
    os.chdir(ROOT)
    build()
    run = run_scene(os.path.join("scenes", "studies", "resolution.toml"), os.path.join(OUT, "run"), args.threads,
                    args.reuse)
    loads = run.loads
    # (series, n, [A/A0 per load]) from the run's columns.
    series = []
    for n, label, fine in ((256, "bem_x_256", False), (512, "bem_x_256", True), (1024, "bem_x_1024", False),
                           (2048, "bem_x_1024", True)):
        suffix = "_fine" if fine else ""
        series.append(("BEM nodes", n, run.column(label, "area_fraction_nodes" + suffix)))
        series.append(("BEM corrected", n, run.column(label, "area_fraction_corrected" + suffix)))
    for n, label in ((512, "bem_x_256"), (1024, "bem_x_512"), (2048, "bem_x_1024")):
        series.append(("BEM extrapolated from n/2 and n", n, run.column(label, "area_fraction_extrapolated")))
    for n in (256, 512, 1024, 2048):
        series.append(("plateau 4", n, run.column("plateau4_{}".format(n))))
        series.append(("plateau 8", n, run.column("plateau8_{}".format(n))))
        series.append(("Hertz-consistent plateaus 4 (this project)", n, run.column("hertz4_{}".format(n))))
    reference = run.column("bem_x_1024")
    reference_error = run.column("bem_x_1024", "area_fraction_error")
    names = []
    for s in series:
        if s[0] not in names:
            names.append(s[0])

    # kappa.csv: one row per series and grid.
    lines = ["# resolution study: scripts/studies/resolution.py --threads {} ({}); kappa at P/(E* A0) = {:g}; dx = "
             "200 um / n".format(args.threads, run.stamp(), loads[0]),
             "series,n,dx_um,kappa," + ",".join("area_fraction_at_{:g}".format(l) for l in loads)]
    for name, n, areas in sorted(series, key=lambda s: (names.index(s[0]), s[1])):  # each series contiguous
        lines.append("{},{},{},{},{}".format(name, n, LENGTH_UM / n, run.kappa(areas[0]),
                                             ",".join(repr(a) for a in areas)))
    write_atomically(os.path.join(OUT, "kappa.csv"), "\n".join(lines) + "\n")

    # table.md
    md = ["# Resolution study: surface A on 256 ... 2048 points a side", "",
          run.summary.get("scene_as_understood", {}).get("description", ""), "",
          "Areal kappa = (A/A0)/(p/(E* gbar)) at P/(E* A0) = {:g} (gbar = {:.4f}); in brackets the error against the "
          "reference, the BEM extrapolated from 1024 and 2048 points a side (kappa {}, its own error estimate "
          "{}).".format(loads[0], run.gbar, fmt(run.kappa(reference[0])), pct(reference_error[0] / reference[0], False)),
          "", "| method | 256 | 512 | 1024 | 2048 |", "|---|---:|---:|---:|---:|"]
    for name in names:
        cells = {n: areas for s, n, areas in series if s == name}
        row = "| {} |".format(name)
        for n in (256, 512, 1024, 2048):
            if n in cells:
                row += " {} ({}) |".format(fmt(run.kappa(cells[n][0])), pct(cells[n][0] / reference[0] - 1))
            else:
                row += " |"
        md.append(row)
    for theory in ("gw_mccool", "bgt", "bgt_linear", "persson"):
        a = run.column(theory)[0]
        md.append("| {} (grid-independent) | {} ({}) | | | |".format(theory, fmt(run.kappa(a)), pct(a / reference[0] - 1)))
    for k in range(1, len(loads)):
        md += ["", "A/A0 at P/(E* A0) = {:g} (reference {:.4g} ± {}):".format(loads[k], reference[k],
                                                                           pct(reference_error[k] / reference[k], False)),
               "", "| method | 256 | 512 | 1024 | 2048 |", "|---|---:|---:|---:|---:|"]
        for name in names:
            cells = {n: areas for s, n, areas in series if s == name}
            row = "| {} |".format(name)
            for n in (256, 512, 1024, 2048):
                row += " {:.4g} ({}) |".format(cells[n][k], pct(cells[n][k] / reference[k] - 1)) if n in cells else " |"
            md.append(row)
    md += ["", "Wall time of each method's stages: see run/table.md. The Hertz-consistent plateaus are the project's "
           "own variant (docs/theory.md section 8.3), not the paper's model.", "",
           "![kappa against pixel size](kappa.png)", "",
           "Made by `scripts/studies/resolution.py --threads {}` ({}).".format(args.threads, run.stamp()), ""]
    write_atomically(os.path.join(OUT, "table.md"), "\n".join(md))

    # kappa.gp: kappa against the pixel size, one line per series, the reference and its bar.
    plot = []
    for i, name in enumerate(names):
        plot.append("'kappa.csv' using (strcol(1) eq '{}' ? $3 : NaN):4 with linespoints lw 2 pt {} title '{}'".format(
            name, 5 + i, name))
    ref_kappa, ref_bar = run.kappa(reference[0]), run.kappa(reference_error[0])
    script = """# Made by scripts/studies/resolution.py: `gnuplot kappa.gp` in this folder redraws the plot from kappa.csv.
set datafile separator ','
set termoption noenhanced
set xlabel 'pixel size dx [um] (200 um / points a side)'
set ylabel 'areal kappa at P/(E* A0) = {load:g}'
set logscale x
set xrange [0.07:1]
set yrange [1.5:4.6]
set grid
set key outside right
set title 'Surface A: kappa against pixel size (the same surface, Fourier-refined)'
set object 1 rect from graph 0, first {lo} to graph 1, first {hi} fc rgb '#dddddd' fs solid 0.5 noborder behind
do for [t in "pngcairo svg"] {{
  if (t eq "pngcairo") {{ set terminal pngcairo noenhanced size 1300,650 font ',11'; set output 'kappa.png' }}
  else {{ set terminal svg noenhanced size 1300,650 dynamic font ',11'; set output 'kappa.svg' }}
  plot {ref} with lines lw 1 dt 2 lc rgb 'black' title 'reference (BEM extrapolated 1024/2048) and its error bar', \\
       {bgt_linear} with lines lw 1 dt 3 lc rgb '#d62728' title 'bgt_linear (grid-independent)', \\
       {persson} with lines lw 1 dt 4 lc rgb '#9467bd' title 'persson (grid-independent)', \\
       {series}
}}
unset output
""".format(load=loads[0], lo=ref_kappa - ref_bar, hi=ref_kappa + ref_bar, ref=ref_kappa,
           bgt_linear=run.kappa(run.column("bgt_linear")[0]), persson=run.kappa(run.column("persson")[0]),
           series=", \\\n       ".join(plot))
    gnuplot(script, OUT, "kappa")
    print("resolution: {} written".format(OUT))


if __name__ == "__main__":
    main()
