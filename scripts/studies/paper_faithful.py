#!/usr/bin/env python3
"""The paper_faithful study (issue 14): the seed paper's comparison as the paper made it (256 x 256, the paper's
500 levels, a node-counted area on that grid standing in for its finite-element model) beside the converged
comparison (the BEM extrapolated from 512 and 1024 points a side; the plateau model and the project's
Hertz-consistent variant on 2048 points a side), on surfaces A and B.
Runs scenes/studies/paper_faithful_{A,B}_{as_made,converged}.toml into results/studies/paper_faithful/<scene>/
and writes results/studies/paper_faithful/{table.md, curves.gp, curves.png, curves.svg}.
Usage: scripts/studies/paper_faithful.py [--threads 2] [--reuse]
"""
import argparse
import os

from study_common import ROOT, build, gnuplot, pct, run_scene, write_atomically

OUT = os.path.join("results", "studies", "paper_faithful")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--reuse", action="store_true")
    args = parser.parse_args()
    os.chdir(ROOT)
    build()
    runs = {}
    for surface in ("A", "B"):
        for kind in ("as_made", "converged"):
            name = "paper_faithful_{}_{}".format(surface, kind)
            runs[surface, kind] = run_scene(os.path.join("scenes", "studies", name + ".toml"),
                                            os.path.join(OUT, name), args.threads, args.reuse)
    stamp = runs["A", "converged"].stamp()
    md = ["# The paper's comparison as made, and converged", "",
          "As made: the paper's 256 x 256 grid, its 500 cutting levels, and the boundary-element solution on the "
          "same grid with the contact area counted by nodes, which is what a node-based finite-element model at "
          "that resolution reports (the paper's own FE model is not available; this is its stand-in). Converged: "
          "the BEM Richardson-extrapolated from 512 and 1024 points a side (docs/theory.md section 9; its own error "
          "estimate in brackets), the plateau model and the project's Hertz-consistent variant (not the paper's "
          "model) swept on the same surface Fourier-refined to 2048 points a side.", ""]
    data = []
    for surface in ("A", "B"):
        made, conv = runs[surface, "as_made"], runs[surface, "converged"]
        fe = made.column("bem_nodes_256")
        plateau_paper = made.column("plateau_paper")
        ref = conv.column("bem_x_512")
        ref_err = conv.column("bem_x_512", "area_fraction_error")
        plateau = conv.column("plateau_2048")
        hertz = conv.column("hertz_2048")
        theories = {t: conv.column(t) for t in ("gw_mccool", "bgt", "bgt_linear", "persson")}
        md += ["## Surface {}".format(surface), "",
               "| P/(E* A0) | FE stand-in: BEM 256 nodes | plateau, 500 levels, 256 (vs FE stand-in) | BEM converged "
               "(± own error) | FE stand-in vs converged | plateau 2048 (vs converged) | Hertz-consistent plateaus 2048, "
               "this project (vs converged) | persson (vs converged) | bgt_linear (vs converged) |",
               "|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        for k, load in enumerate(conv.loads):
            md.append("| {:.3g} | {:.4g} | {:.4g} ({}) | {:.4g} (± {}) | {} | {:.4g} ({}) | {} | {} | {} |".format(
                load, fe[k], plateau_paper[k], pct(plateau_paper[k] / fe[k] - 1), ref[k], pct(ref_err[k] / ref[k], False),
                pct(fe[k] / ref[k] - 1), plateau[k], pct(plateau[k] / ref[k] - 1),
                "n/a" if hertz[k] != hertz[k] else "{:.4g} ({})".format(hertz[k], pct(hertz[k] / ref[k] - 1)),
                pct(theories["persson"][k] / ref[k] - 1), pct(theories["bgt_linear"][k] / ref[k] - 1)))
        md += ["", "Areal kappa at P/(E* A0) = {:g}: FE stand-in {:.3f}, plateau as made {:.3f}; converged BEM {:.3f}, "
               "plateau 2048 {:.3f}, Hertz-consistent plateaus 2048 {:.3f}.".format(
                   conv.loads[0], made.kappa(fe[0]), made.kappa(plateau_paper[0]), conv.kappa(ref[0]),
                   conv.kappa(plateau[0]), conv.kappa(hertz[0])), ""]
        for k, load in enumerate(conv.loads):
            data.append("{},{},{},{},{},{},{},{},{}".format(surface, load, fe[k], plateau_paper[k], ref[k], ref_err[k],
                                                            plateau[k], hertz[k], theories["persson"][k]))
    md += ["Each scene's own table (times, every method's parameters): the folders paper_faithful_<surface>_<as_made|"
           "converged>/ beside this file.", "", "![as made and converged](curves.png)", "",
           "Made by `scripts/studies/paper_faithful.py --threads {}` ({}).".format(args.threads, stamp), ""]
    write_atomically(os.path.join(OUT, "table.md"), "\n".join(md))
    write_atomically(os.path.join(OUT, "curves.csv"),
                     "# paper_faithful: scripts/studies/paper_faithful.py ({})\n".format(stamp) +
                     "surface,load,bem_nodes_256,plateau_paper_256,bem_extrapolated,bem_error,plateau_2048,"
                     "hertz_2048,persson\n" + "\n".join(data) + "\n")
    panels = []
    for surface in ("A", "B"):
        sel = "(strcol(1) eq '{}' ? $2 : NaN)".format(surface)
        panels.append("""set title 'Surface {s}'
plot 'curves.csv' using {sel}:5:6 with yerrorlines lw 3 pt 7 lc rgb 'black' title 'BEM converged (extrapolated 512/1024, error bar)', \\
     '' using {sel}:3 with linespoints lw 2 pt 4 dt 2 lc rgb 'black' title 'FE stand-in: BEM 256 node count', \\
     '' using {sel}:4 with linespoints lw 2 pt 5 dt 2 lc rgb '#1f77b4' title 'plateau model as made (256, 500 levels)', \\
     '' using {sel}:7 with linespoints lw 2 pt 5 lc rgb '#1f77b4' title 'plateau model converged (2048)', \\
     '' using {sel}:8 with linespoints lw 2 pt 9 lc rgb '#2ca02c' title 'Hertz-consistent plateaus 2048 (this project)', \\
     '' using {sel}:9 with lines lw 1.5 lc rgb '#d62728' title 'persson'""".format(s=surface, sel=sel))
    script = """# Made by scripts/studies/paper_faithful.py: `gnuplot curves.gp` in this folder redraws from curves.csv.
set datafile separator ','
set datafile missing 'nan'
set termoption noenhanced
set logscale xy
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
set key top left font ',9'
do for [t in "pngcairo svg"] {{
  if (t eq "pngcairo") {{ set terminal pngcairo noenhanced size 1400,600 font ',11'; set output 'curves.png' }}
  else {{ set terminal svg noenhanced size 1400,600 dynamic font ',11'; set output 'curves.svg' }}
  set multiplot layout 1,2
{panels}
  unset multiplot
}}
unset output
""".format(panels="\n".join(panels))
    gnuplot(script, OUT, "curves")
    print("paper_faithful: {} written".format(OUT))


if __name__ == "__main__":
    main()
