#!/usr/bin/python3
"""Runs scenes with two contactbench binaries and compares what they write, row by row.

For a change that should alter no number (a redesign): every scene's curves.csv and table.md from the old
binary against the new one, with what legitimately differs masked: wall times (the `time [s]` column and the
`*seconds` columns), the provenance lines (commit, date) and the stage timings. Text and whole numbers (areas
as node counts, spots, iterations, convergence) must be equal; other numbers agree to 1e-6 relative, because
one binary run twice already differs in the last bits of the BEM's separation, mean gap, largest pressure and
residual (FFTW_MEASURE picks its algorithms per run and the two threads' partial sums land in either order;
the `residual` column, a largest gap near round-off, moved by up to 8 % between two runs of the same binary
on the 2048^2 solves at a tolerance of 1e-10 of scenes/studies/accuracy_vs_time.toml, so it is compared to
0.2 relative: what it can still catch is a solve that stopped elsewhere). Anything else that differs is printed and the exit status is 1.

Usage: scripts/compare_scene_outputs.py OLD_BINARY NEW_BINARY [SCENE ...] [--threads N]
       (default scenes: every scenes/**/*.toml; build the old binary from the commit before the change)
Standard library only; run with Debian's /usr/bin/python3.
"""
import argparse
import csv
import io
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def masked_csv(text):
    rows = [line for line in text.splitlines() if not line.startswith("#")]
    table = list(csv.reader(io.StringIO("\n".join(rows))))
    if not table:
        return []
    header = table[0]
    keep = [k for k, name in enumerate(header) if not name.endswith("seconds")]
    return [[row[k] for k in keep if k < len(row)] for row in table]


RELATIVE = 1e-6
LOOSE = {"residual": 0.2}  # columns of round-off size, by name


def same_cell(a, b, relative=RELATIVE):
    if a == b:
        return True
    try:
        x, y = float(a), float(b)
    except ValueError:
        return False
    if a.lstrip("-").isdigit() or b.lstrip("-").isdigit():
        return False  # whole numbers must be equal
    return abs(x - y) <= relative * max(abs(x), abs(y))


def differing_cells(a, b):
    """Every (row, column name, old, new) that differs beyond its tolerance; the first row is the header."""
    if len(a) != len(b):
        return [(-1, "rows", len(a), len(b))]
    header = a[0] if a else []
    cells = []
    for k, (r, s) in enumerate(zip(a, b)):
        if len(r) != len(s):
            cells.append((k, "columns", len(r), len(s)))
            continue
        for j, (x, y) in enumerate(zip(r, s)):
            name = header[j] if j < len(header) else str(j)
            if not same_cell(x, y, LOOSE.get(name, RELATIVE)):
                cells.append((k, name, x, y))
    return cells


def masked_table(text):
    out = []
    in_method_table = False
    for line in text.splitlines():
        if line.startswith("Made by") or line.startswith("Stages that ran"):
            continue
        cells = line.split("|")
        # The method table (header "| method | time [s] | ..."): its second column is a wall time.
        in_method_table = (in_method_table and line.startswith("|")) or "| time [s] |" in line
        if in_method_table and len(cells) > 3:
            cells[2] = " t "
        out.append(cells)
    return out


def run(binary, scene, out, threads):
    done = subprocess.run([binary, "run", str(scene), "--out", str(out), "--threads", str(threads), "--quiet",
                           "--no-plots"], capture_output=True, text=True)
    return done.returncode, done.stderr


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("scenes", nargs="*")
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    scenes = [pathlib.Path(s) for s in args.scenes] or sorted(ROOT.glob("scenes/**/*.toml"))
    failures = 0
    with tempfile.TemporaryDirectory() as work:
        for k, scene in enumerate(scenes):
            outputs = []
            for name, binary in (("old", args.old), ("new", args.new)):
                folder = pathlib.Path(work) / f"{k}_{name}"
                status, err = run(binary, scene, folder, args.threads)
                outputs.append((status, err, folder))
            (s_old, e_old, f_old), (s_new, e_new, f_new) = outputs
            differences = []
            if s_old != s_new:
                differences.append(f"exit status {s_old} -> {s_new}: {e_new.strip()[:300]}")
            elif s_old == 0:
                for file, mask in (("curves.csv", masked_csv), ("table.md", masked_table)):
                    a = mask((f_old / file).read_text())
                    b = mask((f_new / file).read_text())
                    cells = differing_cells(a, b)
                    if cells:
                        shown = [f"    row {k}, {name}: {x} -> {y}" for k, name, x, y in cells[:5]]
                        differences.append(f"{file}: {len(cells)} cells differ:\n" + "\n".join(shown))
            print(f"{scene}: {'identical' if not differences else 'DIFFERS'}"
                  + ("" if s_old == 0 else f" (both exit {s_old})"))
            for d in differences:
                print("  " + d)
            failures += bool(differences)
    print(f"{len(scenes)} scenes, {failures} differ")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
