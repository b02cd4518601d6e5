#!/usr/bin/env python3
"""What a whole command costs with and without FFTW wisdom kept between runs (issue 42); writes
results/bench/command_cost.md.

Usage: scripts/command_cost.py [--repetitions 3] [--threads 2] [--build build/release] [--out FILE]
                               [--baseline CONTACTBENCH] [--omp-wait-policy passive|default]

Measures, interleaved (cold, warm, off, cold, warm, off, ...) so that the machine's load falls on each alike:
  1. `contactbench bem S --periodic --loads 0.000478 --threads T` on a 1024^2 periodic surface S (surface A's
     spectrum, made by `contactbench generate`), wall time of the whole process:
       cold  -- a new, empty wisdom file: the finest grid's plans are measured and the file is written (a
                machine's first run); coarse levels and lattices below 512^2 are estimated (docs/solvers.md,
                Planning: the planner level chosen by the work);
       warm  -- the file the run before wrote: the measured plans are read, not measured (every later run);
       none  -- --fftw-wisdom none: nothing kept, so the planner measures only what the run's own work pays
                back (one load: nothing; the plans are estimated).
  2. `contactbench run scenes/paper/surface_A.toml --threads T --no-plots`, the BEM stage's seconds and the
     planning line of "Stages that ran" (summary.json), cold / warm / none as above.
  3. Where the 1024^2 command's time goes, per case: the stages its --progress lines report (reading the
     surface, its spectral moments, the BEM stage and within it the solve and the FFTW planning), the rest of
     the wall time (process start, wisdom read, statistics, CSV write, exit), and the page faults
     (getrusage's minor faults of the child: a first touch of a 4 KiB page each).
Medians of the repetitions; the machine is shared, so the load average is recorded beside them.
--baseline: another contactbench program (an older commit's build, say) measured the same way, interleaved
with this build's runs, so that the tables give the ratio of the two in the same run, under the same load. A
baseline older than the wisdom file (no --fftw-wisdom, no --progress: before 5ffecf8, e.g. the commit issue 42
was measured at, 6cc3e84) runs the same command in each case, planning as it always did; its solve is the CSV's
solve_seconds, its planning not reported.
"""
import argparse
import json
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def run(command, env):
    faults_before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_minflt
    start = time.perf_counter()
    done = subprocess.run(command, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"command_cost: {' '.join(map(str, command))} failed:\n{done.stderr}")
    done.page_faults = resource.getrusage(resource.RUSAGE_CHILDREN).ru_minflt - faults_before
    return wall, done


# The seconds of the stages a `bem --progress` run reports on stderr ("contactbench bem: NAME: done in S s",
# and the load's "N iterations in S s" as the solve).
def progress_stages(stderr):
    stages = {"surface": 0.0, "moments": 0.0, "bem": 0.0, "solve": 0.0, "FFTW planning": 0.0}
    for line in stderr.splitlines():
        done = re.search(r": ([^:]+): done in ([0-9.e+-]+) s$", line)
        if done and done.group(1) in stages:
            stages[done.group(1)] += float(done.group(2))
        solved = re.search(r"iterations in ([0-9.e+-]+) s$", line)
        if solved:
            stages["solve"] += float(solved.group(1))
    return stages


# Whether `program` knows --fftw-wisdom and --progress (the wisdom file came with both, issue 42).
def knows_wisdom(program):
    return "--fftw-wisdom" in subprocess.run([program, "bem", "--help"], capture_output=True, text=True).stdout


# The solve seconds of the CSV a `bem` run wrote (its last column, solve_seconds, summed over the loads).
def csv_solve_seconds(path):
    rows = [line for line in path.read_text().splitlines() if line and not line.startswith("#")]
    column = rows[0].split(",").index("solve_seconds")
    return sum(float(row.split(",")[column]) for row in rows[1:])


def stage_seconds(summary, prefix):
    return sum(s["seconds"] for s in summary["stages"] if s["name"].startswith(prefix))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--build", default="build/release")
    parser.add_argument("--out", default="results/bench/command_cost.md")
    parser.add_argument("--baseline", help="another contactbench program, measured interleaved (its commit is "
                        "what `contactbench --version` says)")
    parser.add_argument("--omp-wait-policy", choices=["passive", "default"], default="passive",
                        help="OpenMP's waiting between parallel regions: passive (OMP_WAIT_POLICY=PASSIVE, "
                        "threads sleep: fair on a machine shared with other jobs) or default (the variable "
                        "unset: libgomp spins a while first, what a user's command does)")
    args = parser.parse_args()
    cli = ROOT / args.build / "app" / "contactbench"
    threads = str(args.threads)
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")
    if args.omp_wait_policy == "default":
        env.pop("OMP_WAIT_POLICY")
    env.pop("CONTACTBENCH_FFTW_WISDOM", None)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                            text=True).stdout.strip()
    if subprocess.run(["git", "diff", "--quiet", "HEAD", "--", "core", "bem", "app"], cwd=ROOT).returncode:
        commit += "+uncommitted"
    machine = next((line.split(":", 1)[1].strip() for line in
                    subprocess.run(["lscpu"], capture_output=True, text=True).stdout.splitlines()
                    if line.startswith("Model name")), "unknown") + f" with {os.cpu_count()} cores"
    date = time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())
    loads = []

    with tempfile.TemporaryDirectory(prefix="command_cost_") as work:
        work = Path(work)
        surface = work / "s1024.txt"
        run([cli, "generate", "--sigma", "0.5e-6", "--hurst", "0.5", "--qr", "3.14e4", "--size", "200e-6",
             "--grid", "1024", "--seed", "1", "--out", surface, "--threads", threads], env)
        programs = {"this": cli}
        if args.baseline:
            programs["baseline"] = Path(args.baseline).resolve()
        cases = [(program, case) for program in programs for case in ("cold", "warm", "none")]
        wisdom_flags = {program: knows_wisdom(binary) for program, binary in programs.items()}
        scene = ROOT / "scenes" / "paper" / "surface_A.toml"
        bem_wall = {key: [] for key in cases}
        bem_stages = {key: [] for key in cases}
        bem_faults = {key: [] for key in cases}
        scene_bem = {key: [] for key in cases}
        scene_planning = {key: [] for key in cases}
        scene_wall = {key: [] for key in cases}
        for repetition in range(args.repetitions):
            for program, binary in programs.items():
                csv = work / f"bem_{program}.csv"
                bem = [binary, "bem", surface, "--periodic", "--loads", "0.000478", "--threads", threads,
                       "--out", csv] + (["--progress"] if wisdom_flags[program] else [])
                wisdom = work / f"bem_wisdom_{program}_{repetition}.txt"
                for case, flag in (("cold", str(wisdom)), ("warm", str(wisdom)), ("none", "none")):
                    loads.append(os.getloadavg()[0])
                    wall, done = run(bem + (["--fftw-wisdom", flag] if wisdom_flags[program] else []), env)
                    bem_wall[program, case].append(wall)
                    stages = progress_stages(done.stderr)
                    stages["solve"] = csv_solve_seconds(csv)
                    stages["rest"] = wall - stages["surface"] - stages["moments"] - stages["bem"]
                    bem_stages[program, case].append(stages)
                    bem_faults[program, case].append(done.page_faults)
            for program, binary in programs.items():
                scene_run = [binary, "run", scene, "--threads", threads, "--no-plots", "--quiet"]
                wisdom = work / f"scene_wisdom_{program}_{repetition}.txt"
                for case, flag in (("cold", str(wisdom)), ("warm", str(wisdom)), ("none", "none")):
                    out = work / f"run_{program}_{case}_{repetition}"
                    loads.append(os.getloadavg()[0])
                    wall, _ = run(scene_run + ["--out", out] +
                                  (["--fftw-wisdom", flag] if wisdom_flags[program] else []), env)
                    summary = json.loads((out / "summary.json").read_text())
                    scene_wall[program, case].append(wall)
                    scene_bem[program, case].append(stage_seconds(summary, "bem"))
                    scene_planning[program, case].append(stage_seconds(summary, "fftw planning"))
        baseline_version = ""
        if args.baseline:
            baseline_version = subprocess.run([programs["baseline"], "--version"], capture_output=True,
                                              text=True).stdout.strip()

    def median(values):
        return f"{statistics.median(values):.2f}"

    def spread(values):
        return " / ".join(f"{v:.2f}" for v in values)

    def ratio(series, case):
        return f"{statistics.median(series['this', case]) / statistics.median(series['baseline', case]):.2f}"

    baseline_note = (f" Baseline (--baseline, interleaved with this build's runs): `{baseline_version}`; "
                     "the ratio is this build's median over the baseline's." if args.baseline else "")
    if args.baseline and not wisdom_flags["baseline"]:
        baseline_note += (" The baseline is older than the wisdom file: it runs the same command in every case "
                          "(no --fftw-wisdom, no --progress), measuring its plans in every run; its stages "
                          "other than the solve (the CSV's solve_seconds) are not reported (0 below).")

    lines = [
        "# What a whole command costs: FFTW planning with and without wisdom kept between runs",
        "",
        f"Made by `scripts/command_cost.py --repetitions {args.repetitions} --threads {args.threads}"
        f"{' --baseline OLD/contactbench' if args.baseline else ''}"
        f"{' --omp-wait-policy default' if args.omp_wait_policy == 'default' else ''}"
        f"{' --out ' + args.out if args.out != parser.get_default('out') else ''}` at commit "
        f"{commit} on {date}; {args.threads} threads, machine: {machine}. Load average (1 min) while it ran: "
        f"{min(loads):.1f} to {max(loads):.1f} on {os.cpu_count()} cores: the machine is shared and the times "
        "are noisy; medians of the repetitions, each repetition's value listed.",
        "",
        "Planner level chosen by the work (docs/solvers.md, Planning): coarse levels and lattices below 512^2 "
        "estimated; the finest level measured when a wisdom file is kept. cold: a new wisdom file (the finest "
        "level's plans measured, FFTW_MEASURE, and the file is written: a machine's first run); warm: the file "
        "the cold run wrote (plans read, not measured: every later run); none: `--fftw-wisdom none` (nothing "
        "kept: measured only where the run's own expected work pays back, which one load or one scene does "
        "not, so estimated). The cases run interleaved. OpenMP's waiting: "
        + ("libgomp's default (OMP_WAIT_POLICY unset: threads spin a while before they sleep, what a user's "
           "command does)" if args.omp_wait_policy == "default" else
           "OMP_WAIT_POLICY=PASSIVE (threads sleep between parallel regions: fair to other jobs on a shared "
           "machine)") + "." + baseline_note,
        "",
        "## One load on a 1024^2 periodic surface, the whole `contactbench bem` process",
        "",
        "Surface: `contactbench generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 1024 "
        "--seed 1` (surface A's spectrum on 1024^2 points).",
        f"Command: `contactbench bem s1024.txt --periodic --loads 0.000478 --threads {args.threads} "
        "--fftw-wisdom FILE|none`.",
        "",
        "| case | wall [s], median | each run [s] |" + (" baseline [s], median | each run [s] | ratio |"
                                                        if args.baseline else ""),
        "|---|---:|---|" + ("---:|---|---:|" if args.baseline else ""),
    ]
    for case in ("cold", "warm", "none"):
        row = f"| {case} | {median(bem_wall['this', case])} | {spread(bem_wall['this', case])} |"
        if args.baseline:
            row += (f" {median(bem_wall['baseline', case])} | {spread(bem_wall['baseline', case])} | "
                    f"{ratio(bem_wall, case)} |")
        lines.append(row)
    lines += [
        "",
        "Where the time goes (medians of each column over the repetitions): the stages the command's "
        "--progress lines report; solve and planning are parts of the BEM stage (the rest of it: making "
        "the solver's arrays and coarse levels, the contact statistics); rest: the wall time outside the "
        "reported stages (process start and exit, the wisdom file, the CSV). Page faults: minor faults of "
        "the process (getrusage).",
        "",
        "| program | case | wall [s] | surface read [s] | moments [s] | BEM stage [s] | of which solve [s] | "
        "of which planning [s] | rest [s] | page faults |",
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for program in (("this", "baseline") if args.baseline else ("this",)):
        for case in ("cold", "warm", "none"):
            stage = {name: statistics.median(s[name] for s in bem_stages[program, case])
                     for name in ("surface", "moments", "bem", "solve", "FFTW planning", "rest")}
            lines.append(f"| {program} | {case} | {statistics.median(bem_wall[program, case]):.3f} | "
                         f"{stage['surface']:.3f} | {stage['moments']:.3f} | {stage['bem']:.3f} | "
                         f"{stage['solve']:.3f} | {stage['FFTW planning']:.3f} | {stage['rest']:.3f} | "
                         f"{statistics.median(bem_faults[program, case]):.0f} |")
    lines += [
        "",
        "## The paper's surface A scene, `contactbench run`",
        "",
        f"Command: `contactbench run scenes/paper/surface_A.toml --threads {args.threads} --no-plots --quiet "
        "--fftw-wisdom FILE|none`. BEM stage: the seconds of the stages named bem in summary.json (12 loads "
        "solved on 512^2 and 1024^2 points for the extrapolated area, and since the error bar's third grid "
        "(docs/theory.md section 9.2) on 256^2 points too); planning: the `fftw planning` line of "
        "\"Stages that ran\" (part of the BEM stage's seconds).",
        "",
        "| case | BEM stage [s], median | each run [s] | of which planning [s], median | each run [s] | whole "
        "command [s], median |" + (" baseline BEM stage [s], median | each run [s] | ratio |"
                                   if args.baseline else ""),
        "|---|---:|---|---:|---|---:|" + ("---:|---|---:|" if args.baseline else ""),
    ]
    for case in ("cold", "warm", "none"):
        row = (f"| {case} | {median(scene_bem['this', case])} | {spread(scene_bem['this', case])} | "
               f"{median(scene_planning['this', case])} | {spread(scene_planning['this', case])} | "
               f"{median(scene_wall['this', case])} |")
        if args.baseline:
            row += (f" {median(scene_bem['baseline', case])} | {spread(scene_bem['baseline', case])} | "
                    f"{ratio(scene_bem, case)} |")
        lines.append(row)
    lines.append("")
    out = ROOT / args.out
    temporary = out.with_suffix(".md.tmp")
    temporary.write_text("\n".join(lines))
    temporary.replace(out)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
