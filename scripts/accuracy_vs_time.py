#!/usr/bin/env python3
"""What accuracy costs in time: runs the study scene and renders its Pareto front.

Runs `contactbench run scenes/studies/accuracy_vs_time.toml` (each method at several costs on surface A,
judged against the BEM at 2048 points a side and tolerance 1e-10), then writes from its summary.json:
  results/accuracy_vs_time.csv   one row per method and load: seconds, A/A0, relative error
  results/accuracy_vs_time.md    per method: seconds, max and rms |error|, on the Pareto front or not
  results/accuracy_vs_time.png, .svg   max |error| against seconds, log-log, the Pareto front drawn
Every file is written under a temporary name and renamed. Usage:
  scripts/accuracy_vs_time.py [--contactbench build/release/app/contactbench] [--threads 2]
                              [--summary FILE]   (render an existing run's summary.json instead of running)
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join("scenes", "studies", "accuracy_vs_time.toml")
RUN_FOLDER = os.path.join("results", "accuracy_vs_time_run")


def write_atomically(path, text):
    folder = os.path.dirname(path) or "."
    fd, partial = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(path) + ".")
    with os.fdopen(fd, "w") as out:
        out.write(text)
    os.replace(partial, path)


def pareto_front(rows):
    """Labels of the methods no other method beats in both time and max |error|."""
    front = []
    for r in rows:
        beaten = any(o["seconds"] <= r["seconds"] and o["max_error"] <= r["max_error"] and
                     (o["seconds"] < r["seconds"] or o["max_error"] < r["max_error"]) for o in rows)
        if not beaten:
            front.append(r["label"])
    return front


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--contactbench", default=os.path.join("build", "release", "app", "contactbench"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--summary", help="an existing summary.json (skips the run)")
    args = parser.parse_args()
    os.chdir(ROOT)

    summary_path = args.summary
    if not summary_path:
        command = [args.contactbench, "run", SCENE, "--out", RUN_FOLDER, "--threads", str(args.threads)]
        print("running:", " ".join(command), file=sys.stderr)
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        summary_path = os.path.join(RUN_FOLDER, "summary.json")
    with open(summary_path) as f:
        summary = json.load(f)
    reference = summary["reference"]
    loads = summary["loads"]
    prov = summary["provenance"]
    made_by = "scripts/accuracy_vs_time.py --threads {}".format(prov["threads"])
    stamp = "commit {}, {}, {} threads, {}".format(prov["commit"], prov["date"], prov["threads"], prov["machine"])

    rows = []
    for m in summary["methods"]:
        if m["label"] == reference:
            continue
        errors = [abs(e) for e in m["relative_error"] if e is not None]
        rows.append({"label": m["label"], "method": m["method"], "seconds": m["seconds"],
                     "max_error": max(errors) if errors else float("inf"),
                     "rms_error": m["rms_relative_error"], "parameters": m["parameters"], "m": m})
    rows.sort(key=lambda r: r["seconds"])
    front = pareto_front(rows)
    ref = next(m for m in summary["methods"] if m["label"] == reference)

    # CSV: one row per method and load.
    lines = ["# accuracy vs time: {} ({}); reference {} took {:.3g} s".format(made_by, stamp, reference, ref["seconds"])]
    buffer = [["method", "label", "seconds", "load", "area_fraction", "reference_area_fraction", "relative_error",
               "pareto"]]
    for r in rows:
        for k, load in enumerate(loads):
            a = r["m"]["area_fraction"][k]
            e = r["m"]["relative_error"][k]
            buffer.append([r["method"], r["label"], repr(r["seconds"]), repr(load), "" if a is None else repr(a),
                           repr(ref["area_fraction"][k]), "" if e is None else repr(e),
                           "1" if r["label"] in front else "0"])
    from io import StringIO
    text = StringIO()
    text.write(lines[0] + "\n")
    csv.writer(text, lineterminator="\n").writerows(buffer)
    write_atomically(os.path.join("results", "accuracy_vs_time.csv"), text.getvalue())

    # Markdown table.
    md = ["# What accuracy costs in time", "",
          "Surface A of the seed paper; error in A/A0 against `{}` (took {:.3g} s) at P/(E* A0) = {}.".format(
              reference, ref["seconds"], ", ".join("{:g}".format(l) for l in loads)),
          "Time: wall clock on {} threads of the stages each answer needed (a shared stage is charged in full to "
          "each method that needs it). Pareto: no other answer is both faster and more accurate.".format(
              prov["threads"]), "",
          "| method | time [s] | max abs error | rms error | Pareto |", "|---|---:|---:|---:|:-:|"]
    for r in rows:
        md.append("| {} | {:.3g} | {:.1f} % | {:.1f} % | {} |".format(
            r["label"], r["seconds"], 100 * r["max_error"], 100 * (r["rms_error"] or float("nan")),
            "yes" if r["label"] in front else ""))
    md += ["", "Labels: bem_<points a side>_<tolerance>; bem_x_<n>: extrapolated from n and 2n points a side "
           "(docs/theory.md section 9); plateau_<levels> (4-connectivity) on 256 points, plateau_<n> exact levels on "
           "the surface Fourier-refined to n points a side; hertz_<n>: the Hertz-consistent plateaus, this project's "
           "variant, not the paper's model (docs/theory.md section 8.3); the theories by name. "
           "Each method's parameters are in {}.".format(summary_path), "",
           "![accuracy vs time](accuracy_vs_time.png)", "",
           "Made by `{}` ({}).".format(made_by, stamp), ""]
    write_atomically(os.path.join("results", "accuracy_vs_time.md"), "\n".join(md))

    # Plot: max |error| against seconds, log-log; the front as a step line.
    family = {"bem": 1, "plateau": 2, "plateau_hertz": 4}
    data = "\n".join("{} {} {} {}".format(r["seconds"], max(r["max_error"], 1e-6), r["label"],
                                         family.get(r["method"], 3)) for r in rows)
    front_rows = sorted((r for r in rows if r["label"] in front), key=lambda r: r["seconds"])
    front_data = "\n".join("{} {}".format(r["seconds"], max(r["max_error"], 1e-6)) for r in front_rows)
    script = """set termoption noenhanced
$points << EOD
{data}
EOD
$front << EOD
{front}
EOD
set logscale xy
set xlabel 'wall time on {threads} threads [s]'
set ylabel 'max |relative error in A/A0| against {reference}'
set grid
set key bottom left
set offsets graph 0.02, graph 0.2, graph 0.05, graph 0.05
set title 'What accuracy costs in time: surface A'
do for [t in "pngcairo svg"] {{
  if (t eq "pngcairo") {{ set terminal pngcairo noenhanced size 1000,700 font ',11'; set output '{png}' }}
  else {{ set terminal svg noenhanced size 1000,700 dynamic font ',11'; set output '{svg}' }}
  plot $front using 1:2 with steps lw 2 lc rgb 'gray' title 'Pareto front', \\
       $points using 1:($4 == 1 ? $2 : NaN) with points pt 7 ps 1.3 lc rgb 'black' title 'BEM (grid, tolerance)', \\
       $points using 1:($4 == 2 ? $2 : NaN) with points pt 5 ps 1.3 lc rgb '#1f77b4' title 'plateau model (levels)', \\
       $points using 1:($4 == 3 ? $2 : NaN) with points pt 9 ps 1.5 lc rgb '#d62728' title 'analytic theories', \\
       $points using 1:($4 == 4 ? $2 : NaN) with points pt 11 ps 1.5 lc rgb '#2ca02c' title 'Hertz-consistent plateaus (this project)', \\
       $points using 1:2:3 with labels offset 1,0.6 left font ',9' notitle
}}
unset output
"""
    png_partial = os.path.join("results", ".accuracy_vs_time.png.partial")
    svg_partial = os.path.join("results", ".accuracy_vs_time.svg.partial")
    gp = script.format(data=data, front=front_data, threads=prov["threads"], reference=reference,
                       png=png_partial, svg=svg_partial)
    subprocess.run(["gnuplot"], input=gp, text=True, check=True)
    os.replace(png_partial, os.path.join("results", "accuracy_vs_time.png"))
    os.replace(svg_partial, os.path.join("results", "accuracy_vs_time.svg"))
    print("\n".join(md))


if __name__ == "__main__":
    main()
