#!/usr/bin/env python3
"""Renders a Google Benchmark JSON of contactbench (bench_labelling, bench_sweep, bench_bem or
bench_bem_solvers, bench_bem_adhesion, bench_fill, bench_formats_read, bench_command, bench_load_path) as
Markdown tables.

Medians of the repetitions, in milliseconds, and ratios to the references measured in the same run.
Usage: render_bench.py results/bench/labelling.json > results/bench/labelling.md
"""
import json
import re
import sys
from collections import defaultdict


def medians(data):
    """name -> median real time in ms, from the aggregate rows (or the single run of a benchmark repeated once)."""
    out = {}
    for b in data["benchmarks"]:
        scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") == "median":
            out[b["run_name"]] = b["real_time"] * scale
        elif b.get("run_type") == "iteration" and b.get("repetitions", 1) <= 1:
            out.setdefault(b["run_name"], b["real_time"] * scale)
    return out


def parse(name):
    """'labelling/opencv_bbdt/n:256/coverage:1/conn:4' -> ('opencv_bbdt', {'n': '256', ...})."""
    parts = name.split("/")
    fields = dict(p.split(":", 1) for p in parts[2:] if ":" in p)  # "real_time" carries no value
    return parts[1], fields


def fmt(value):
    return "-" if value is None else (f"{value:.3g}" if value < 100 else f"{value:.0f}")


def runs(context, command):
    """(command, commit, date) of each run recorded in the context; runs appended by BENCH_APPEND=1 are joined
    by '; then ' in each of the three keys (scripts/bench.sh)."""
    fields = [str(context.get(key, default)).split("; then ")
              for key, default in (("command", command), ("commit", "?"), ("date", "?"))]
    if len({len(f) for f in fields}) != 1:  # not aligned: show each key whole
        return [tuple("; then ".join(f) for f in fields)]
    return list(zip(*fields))


def run_of(name, made):
    """The number (1, 2, ...) of the last run whose BENCH_FILTER matches `name` (Google Benchmark's filter is a
    regular expression searched in the name): the run that made the recorded row."""
    found = None
    for k, (cmd, _, _) in enumerate(made, 1):
        _, _, pattern = cmd.partition(" with BENCH_FILTER set to ")
        if not pattern or re.search(pattern, name):
            found = k
    return found


def header(data, title, command):
    c = data["context"]
    lines = [f"# {title}", ""]
    made = runs(c, command)
    if len(made) == 1:
        lines.append(f"Made by `{made[0][0]}` at commit {made[0][1]} on {made[0][2]};")
    else:
        lines.append(f"Made in {len(made)} runs, each replacing the rows it ran (BENCH_APPEND=1), oldest first:")
        lines.append("")
        lines += [f"{k}. {date[:16].replace('T', ' ')} at commit {commit}: `{cmd}`"
                  for k, (cmd, commit, date) in enumerate(made, 1)]
        lines.append("")
    lines.append(f"{c.get('threads', '?')} threads, machine: {c.get('machine', c.get('host_name', '?'))}, "
                 f"{c.get('num_cpus', '?')} CPUs at {c.get('mhz_per_cpu', '?')} MHz; OpenCV: {c.get('opencv', 'n/a')}.")
    lines.append("Times are medians of the repetitions, in ms (wall clock). The machine is shared and noisy.")
    lines.append("")
    return lines


def labelling(data):
    t = medians(data)
    rows = defaultdict(dict)
    for name, ms in t.items():
        impl, f = parse(name)
        rows[(int(f["n"]), int(f["coverage"]), int(f["conn"]))][impl] = ms
    lines = header(data, "Labelling one level", "scripts/bench.sh labelling")
    lines.append("contactbench returns labels and every spot's area; OpenCV's connectedComponents returns labels only.")
    lines.append("The memory pass reads the heights and writes int32: the floor for any labeller.")
    lines.append("")
    lines.append("| n | coverage % | conn | contactbench | OpenCV Spaghetti | OpenCV BBDT | OpenCV SAUF | memory pass "
                 "| contactbench / best OpenCV | contactbench / memory pass |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|")
    for key in sorted(rows):
        r = rows[key]
        cb = r.get("contactbench")
        opencv = [r[k] for k in ("opencv_spaghetti", "opencv_bbdt", "opencv_sauf") if k in r]
        best = min(opencv) if opencv else None
        ratio = cb / best if cb and best else None
        floor = cb / r["memory_pass"] if cb and r.get("memory_pass") else None
        lines.append(f"| {key[0]} | {key[1]} | {key[2]} | {fmt(cb)} | {fmt(r.get('opencv_spaghetti'))} | "
                     f"{fmt(r.get('opencv_bbdt'))} | {fmt(r.get('opencv_sauf'))} | {fmt(r.get('memory_pass'))} | "
                     f"{fmt(ratio)} | {fmt(floor)} |")
    return lines


def sweep(data):
    t = medians(data)
    rows = defaultdict(dict)
    passes = {}
    for name, ms in t.items():
        mode, f = parse(name)
        if mode == "memory_pass":
            passes[int(f["n"])] = ms
        else:
            rows[(int(f["n"]), int(f["conn"]))][mode] = ms
    lines = header(data, "The geometric sweep", "scripts/bench.sh sweep")
    lines.append("levels500: the paper's 500 levels in one union-find pass; exact: every distinct height; per_level: "
                 "the same 500 levels thresholded and labelled one by one with the project's labeller. "
                 "Surfaces are not periodic.")
    lines.append("")
    lines.append("| n | conn | levels500 | exact | per_level | memory pass | per_level / levels500 "
                 "| levels500 / memory pass | exact / memory pass |")
    lines.append("|---|---|---|---|---|---|---|---|---|")
    for key in sorted(rows):
        r = rows[key]
        floor = passes.get(key[0])
        l500, exact, per = r.get("levels500"), r.get("exact"), r.get("per_level")
        lines.append(f"| {key[0]} | {key[1]} | {fmt(l500)} | {fmt(exact)} | {fmt(per)} | {fmt(floor)} | "
                     f"{fmt(per / l500 if per and l500 else None)} | {fmt(l500 / floor if l500 and floor else None)} | "
                     f"{fmt(exact / floor if exact and floor else None)} |")
    return lines


def median_rows(data):
    """name -> the median aggregate row (with its counters)."""
    rows = {b["run_name"]: b for b in data["benchmarks"]
            if b.get("run_type") == "iteration" and b.get("repetitions", 1) <= 1}
    rows.update({b["run_name"]: b for b in data["benchmarks"]
                 if b.get("run_type") == "aggregate" and b.get("aggregate_name") == "median"})
    return rows


def bem(data):
    t = medians(data)
    rows = median_rows(data)
    pairs = {}
    table = defaultdict(dict)
    for name, ms in t.items():
        kind, f = parse(name)
        if kind == "fft_pair":
            pairs[int(f["n"])] = ms
            continue
        run = name.split("/")[3]
        table[(int(f["n"]), kind)][run] = (ms, rows[name])
    lines = header(data, "The boundary-element solver (Polonsky-Keer)", "scripts/bench.sh bem")
    lines.append("Surface A (Table 1) Fourier-refined to n x n; tolerance 1e-8 on the relative pressure change. "
                 "solve: one load, P/(E* A0) = 0.01, cold start; curve: 10 loads 0.001 ... 0.01, each warm-started "
                 "from the last; cold curve: the same 10 loads, each from a new solver. One FFT pair: r2c + c2r of "
                 "the padded size (n periodic, 2n non-periodic) in the same binary; FFT pairs per iteration = one "
                 "iteration's time over that pair's (target <= 2.5; two convolutions are the floor).")
    lines.append("")
    lines.append("| n | boundary | solve [ms] | iterations | ms / iteration | FFT pair [ms] | FFT pairs / iteration "
                 "| curve [ms] | curve iterations (warm) | cold curve [ms] | cold curve iterations |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|")
    for key in sorted(table):
        r = table[key]
        solve_ms, solve_row = r.get("solve", (None, {}))
        curve_ms, curve_row = r.get("curve", (None, {}))
        cold_ms, cold_row = r.get("cold_curve", (None, {}))
        padded = key[0] if key[1] == "periodic" else 2 * key[0]
        lines.append(f"| {key[0]} | {key[1]} | {fmt(solve_ms)} | {fmt(solve_row.get('iterations'))} | "
                     f"{fmt(solve_row.get('ms_per_iteration'))} | {fmt(pairs.get(padded))} | "
                     f"{fmt(solve_row.get('fft_pairs_per_iteration'))} | {fmt(curve_ms)} | "
                     f"{fmt(curve_row.get('iterations'))} | {fmt(cold_ms)} | {fmt(cold_row.get('iterations'))} |")
    return lines


def bem_solvers(data):
    """bench_bem_solvers: the solvers at equal accuracy, and the load curves."""
    rows = median_rows(data)
    cases = defaultdict(dict)  # (surface, boundary, contact) -> n -> solver -> row
    curves = defaultdict(dict)  # (boundary, n) -> (solver, start) -> row
    capped = defaultdict(dict)  # (boundary, n, H/E*) -> solver -> row
    separations = defaultdict(dict)  # (surface, boundary, contact, n) -> solver -> row
    plastic = {}  # (boundary, n, path, H/E*, solver) -> row: plastic against elastic in one benchmark
    float_sizes = set()  # grid sizes solved in single precision (names ending /precision:float)
    for name, row in rows.items():
        parts = name.split("/")
        solver, boundary = parts[1], parts[2]
        f = dict(p.split(":", 1) for p in parts[3:] if ":" in p)
        if "curve" in f:
            curves[(boundary, int(f["n"]))][(solver, f["curve"])] = row
        elif "capped" in f:
            capped[(boundary, int(f["n"]), f["capped"])][solver] = row
        elif "plastic" in f or "plastic_cycle" in f:
            path = "cycle" if "plastic_cycle" in f else "up"
            plastic[(boundary, int(f["n"]), path, f.get("plastic", f.get("plastic_cycle")), solver)] = row
        elif "separation" in f:
            separations[(parts[5], boundary, int(f["separation"]), int(f["n"]))][solver] = row
        elif "contact" in f:
            cases[(parts[5], boundary, int(f["contact"]))].setdefault(int(f["n"]), {})[solver] = row
            if f.get("precision") == "float":
                float_sizes.add(int(f["n"]))
    solvers = sorted({s for c in cases.values() for r in c.values() for s in r})
    def size_label(n):
        return f"{n} float" if n in float_sizes else str(n)

    lines = header(data, "The boundary-element solvers at equal accuracy", "scripts/bench.sh bem_solvers")
    lines.append("Each solver is run from a cold start at the tolerances 1e-3, 1e-4, ... until its contact area "
                 "(node count) is within 1e-4 relative and its pressure within 1e-4 relative L2 of a reference "
                 "solve of the same case (plain Polonsky-Keer at 1e-12, not timed); the iterations and seconds are "
                 "those of that solve (seconds: the median of three runs), `tol` the tolerance it needed. surface_a: the paper's surface A Fourier-"
                 "refined to n x n; h08: H = 0.8, roll-off at 4 (2 pi/L), cut at each grid's Nyquist wavevector. "
                 "contact: nominal % (the reference's area fraction in the `area` column). FFT pairs / iteration: "
                 "one iteration over one r2c + c2r pair of the padded size (FFTW_MEASURE) in the same binary. "
                 "n marked float: solved in single precision, the ladder ending at float's smallest tolerance, "
                 "1e-6 (the reference is the same double solve; the FFT pair is a float one).")
    lines.append("")
    head = "| surface | boundary | contact % | n | area |"
    rule = "|---|---|---|---|---|"
    for s in solvers:
        head += f" {s} iterations | {s} [s] | {s} tol | {s} FFT pairs / it |"
        rule += "---|---|---|---|"
    # Ratios against plain Polonsky-Keer (the yardstick of issue 12), else against the first solver.
    base_solver = "polonsky_keer" if "polonsky_keer" in solvers or not solvers else solvers[0]
    others = [s for s in solvers if s != base_solver]
    for s in others:
        head += f" iterations {base_solver} / {s} | time {base_solver} / {s} |"
        rule += "---|---|"
    made = runs(data["context"], "scripts/bench.sh bem_solvers")
    head += " runs |"
    rule += "---|"
    lines += [head, rule]
    for key in sorted(cases):
        for n in sorted(cases[key]):
            r = cases[key][n]
            area = next((row["area_fraction"] for row in r.values() if "area_fraction" in row), None)
            line = f"| {key[0]} | {key[1]} | {key[2]} | {size_label(n)} | {fmt(area)} |"
            for s in solvers:
                row = r.get(s, {})
                if not row:
                    line += " - | - | - | - |"
                    continue
                if row.get("error_occurred"):
                    line += " did not reach | - | - | - |"
                    continue
                if row.get("reached") == 0:  # the tightest solve's numbers, and how far it was
                    line += (f" did not reach: {fmt(row.get('iterations'))} (area {row['area_error']:.0e}, "
                             f"pressure {row['pressure_error']:.0e})"
                             f" | {fmt(row.get('seconds'))} | {row.get('tolerance', 0):.0e} | - |")
                    continue
                line += (f" {fmt(row.get('iterations'))} | {fmt(row.get('seconds'))} | "
                         f"{row.get('tolerance', 0):.0e} | {fmt(row.get('fft_pairs_per_iteration'))} |")
            for s in others:
                a, b = r.get(base_solver, {}), r.get(s, {})
                ok = at_equal_accuracy(a) and at_equal_accuracy(b)
                line += (f" {fmt(a['iterations'] / b['iterations'])} | {fmt(a['seconds'] / b['seconds'])} |"
                         if ok else " - | - |")
            # Which runs (numbered above) made the row's cells.
            made_by = sorted({run_of(row["run_name"], made) for row in r.values()})
            line += " " + ", ".join(str(k) for k in made_by) + " |"
            lines.append(line)
    # Growth of the iteration count with the grid: the count at n over the count at the smallest n.
    lines += ["", "Iterations at n over iterations at the smallest n of the case (the growth with the grid):", ""]
    lines += ["| surface | boundary | contact % | solver | " + " | ".join(
        f"n = {size_label(n)}" for n in sorted({n for c in cases.values() for n in c})) + " |"]
    sizes = sorted({n for c in cases.values() for n in c})
    lines += ["|---|---|---|---|" + "---|" * len(sizes)]
    for key in sorted(cases):
        for s in solvers:
            counts = {n: cases[key][n][s]["iterations"] if at_equal_accuracy(cases[key][n].get(s, {})) else None
                      for n in cases[key]}
            if not any(counts.values()):
                continue
            base = counts.get(min(counts))
            cells = [fmt(counts[n] / base) if counts.get(n) and base else "-" for n in sizes]
            lines.append(f"| {key[0]} | {key[1]} | {key[2]} | {s} | " + " | ".join(cells) + " |")
    if curves:
        lines += ["", "Load curves: 10 loads P/(E* A0) = 0.001 ... 0.01 on surface_a at tolerance 1e-8, in "
                  "increasing order. cold: each load by a new solver; warm: each from the last solution scaled "
                  "to the new load; extrapolated: each from the linear extrapolation of the last two solutions.",
                  "", "| boundary | n | solver | start | iterations | seconds | iterations / cold | run |",
                  "|---|---|---|---|---|---|---|---|"]
        for key in sorted(curves):
            c = curves[key]
            for (solver, start) in sorted(c):
                row = c[(solver, start)]
                cold = c.get((solver, "cold"), {}).get("iterations")
                lines.append(f"| {key[0]} | {key[1]} | {solver} | {start} | {fmt(row.get('iterations'))} | "
                             f"{fmt(row.get('seconds'))} | "
                             f"{fmt(row['iterations'] / cold) if cold else '-'} | "
                             f"{run_of(row['run_name'], made)} |")
    if capped:
        lines += ["", "Capped load curves: the same 10 loads with the pressure capped at the hardness H (H/E* in the "
                  "table), warm-started, each solver at tolerance 1e-8. active_set caps each solve itself (a third, "
                  "plastic set); the others solve elastically, then search the flat's height with capped solves "
                  "under separation control. area and plastic: fractions at the last load.",
                  "", "| boundary | n | H/E* | solver | iterations | seconds | area | plastic | "
                  "iterations polonsky_keer / solver | time polonsky_keer / solver | run |",
                  "|---|---|---|---|---|---|---|---|---|---|---|"]
        lines += ratio_rows(capped, lambda key: f"{key[0]} | {key[1]} | {key[2]}",
                            lambda row: f"{fmt(row.get('area_fraction'))} | {fmt(row.get('plastic_area_fraction', row.get('plastic_fraction')))}",
                            made)
    if plastic:
        lines += ["", "Plastic against elastic: the same loads and grid in one benchmark (bench/bench_bem_solvers.cpp, "
                  "plastic_against_elastic), each solver at tolerance 1e-8, elastic and capped at H alternately, "
                  "three times each; seconds are the medians, ratio = plastic / elastic (goal: at most 1.5). path up: "
                  "the 10 loads P/(E* A0) = 0.001 ... 0.01; cycle: up, down to 0.001 and up again (28 solves), the "
                  "plastic one keeping its deformation. area and plastic: fractions at the top load.",
                  "", "| boundary | n | path | H/E* | solver | elastic [s] | plastic [s] | ratio | elastic iterations | "
                  "plastic iterations | area | plastic | run |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for key in sorted(plastic):
            row = plastic[key]
            lines.append(f"| {key[0]} | {key[1]} | {key[2]} | {key[3]} | {key[4]} | {fmt(row.get('elastic_seconds'))} | "
                         f"{fmt(row.get('plastic_seconds'))} | {fmt(row.get('time_ratio'))} | "
                         f"{fmt(row.get('elastic_iterations'))} | {fmt(row.get('iterations'))} | "
                         f"{fmt(row.get('area_fraction'))} | {fmt(row.get('plastic_area_fraction', row.get('plastic_fraction')))} | "
                         f"{run_of(row['run_name'], made)} |")
    if separations:
        lines += ["", "Separation control: one cold solve with the flat at the height of the equal-accuracy "
                  "reference of the case (plain Polonsky-Keer, 1e-12, under load control), each solver at "
                  "tolerance 1e-8 (seconds: the median of three runs). load error: the solve's mean pressure "
                  "against the reference's load; area error: its node count against the reference's.",
                  "", "| surface | boundary | contact % | n | solver | iterations | seconds | load error | "
                  "area error | iterations polonsky_keer / solver | time polonsky_keer / solver | run |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        lines += ratio_rows(separations, lambda key: " | ".join(str(k) for k in key),
                            lambda row: f"{row.get('load_error', 0):.1e} | {row.get('area_error', 0):.1e}", made)
    return lines


def at_equal_accuracy(row):
    """A solve that reached the accuracy (not an error row, not reached = 0), so its counts can be compared."""
    return bool(row.get("iterations")) and not row.get("error_occurred") and row.get("reached", 1) == 1


def ratio_rows(table, key_cells, extra_cells, made):
    """Rows of key -> solver -> row: iterations, seconds, the extra cells, plain Polonsky-Keer's over each, and
    the run (of `made`) that made the row."""
    out = []
    for key in sorted(table):
        base = table[key].get("polonsky_keer", {})
        for solver in sorted(table[key]):
            row = table[key][solver]
            if row.get("error_occurred"):
                out.append(f"| {key_cells(key)} | {solver} | did not converge | - | - | - | - | "
                           f"{run_of(row['run_name'], made)} |")
                continue
            ok = base.get("iterations") and not base.get("error_occurred")
            ratios = (f"{fmt(base['iterations'] / row['iterations'])} | {fmt(base['seconds'] / row['seconds'])}"
                      if ok else "- | -")
            out.append(f"| {key_cells(key)} | {solver} | {fmt(row.get('iterations'))} | "
                       f"{fmt(row.get('seconds'))} | {extra_cells(row)} | {ratios} | "
                       f"{run_of(row['run_name'], made)} |")
    return out


def bem_adhesion(data):
    """bench_bem_adhesion: the adhesive solve against the non-adhesive active_set solve of the same run."""
    lines = header(data, "What adhesion costs the boundary-element solve", "scripts/bench.sh bem_adhesion")
    lines.append("Each row: one cold adhesive solve (AdhesiveBemSolver around active_set) and, in the same repetition, "
                 "the non-adhesive active_set solve at the same mean pressure, both at the contact tolerance 1e-6 "
                 "(bench/bench_bem_adhesion.cpp). Ratio: adhesive over non-adhesive time, median of the repetitions.")
    lines.append("")
    lines.append("With a method: segment, constrained_cg rows also give the whole-surface CG's steps (cg), each one "
                 "convolution more than a step of the contact solver (bem/adhesive_constrained_cg.hpp); "
                 "projected_lbfgs rows give its quasi-Newton steps (cg) and, as iterations, its energy "
                 "evaluations (one FFT pair each) with the start's non-adhesive solve (bem/adhesive_lbfgs.hpp). "
                 "Residual: the force imbalance the adhesive solve stopped at, in units of the law's peak stress "
                 "(both methods stop at 100 x the tolerance; rows recorded before it was a counter show -).")
    lines.append("")
    lines.append("| case | adhesive [s] | iterations (outer) | non-adhesive [s] | iterations | ratio | zone [px] "
                 "| A/A0 adhesive / without | residual | converged |")
    lines.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, row in sorted(median_rows(data).items(), key=lambda item: parse(item[0])[1].get("n", "")):
        lines.append(
            f"| {name.removeprefix('bem_adhesion/')} | {row['seconds']:.3g} | {row['iterations']:.0f} "
            f"({row['outer_iterations']:.0f}"
            f"{', cg ' + format(row['cg_iterations'], '.0f') if row.get('cg_iterations', 0) > 0 else ''})"
            f" | {row['elastic_seconds']:.3g} | {row['elastic_iterations']:.0f} "
            f"| {row['ratio']:.2f} | {row['zone_pixels']:.2g} | {row['area_fraction']:.3f} / "
            f"{row['elastic_area_fraction']:.3f} | "
            f"{format(row['residual'], '.2g') if 'residual' in row else '-'} | "
            f"{'yes' if row['converged'] >= 1 else 'NO'} |")
    return lines


def fill(data):
    """bench_fill: the harmonic fill of invalid points against one memory pass over the same grid."""
    rows = median_rows(data)
    passes = {int(parse(n)[1]["n"]): r for n, r in rows.items() if n.startswith("fill/memory_pass/")}
    lines = header(data, "The harmonic fill of invalid points", "scripts/bench.sh fill")
    lines.append("The multigrid-preconditioned conjugate gradient (core/formats/harmonic_fill.cpp, one thread) on holes "
                 "of four shapes (bench/bench_fill.cpp): random_half, each point invalid with probability 1/2; "
                 "half_plane, the left half; squares_64, a checkerboard of 64-pixel squares; sparse_valid, 97 % "
                 "invalid. Memory pass: one read and write of the grid on 2 threads, the floor. Medians of the "
                 "repetitions, wall time.")
    lines.append("")
    lines.append("| holes | n | unknowns | iterations | levels | fill [ms] | memory pass [ms] | fill / memory pass "
                 "| ns per unknown |")
    lines.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    fills = [(n.split("/")[2], int(parse(n)[1]["n"]), r) for n, r in rows.items() if n.startswith("fill/harmonic/")]
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
    for holes, n, r in sorted(fills, key=lambda item: (item[0], item[1])):
        ms = r["real_time"] * scale[r["time_unit"]]
        floor = passes.get(n)
        floor_ms = floor["real_time"] * scale[floor["time_unit"]] if floor else None
        lines.append(f"| {holes} | {n} | {r['unknowns']:.0f} | {r['iterations']:.0f} | {r['levels']:.0f} | {fmt(ms)} "
                     f"| {fmt(floor_ms)} | {fmt(ms / floor_ms if floor_ms else None)} "
                     f"| {fmt(ms * 1e6 / r['unknowns'])} |")
    return lines


def formats_read(data):
    """bench_formats_read: reading a 4096^2 file of each binary format against memory passes over its bytes."""
    rows = median_rows(data)
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
    table = defaultdict(dict)  # format -> kind -> (ms, row)
    for name, r in rows.items():
        parts = name.split("/")
        table[parts[1]][parts[2]] = (r["real_time"] * scale[r["time_unit"]], r)
        table[parts[1]][parts[2] + "_cpu"] = (r["cpu_time"] * scale[r["time_unit"]], r)
    lines = header(data, "Reading a 4096^2 file of each binary format", "scripts/bench.sh formats_read")
    load = data["context"].get("load_avg")
    if load:
        lines.insert(-2, "Load average at the start (1, 5, 15 min): " + ", ".join(f"{x:.2f}" for x in load) + ".")
    lines.append("Each file is written from the format's description (bench/bench_formats_read.cpp; the project's "
                 "writers for x3p, npy, gwy) in a temporary folder, checked to read back (detected format, 4096 x "
                 "4096, one height to 1e-9 m), timed, and removed before the next. memory sum: the file's bytes, "
                 "already in memory, summed as 8-byte words; file to memory: the file (in the page cache) read "
                 "into a string. read: read_topography_reading (file read, detection, parse, channel, metres, "
                 "invalid-point checks, the Surface); + plane: levelled by the least-squares plane; + rows + "
                 "plane: each row's mean removed first. Everything runs on one thread (no reader is parallel). "
                 "MB/s: file bytes (10^6) per second of wall time. Medians of the repetitions. CPU: the thread's "
                 "CPU time, which a loaded machine inflates less than the wall time.")
    lines.append("")
    lines.append("| format | file MB | memory sum [ms] | file to memory [ms] | read [ms] | + plane [ms] "
                 "| + rows + plane [ms] | read / memory sum | read / file to memory | read MB/s | + plane MB/s "
                 "| read CPU [ms] | read / memory sum, CPU |")
    lines.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for fmt_name, kinds in table.items():  # registration order
        read_cpu, summed_cpu = kinds.get("read_cpu", (None,))[0], kinds.get("memory_sum_cpu", (None,))[0]
        def ms(kind):
            return kinds.get(kind, (None, {}))[0]
        any_row = next(iter(kinds.values()))[1]
        mb = any_row.get("file_bytes", 0) / 1e6
        read, plane = ms("read"), ms("read_plane")
        summed, slurped = ms("memory_sum"), ms("file_to_memory")
        lines.append(f"| {fmt_name} | {mb:.1f} | {fmt(summed)} | {fmt(slurped)} | {fmt(read)} | {fmt(plane)} "
                     f"| {fmt(ms('read_rows_plane'))} | {fmt(read / summed if read and summed else None)} "
                     f"| {fmt(read / slurped if read and slurped else None)} "
                     f"| {fmt(mb / read * 1e3 if read else None)} | {fmt(mb / plane * 1e3 if plane else None)} "
                     f"| {fmt(read_cpu)} | {fmt(read_cpu / summed_cpu if read_cpu and summed_cpu else None)} |")
    return lines


def command(data):
    """bench_command: the whole `contactbench bem` command in-process beside its solve alone."""
    rows = medians(data)
    lines = header(data, "The whole bem command beside its solve", "scripts/bench.sh command")
    lines.append("`contactbench bem FILE --periodic --loads ... --threads 2` run in-process (app/cli.hpp run_cli: "
                 "reading the text surface, planning from the wisdom file an untimed first run wrote, solving, the "
                 "statistics, writing the CSV; the process start is not in it) against BemSolver made on the "
                 "surface already read and solved at the same loads (bench/bench_command.cpp). Surface: "
                 "`contactbench generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid n --seed 1`; "
                 "one load 0.000478, a curve of 12 loads 0.000478 to 0.05. Medians of the repetitions, wall time.")
    lines.append("")
    lines.append("| n | loads | command [ms] | solve alone [ms] | overhead [ms] | command / solve |")
    lines.append("|---:|---:|---:|---:|---:|---:|")
    times = {}  # (whole or solve, n, loads) -> ms
    for name, ms in rows.items():
        if name.startswith("command/"):
            kind, fields = parse(name)
            times[(kind, int(fields["n"]), int(fields["loads"]))] = ms
    for n, loads in sorted({(n, loads) for _, n, loads in times}):
        whole, solve = times.get(("whole", n, loads)), times.get(("solve", n, loads))
        over = whole - solve if whole is not None and solve is not None else None
        ratio = whole / solve if whole is not None and solve else None
        lines.append(f"| {n} | {loads} | {fmt(whole)} | {fmt(solve)} | {fmt(over)} | {fmt(ratio)} |")
    return lines


def counter_medians(data):
    """name -> {counter: value} from the median aggregate rows (or the single run of a benchmark repeated
    once)."""
    out = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") == "median":
            out[b["run_name"]] = b
        elif b.get("run_type") == "iteration" and b.get("repetitions", 1) <= 1:
            out.setdefault(b["run_name"], b)
    return out


def load_path(data):
    """bench_load_path: each solver's 10-load curve with each start against 10 cold solves, in one run."""
    starts = ("scaled", "extrapolated", "cold")  # LoadPathStart's order
    lines = header(data, "Load curves: how each solver starts the next load", "scripts/bench.sh load_path")
    lines.append("10 loads, contact 1 % to 30 % (nominal, log-spaced), increasing, tolerance 1e-8, each start's "
                 "curve against the same 10 loads solved cold in the same run (bench/bench_load_path.cpp). "
                 "Iterations: the curve's total as each solver counts them (active_set's coarse levels at a "
                 "quarter); scaled, extrapolated: their ratio to the cold curve's. declared: the start the solver declares "
                 "(SolverEntry::load_path), what scenes get. Time: the solves' own seconds, medians of the "
                 "repetitions (shared machine, OMP_WAIT_POLICY=PASSIVE). area diff.: the largest over the 10 "
                 "loads of |N - N_cold| / N_cold (contact nodes) of any start.")
    lines.append("")
    lines.append("| solver | boundary | n | surface | cold iterations | scaled | extrapolated | declared | "
                 "declared / cold | cold [s] | declared [s] | time ratio | area diff. |")
    lines.append("|---|---|---:|---|---:|---:|---:|---|---:|---:|---:|---:|---:|")
    rows = []
    for name, b in counter_medians(data).items():
        parts = name.split("/")
        if parts[0] != "load_path":
            continue
        solver, boundary, n, surface = parts[1], parts[2], int(parts[3].split(":")[1]), parts[4]
        declared = starts[int(round(b["declared"]))]
        area = max(b.get(f"{s}_area_difference", 0) for s in starts)
        rows.append((solver, boundary, n, surface,
                     f"| {solver} | {boundary} | {n} | {surface} | {b['cold_iterations']:.0f} "
                     f"| {b['scaled_ratio']:.2f} | {b['extrapolated_ratio']:.2f} | {declared} "
                     f"| {b['solver_ratio']:.2f} | {fmt(b['cold_seconds'])} | {fmt(b['solver_seconds'])} "
                     f"| {b['solver_time_ratio']:.2f} | {area:.1e} |"))
    order = {"polonsky_keer": 0, "preconditioned_cg": 1, "active_set": 2}
    for row in sorted(rows, key=lambda r: (order.get(r[0], 9), r[0], r[1] != "periodic", r[2], r[3])):
        lines.append(row[4])
    return lines


def contact_stiffness(data):
    """bench_contact_stiffness: the stiffness solves of a paper scene's 12 loads, before issue 36 and after."""
    rows = median_rows(data)
    times = medians(data)
    lines = header(data, "The contact stiffness solve (K = -dP/dd of the BEM)", "scripts/bench.sh contact_stiffness")
    lines.append("Surface A (seed 1) refined to 512^2, periodic, the 12 loads of scenes/paper/surface_A_gap.toml, each "
                 "solved once by active_set at 1e-8 (not timed); a row times the 12 stiffness solves "
                 "(bench/bench_contact_stiffness.cpp). before: the implementation before issue 36; one_state: "
                 "contact_stiffness per load (fused iteration, plans per load); stage: one ContactStiffnessSolver "
                 "for the 12 loads, as the scenes run it (stage:1e-5 is the scene path). k_error: largest relative "
                 "difference of K from before:1e-10 over the loads. ratio: time over before:1e-10 of the same run.")
    lines.append("")
    lines.append("| path:tolerance | time [ms] | ratio | iterations (12 loads) | per load | FFT pairs / iteration "
                 "| k_error |")
    lines.append("|---|---:|---:|---:|---|---:|---:|")
    reference = next((t for n, t in times.items() if "/before:1e-10" in n), None)
    for name, row in rows.items():
        if "fft_pair" in name:
            continue
        label = name.split("/")[2]
        per_load = " ".join(f"{row[k]:.0f}" for k in sorted(row) if k.startswith("iterations_"))
        t = times.get(name)
        lines.append(f"| {label} | {fmt(t)} | {fmt(t / reference if t and reference else None)} "
                     f"| {row['iterations']:.0f} | {per_load} | {fmt(row.get('fft_pairs_per_iteration'))} "
                     f"| {row['k_error']:.2g} |")
    return lines


def iteration_cost(data):
    """bench_bem_solvers iteration_cost/n:<n>: one iteration of active_set against polonsky_keer (issue 42)."""
    rows = counter_medians(data)
    lines = header(data, "What one iteration costs: active_set against polonsky_keer",
                   "scripts/bench.sh bem_solvers")
    lines.append("Surface A refined to n x n, periodic, nominal 10 % contact, cold start, tolerance 1e-6; polonsky_keer "
                 "stopped after 60 iterations (its iterations all cost the same), active_set to convergence; the two "
                 "solvers interleaved, five rounds, in one benchmark (bench/bench_bem_solvers.cpp iteration_cost). "
                 "ms / iteration: the median over the rounds of a solve's time over its iterations (active_set's "
                 "coarse levels at a quarter). FFT pairs: over one r2c + c2r pair of n x n in double measured in "
                 "the same binary. ratio: active_set's ms per iteration over polonsky_keer's (issue 42's target: "
                 "at most 1.5).")
    lines.append("")
    lines.append("| n | PK iterations | PK ms / iteration | PK FFT pairs / it. | active_set iterations "
                 "| active_set ms / iteration | active_set FFT pairs / it. | ratio |")
    lines.append("|---:|---:|---:|---:|---:|---:|---:|---:|")
    found = []
    for name, b in rows.items():
        parts = name.split("/")
        if parts[0] == "iteration_cost":
            found.append((int(parts[1].split(":")[1]), b))
    for n, b in sorted(found, key=lambda item: item[0]):
        lines.append(f"| {n} | {b['polonsky_keer_iterations']:.0f} | {fmt(b['polonsky_keer_ms_per_iteration'])} "
                     f"| {fmt(b['polonsky_keer_fft_pairs_per_iteration'])} | {b['active_set_iterations']:.0f} "
                     f"| {fmt(b['active_set_ms_per_iteration'])} | {fmt(b['active_set_fft_pairs_per_iteration'])} "
                     f"| {b['ratio']:.2f} |")
    return lines


def main():
    with open(sys.argv[1]) as f:
        data = json.load(f)
    names = [b["name"] for b in data["benchmarks"]]
    if names and names[0].startswith("iteration_cost/"):
        lines = iteration_cost(data)
    elif names and names[0].startswith("load_path/"):
        lines = load_path(data)
    elif names and names[0].startswith("contact_stiffness/"):
        lines = contact_stiffness(data)
    elif names and names[0].startswith("formats_read/"):
        lines = formats_read(data)
    elif names and names[0].startswith("command/"):
        lines = command(data)
    elif names and names[0].startswith("fill/"):
        lines = fill(data)
    elif names and names[0].startswith("bem_adhesion/"):
        lines = bem_adhesion(data)
    elif names and names[0].startswith("labelling/"):
        lines = labelling(data)
    elif any(f"/{family}:" in n for n in names for family in ("contact", "curve", "capped", "separation", "plastic")):
        lines = bem_solvers(data)
    elif names and names[0].startswith("bem/"):
        lines = bem(data)
    else:
        lines = sweep(data)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
