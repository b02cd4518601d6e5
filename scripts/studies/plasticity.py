#!/usr/bin/env python3
"""The plasticity-index study (issue 35): every method against the elastic-perfectly plastic BEM over
Greenwood-Williamson's plasticity index psi = (E*/H) sqrt(sigma_s/beta) (Greenwood & Williamson 1966, with
McCool's summit parameters sigma_s, beta from the surface's moments, docs/theory.md section 11.4), the hardness H
varied so that psi runs from 0.3 to 10. Surfaces: the paper's A and B (scenes/paper/, their own generator keys)
and two generated surfaces nobody tuned on (Hurst 0.3, seed 7; Hurst 0.9, seed 11), all 256 x 256, the BEM on
that grid (no refinement: modest, so that the study runs in minutes on 2 cores).
For each surface and psi it writes a scene (results/studies/plasticity/runs/<surface>_psi<psi>/scene.toml),
runs it, and then writes results/studies/plasticity/{table.md, errors.csv, errors.gp, errors.png, errors.svg}.
Loads: P/(E* A0) = 1e-4 .. 1e-2 (5, logarithmic), those at or above H/(2 E*) left out (near full plastic
contact, which the BEM refuses at H itself).
Usage: scripts/studies/plasticity.py [--threads 2] [--reuse]
"""
import argparse
import math
import os
import re

from study_common import ROOT, build, fmt, gnuplot, pct, run_scene, write_atomically

OUT = os.path.join("results", "studies", "plasticity")
PSI = [0.3, 0.5, 1, 2, 3, 5, 10]
BASE_LOADS = [1e-4 * 10 ** (0.5 * k) for k in range(5)]  # 1e-4 .. 1e-2
E, NU = 100e9, 0.3
# name -> (the [surface] generate table, what it is)
SURFACES = {
    "A": (None, "the paper's surface A (scenes/paper/surface_A.toml)"),
    "B": (None, "the paper's surface B (scenes/paper/surface_B.toml)"),
    "H03_s7": ("{ sigma = 0.5e-6, hurst = 0.3, qr = 3.14e4, size = 200e-6, grid = 256, seed = 7 }",
               "generated, Hurst 0.3, seed 7 (untuned)"),
    "H09_s11": ("{ sigma = 1.0e-6, hurst = 0.9, qr = 6.28e4, size = 200e-6, grid = 256, seed = 11 }",
                "generated, Hurst 0.9, seed 11 (untuned)"),
}
# label -> (method, whether it models the hardness, legend)
METHODS = [
    ("bem", "bem", True, "BEM, capped at H (reference)"),
    ("bem_elastic", "bem", False, "BEM, elastic"),
    ("plateau", "plateau", False, "plateau (paper), elastic"),
    ("plateau_hertz", "plateau_hertz", False, "plateau_hertz (this project), elastic"),
    ("gw_mccool", "gw_mccool", False, "GW-McCool, elastic"),
    ("persson", "persson", False, "Persson, elastic"),
    ("plateau_capped", "plateau_capped", True, "plateau capped at H (this project)"),
    ("plateau_hertz_capped", "plateau_hertz_capped", True, "plateau_hertz capped at H (this project)"),
    ("ceb", "ceb", True, "Chang-Etsion-Bogy"),
    ("kogut_etsion", "kogut_etsion", True, "Kogut-Etsion"),
    ("persson_plastic", "persson_plastic", True, "Persson with yield"),
    ("majumdar_bhushan", "majumdar_bhushan", True, "Majumdar-Bhushan"),
]
# A method "stops being usable" under plasticity where its mean rms error has grown by this much over its own
# value at the smallest psi: 5 points, about the BEM reference's own discretisation error on 256 points a side
# (6.3 %, docs/studies.md section 5), below which a change is not resolved.
DEGRADED = 0.05


def paper_generate(name):
    with open(os.path.join("scenes", "paper", "surface_{}.toml".format(name))) as f:
        return re.search(r"^generate = (\{.*\})$", f.read(), re.M).group(1)


def summit_ratio(summary):
    """sqrt(sigma_s/beta) from McCool's parameters of the surface's moments (docs/theory.md section 5)."""
    s = summary["surface"]
    m0, m2, m4 = s["m0"], 0.5 * (s["m2x"] + s["m2y"]), 0.5 * (s["m4x"] + s["m4y"])
    alpha = m0 * m4 / m2 ** 2
    sigma_s = math.sqrt((1 - 0.8968 / alpha) * m0)
    beta = 0.375 * math.sqrt(math.pi / m4)
    return math.sqrt(sigma_s / beta), sigma_s, beta


def scene_text(name, generate, hardness, loads, methods):
    lines = ["# Written by scripts/studies/plasticity.py: surface {}, hardness {:.6g} Pa.".format(name, hardness or 0),
             'name = "plasticity_{}"'.format(name), 'reference = "{}"'.format(methods[0][0]), "", "[surface]",
             "generate = " + generate, "", "[material]", "E = {:g}".format(E), "nu = {:g}".format(NU), ""]
    if hardness:
        lines += ["[interface]", "hardness = {:.9g}".format(hardness), ""]
    lines += ["[loads]", "values = [" + ", ".join("{:.6g}".format(x) for x in loads) + "]", ""]
    for label, method, plastic, _ in methods:
        lines.append("[methods.{}]".format(label))
        if label != method:
            lines.append('method = "{}"'.format(method))
        if method == "bem":
            lines.append("tolerance = 1e-8")
        if hardness and not plastic:
            lines.append('ignore = ["hardness"]')
        lines.append("")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--reuse", action="store_true")
    args = parser.parse_args()
    os.chdir(ROOT)
    build()
    estar = E / (1 - NU ** 2)
    rows = []  # (surface, psi, hardness, label, loads, errors, seconds, plastic area fraction of the BEM)
    stamp = None
    for name, (generate, _) in SURFACES.items():
        generate = generate or paper_generate(name)
        # A probe without hardness gives the moments, hence sqrt(sigma_s/beta).
        probe_dir = os.path.join(OUT, "runs", name + "_probe")
        os.makedirs(probe_dir, exist_ok=True)
        probe_scene = os.path.join(probe_dir, "scene.toml")
        write_atomically(probe_scene, scene_text(name, generate, None, [1e-3], [("persson", "persson", False, "")]))
        probe = run_scene(probe_scene, os.path.join(probe_dir, "out"), args.threads, args.reuse, plots=False)
        ratio, sigma_s, beta = summit_ratio(probe.summary)
        for psi in PSI:
            hardness = estar * ratio / psi
            loads = [x for x in BASE_LOADS if x < 0.5 * hardness / estar]
            folder = os.path.join(OUT, "runs", "{}_psi{:g}".format(name, psi))
            os.makedirs(folder, exist_ok=True)
            scene = os.path.join(folder, "scene.toml")
            write_atomically(scene, scene_text(name, generate, hardness, loads, METHODS))
            run = run_scene(scene, os.path.join(folder, "out"), args.threads, args.reuse, plots=False)
            stamp = stamp or run.stamp()
            bem_plastic = run.column("bem", "plastic_area_fraction" if "plastic_area_fraction" in run.rows["bem"][0] else "plastic_fraction")  # runs before the rename (--reuse)
            for label, _, _, _ in METHODS:
                m = run.methods[label]
                rows.append((name, psi, hardness, label, run.loads, m["relative_error"], m["seconds"], bem_plastic,
                             run.column(label, "area_fraction")))
    write_outputs(rows, stamp, args)


def rms(values):
    values = [v for v in values if v is not None and math.isfinite(v)]
    return math.sqrt(sum(v * v for v in values) / len(values)) if values else math.nan


def write_outputs(rows, stamp, args):
    csv = ["surface,psi,hardness_pa,method,load,area_fraction,relative_error,bem_plastic_fraction,method_seconds"]
    for name, psi, hardness, label, loads, errors, seconds, bem_plastic, areas in rows:
        for load, err, plastic, area in zip(loads, errors, bem_plastic, areas):
            csv.append("{},{:g},{:.6g},{},{:.6g},{:.6g},{},{:.6g},{:.4g}".format(
                name, psi, hardness, label, load, area, "" if err is None else "{:.6g}".format(err), plastic, seconds))
    write_atomically(os.path.join(OUT, "errors.csv"),
                     "# plasticity study: scripts/studies/plasticity.py ({})\n".format(stamp) + "\n".join(csv) + "\n")

    # Per method and psi: the rms error over loads of each surface, then its mean, min and max over surfaces.
    def stats(label, psi):
        values = [rms(errors) for (n, p, _, l, _, errors, _, _, _) in rows if l == label and p == psi]
        values = [v for v in values if math.isfinite(v)]
        if not values:
            return math.nan, math.nan, math.nan
        return sum(values) / len(values), min(values), max(values)

    def seconds(label):
        values = sorted(s for (_, _, _, l, _, _, s, _, _) in rows if l == label)
        return values[len(values) // 2]

    surfaces = list(SURFACES)
    md = ["# Plasticity study: every method against the elastic-perfectly plastic BEM over the plasticity index", "",
          "psi = (E*/H) sqrt(sigma_s/beta) (Greenwood & Williamson 1966; McCool's sigma_s, beta from the moments;",
          "docs/theory.md section 11.4), the hardness H varied. Surfaces (256 x 256, BEM on that grid): " +
          "; ".join("{} = {}".format(n, d) for n, (_, d) in SURFACES.items()) + ".",
          "Loads P/(E* A0) = 1e-4 .. 1e-2 (5, log), those >= H/(2E*) left out. Entry: rms over loads of the relative",
          "error of A/A0 against the capped BEM, mean over the {} surfaces, [min, max] beneath.".format(len(surfaces)),
          "", "| method | " + " | ".join("psi = {:g}".format(p) for p in PSI) + " | median time [s] |",
          "|---|" + "---:|" * (len(PSI) + 1)]
    for label, _, _, legend in METHODS[1:]:
        cells = []
        for psi in PSI:
            mean, low, high = stats(label, psi)
            cells.append("n/a" if not math.isfinite(mean) else
                         "{} [{}, {}]".format(pct(mean, False), pct(low, False), pct(high, False)))
        md.append("| {} | {} | {} |".format(legend, " | ".join(cells), fmt(seconds(label), "{:.3g}")))
    md.append("| BEM, capped: median time [s] | " + " | ".join(
        fmt(sorted(s for (_, p, _, l, _, _, s, _, _) in rows if l == "bem" and p == psi)[len(surfaces) // 2], "{:.3g}")
        for psi in PSI) + " | {} |".format(fmt(seconds("bem"), "{:.3g}")))
    md.append("| BEM: plastic nodes / all at the largest load, mean | " + " | ".join(
        fmt(sum(bp[-1] for (_, p, _, l, _, _, _, bp, _) in rows if l == "bem" and p == psi) / len(surfaces), "{:.4f}")
        for psi in PSI) + " | |")
    md.append("")
    # Where each method stops being usable under plasticity: the smallest psi at which its mean rms error has
    # grown by more than DEGRADED (absolute) over its own error at the smallest psi, where the contact is
    # elastic (the elastic theories' own error is not plasticity's doing). For the elastic BEM this is where
    # plasticity itself first matters.
    md.append("Where each method's mean rms error first exceeds its own value at psi = {:g} by more than {} "
              "(absolute):".format(PSI[0], pct(DEGRADED, False)))
    md.append("")
    for label, _, _, legend in METHODS[1:]:
        start = stats(label, PSI[0])[0]
        over = [psi for psi in PSI if stats(label, psi)[0] > start + DEGRADED]
        md.append("- {}: {}".format(legend, "psi = {:g}".format(over[0]) if over else "never (up to psi = {:g})".format(PSI[-1])))
    md += ["", "Made by `scripts/studies/plasticity.py --threads {}` ({}).".format(args.threads, stamp), ""]
    write_atomically(os.path.join(OUT, "table.md"), "\n".join(md))

    # errors.gp: the mean rms error against psi, one line per method; log x.
    means = ["psi," + ",".join(label for label, _, _, _ in METHODS[1:])]
    for psi in PSI:
        means.append("{:g},".format(psi) + ",".join("{:.6g}".format(stats(label, psi)[0]) for label, _, _, _ in METHODS[1:]))
    write_atomically(os.path.join(OUT, "mean_errors.csv"),
                     "# plasticity study, mean over surfaces of the rms error: scripts/studies/plasticity.py ({})\n".format(stamp)
                     + "\n".join(means) + "\n")
    plots = []
    for i, (label, _, plastic, legend) in enumerate(METHODS[1:]):
        plots.append("'mean_errors.csv' using 1:(100*${col}) with linespoints lw 2 pt {pt} dt {dt} title '{title}'".format(
            col=i + 2, pt=4 + i, dt=1 if plastic else 2, title=legend))
    script = """# Made by scripts/studies/plasticity.py: `gnuplot errors.gp` in this folder redraws from mean_errors.csv.
set datafile separator ','
set termoption noenhanced
set logscale xy
set xrange [0.25:12]
set xlabel 'plasticity index psi = (E*/H) sqrt(sigma_s/beta)'
set ylabel 'rms error of A/A0 against the capped BEM [%] (mean over 4 surfaces)'
set grid
set key outside right
set title 'Elastic (dashed) and elastic-plastic (solid) methods against the elastic-perfectly plastic BEM'
do for [t in "pngcairo svg"] {{
  if (t eq "pngcairo") {{ set terminal pngcairo noenhanced size 1300,650 font ',11'; set output 'errors.png' }}
  else {{ set terminal svg noenhanced size 1300,650 dynamic font ',11'; set output 'errors.svg' }}
  plot {plots}
}}
unset output
""".format(plots=", \\\n       ".join(plots))
    gnuplot(script, OUT, "errors")
    print("plasticity: {} written".format(OUT))


if __name__ == "__main__":
    main()
