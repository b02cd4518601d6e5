#!/usr/bin/env python3
"""The areal kappa of surface A from the boundary-element reference, under grid refinement.

Surface A of the paper (docs/theory.md section 2, Table 1: sigma = 0.5 um, H = 0.5, qr = 3.14e4 1/m, L = 200 um,
256 x 256 points, qs at the Nyquist wavevector of that grid) is generated once with seed 1 and resampled by
Fourier interpolation on n x n points (the same realisation, only sampled finer). At each nominal pressure
p/(E* gbar) the Polonsky-Keer solver (contactbench bem) gives A/A0 by node count and perimeter-corrected
(Yastrebov, Anciaux, Molinari 2017), and the areal kappa (docs/theory.md section 0) is

    kappa = (A/A0) / (p/(E* gbar)),   gbar = sqrt(<|grad h|^2>) the areal rms gradient.

Every load is a separate, cold-started solve, so the seconds column is the cost of that solve alone.
Writes results/bem_kappa/surface_a_kappa.csv and .md (each written to a temporary file and renamed), stamped
with the commit, the date (UTC), the thread count, the machine and the command that made them.

Standard library only. Usage:
    scripts/bem_kappa_table.py [--cli build/release/app/contactbench] [--sizes 256,512,1024]
                               [--pressures 0.005,0.01,0.05] [--threads 1] [--tolerance 1e-8]
"""
import argparse
import csv
import datetime
import io
import json
import os
import platform
import shlex
import subprocess
import sys
import tempfile
import time

SURFACE_A = ["--sigma", "0.5e-6", "--hurst", "0.5", "--qr", "3.14e4", "--size", "200e-6", "--grid", "256"]


def run(command):
    """Runs a command, returns its standard output; stops the script with its error output on failure."""
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"bem_kappa_table: {shlex.join(command)} failed ({result.returncode}):\n{result.stderr}")
    return result.stdout


def machine():
    """Host name and CPU model (from /proc/cpuinfo where there is one)."""
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{platform.node()} ({cpu}, {os.cpu_count()} logical CPUs)"


def commit(repository):
    try:
        out = subprocess.run(["git", "-C", repository, "rev-parse", "--short", "HEAD"], capture_output=True,
                             text=True, check=True).stdout.strip()
        # Only the sources that make the numbers count (results/ and docs may be mid-edit).
        dirty = subprocess.run(["git", "-C", repository, "status", "--porcelain", "--untracked-files=no", "--",
                                "core", "bem", "app", "theories", "CMakeLists.txt", "cmake"],
                               capture_output=True, text=True, check=True).stdout.strip()
        return out + ("-dirty" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write_atomically(path, text):
    """Writes text to a temporary file in the same folder, then renames it over path."""
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=folder, prefix=".tmp-", suffix=os.path.basename(path))
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def read_curve(path):
    """The rows of a contactbench bem CSV, a one-method scene's curves.csv (comment lines start with '#')."""
    with open(path, encoding="utf-8") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def main():
    repository = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cli", default=os.path.join(repository, "build/release/app/contactbench"),
                        help="the contactbench executable (default: build/release/app/contactbench)")
    parser.add_argument("--sizes", default="256,512,1024", help="points a side, comma-separated")
    parser.add_argument("--pressures", default="0.005,0.01,0.05", help="p/(E* gbar), comma-separated")
    parser.add_argument("--threads", type=int, default=2, help="threads for contactbench (default 2)")
    parser.add_argument("--tolerance", default="1e-8", help="relative pressure change to stop at (default 1e-8)")
    parser.add_argument("--seed", default="1", help="seed of the realisation (default 1)")
    parser.add_argument("--out", default=os.path.join(repository, "results/bem_kappa/surface_a_kappa"),
                        help="output path without extension (.csv and .md are written)")
    args = parser.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    pressures = [float(p) for p in args.pressures.split(",")]
    threads = ["--threads", str(args.threads)]

    stamp = {
        "commit": commit(repository),
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "threads": str(args.threads),
        "machine": machine(),
        "command": shlex.join([os.path.relpath(sys.argv[0], repository)] + sys.argv[1:]),
    }
    rows = []
    with tempfile.TemporaryDirectory(prefix="bem_kappa_") as work:
        for n in sizes:
            surface = os.path.join(work, f"surface_a_{n}.txt")
            run([args.cli, "generate", *SURFACE_A, "--seed", args.seed, "--refine", str(n), "--out", surface,
                 *threads])
            stats = json.loads(run([args.cli, "stats", surface, *threads]))
            gbar = stats["rms_gradient"]
            for pressure in pressures:
                curve = os.path.join(work, f"curve_{n}_{pressure}.csv")
                started = time.monotonic()
                run([args.cli, "bem", surface, "--loads", repr(pressure * gbar), "--tolerance", args.tolerance,
                     "--out", curve, *threads])
                wall = time.monotonic() - started
                (row,) = read_curve(curve)
                if row["converged"] != "1":
                    sys.exit(f"bem_kappa_table: n = {n}, p/(E* gbar) = {pressure} did not converge")
                rows.append({
                    "n": n,
                    "pressure": pressure,
                    "gbar": gbar,
                    "load": float(row["load"]),
                    "area_fraction_nodes": float(row["area_fraction_nodes"]),
                    "area_fraction_corrected": float(row["area_fraction_corrected"]),
                    "kappa_nodes": float(row["area_fraction_nodes"]) / pressure,
                    "kappa_corrected": float(row["area_fraction_corrected"]) / pressure,
                    "spots": int(row["spots"]),
                    "iterations": int(row["iterations"]),
                    "residual": float(row["residual"]),
                    "seconds": float(row["solve_seconds"]),
                    "wall_seconds": wall,
                })
                print(f"n = {n}, p/(E* gbar) = {pressure}: kappa {rows[-1]['kappa_nodes']:.4f} (nodes), "
                      f"{rows[-1]['kappa_corrected']:.4f} (corrected), {row['iterations']} iterations, "
                      f"{float(row['solve_seconds']):.2f} s", file=sys.stderr, flush=True)

    header = "".join(f"# {key}: {value}\n" for key, value in stamp.items())
    about = ("# surface A (docs/theory.md section 2, Table 1), seed " + args.seed + ", generated on 256 x 256 and "
             "Fourier-refined to n x n; periodic half-space, E* = 109.9 GPa, Polonsky-Keer tolerance " +
             args.tolerance + " on the relative pressure change, each load cold-started; "
             "kappa = (A/A0)/(p/(E* gbar)), areal gbar (docs/theory.md section 0); seconds = solver time of that "
             "solve, wall_seconds = the whole bem command (reading the file included)\n")
    columns = ["n", "pressure", "gbar", "load", "area_fraction_nodes", "area_fraction_corrected", "kappa_nodes",
               "kappa_corrected", "spots", "iterations", "residual", "seconds", "wall_seconds"]
    table = io.StringIO()
    writer = csv.DictWriter(table, fieldnames=columns, lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({key: (repr(value) if isinstance(value, float) else value) for key, value in row.items()})
    write_atomically(args.out + ".csv", header + about + table.getvalue())

    md = ["# Areal kappa of surface A (boundary-element reference)", ""]
    md += [f"- {key}: `{value}`" for key, value in stamp.items()]
    md += [
        "", about[2:].strip(), "",
        "The machine is shared: read the times within a factor of about 1.5.", "",
        "| n | p/(E* gbar) | kappa (nodes) | kappa (corrected) | spots | iterations | seconds |",
        "|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        md.append(f"| {row['n']} | {row['pressure']:g} | {row['kappa_nodes']:.4f} | {row['kappa_corrected']:.4f} "
                  f"| {row['spots']} | {row['iterations']} | {row['seconds']:.3g} |")
    write_atomically(args.out + ".md", "\n".join(md) + "\n")
    print(f"bem_kappa_table: wrote {args.out}.csv and {args.out}.md", file=sys.stderr)


if __name__ == "__main__":
    main()
