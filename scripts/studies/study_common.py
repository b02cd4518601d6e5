"""What the study scripts share: running a scene with contactbench, reading its curves.csv and summary.json,
the stamp (commit, date, threads, machine), writing files atomically, drawing with gnuplot."""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CONTACTBENCH = os.path.join("build", "release", "app", "contactbench")


def build():
    """Builds the program (the scripts always run the worktree's own code)."""
    subprocess.run(["cmake", "--build", "--preset", "release", "-j", "2", "--target", "contactbench"],
                   check=True, stdout=subprocess.DEVNULL)


def run_scene(scene, out, threads, reuse=False, plots=True):
    """Runs `contactbench run scene --out out` unless reuse and out/summary.json exists; returns the run."""
    if not (reuse and os.path.exists(os.path.join(out, "summary.json"))):
        command = [CONTACTBENCH, "run", scene, "--out", out, "--threads", str(threads), "--quiet"]
        if not plots:
            command.append("--no-plots")
        print("running:", " ".join(command), file=sys.stderr)
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return Run(out)


class Run:
    """One scene run: summary.json and curves.csv (rows by method label, each a list of dicts per load)."""

    def __init__(self, folder):
        self.folder = folder
        with open(os.path.join(folder, "summary.json")) as f:
            self.summary = json.load(f)
        self.loads = self.summary["loads"]
        self.gbar = self.summary["surface"]["rms_gradient"]
        self.rows = {}
        with open(os.path.join(folder, "curves.csv")) as f:
            lines = [line for line in f if not line.startswith("#")]
        for row in csv.DictReader(lines):
            self.rows.setdefault(row["method"], []).append(row)
        self.methods = {m["label"]: m for m in self.summary["methods"]}

    def column(self, label, name="area_fraction"):
        return [number(r.get(name, "")) for r in self.rows[label]]

    def kappa(self, area_fraction):
        """Areal kappa at the smallest load (docs/theory.md section 0)."""
        return area_fraction * self.gbar / self.loads[0]

    def stamp(self):
        p = self.summary["provenance"]
        return "commit {}, {}, {} threads, {}".format(p["commit"], p["date"], p["threads"], p["machine"])


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def write_atomically(path, text):
    folder = os.path.dirname(path) or "."
    os.makedirs(folder, exist_ok=True)
    fd, partial = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(path) + ".")
    with os.fdopen(fd, "w") as out:
        out.write(text)
    os.replace(partial, path)


def gnuplot(script, folder, name):
    """Writes folder/name.gp (which draws name.png and name.svg when run in folder) and runs it."""
    write_atomically(os.path.join(folder, name + ".gp"), script)
    subprocess.run(["gnuplot", name + ".gp"], cwd=folder, check=True)


def pct(x, signed=True):
    if x is None or not math.isfinite(x):
        return "n/a"
    return ("{:+.1f} %" if signed else "{:.1f} %").format(100 * x)


def fmt(x, spec="{:.3f}"):
    return "n/a" if x is None or not math.isfinite(x) else spec.format(x)
