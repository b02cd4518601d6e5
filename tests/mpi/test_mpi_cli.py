"""The command line run as several MPI ranks (app/distributed_stages.hpp, docs/mpi.md) against one process.

Usage: test_mpi_cli.py CONTACTBENCH MPIEXEC RANKS

`bem` and `sweep` under mpiexec write the files a serial run writes: the BEM's areas, spot counts, iterations
and convergence flags equal, its separation, mean gap, largest pressure and fields to 1e-12 relative (the
distributed solver takes the serial iteration step for step; only the order of its global sums differs, so
they agree to round-off: 1e-12 leaves a factor of 1e3 over what 1-3 ranks showed); the sweep's rows equal.
A run's summary records the ranks and the memory per rank. The default solver (active_set) is distributed: a
command or scene that names no solver equals one process, with a hardness too (plastic counts equal). What has
no distributed version is refused. The non-periodic problem is compared as is and mirrored (the ranks extend
the patch on their slabs, mpi/distributed_mirror.hpp), and a boundary left unset is mirrored under mpiexec as in
one process.
"""
import json
import os
import subprocess
import sys
import tempfile

from mpi_outputs import csv_differences, relative, rows

contactbench, mpiexec, ranks = sys.argv[1], sys.argv[2], int(sys.argv[3])
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMP_NUM_THREADS="1", OMP_WAIT_POLICY="PASSIVE")
failures = []


def run(arguments, distributed, expect_status=0):
    command = ([mpiexec, "--oversubscribe", "-np", str(ranks)] if distributed else []) + [contactbench] + arguments
    done = subprocess.run(command, capture_output=True, text=True, env=environment, timeout=120)
    if done.returncode != expect_status:
        failures.append(f"{' '.join(command)}: exit {done.returncode}, expected {expect_status}\n{done.stderr}")
    return done


def scene_curves(scene, name, *options):
    """Runs `scene` as one process and as the ranks (outputs in work/<name> and work/<name>_mpi) and returns
    both curves.csv's rows, serial first; fewer than two when a run wrote none (a failure is recorded)."""
    curves = []
    for distributed in (False, True):
        out = os.path.join(work, name + ("_mpi" if distributed else ""))
        run(["run", scene, "--out", out, "--threads", "1", *options], distributed)
        try:
            curves.append(rows(os.path.join(out, "curves.csv")))
        except OSError as e:
            failures.append(f"run {scene}: no curves.csv ({e})")
    return curves


def rank0_surface_bytes(folder, what):
    """summary.json's rank0_surface_bytes of a distributed run's output folder (None, and a failure recorded,
    when it cannot be read)."""
    try:
        with open(os.path.join(folder, "summary.json")) as f:
            return json.load(f)["distributed"].get("rank0_surface_bytes")
    except (OSError, KeyError, ValueError) as e:
        failures.append(f"{what}: no readable summary.json ({e})")
        return None


def field(path):
    with open(path) as f:
        return [float(v) for line in f if not line.startswith("#") for v in line.split()]


def same_bem_rows(distributed, serial, what, iteration_slack=0):
    """iteration_slack: with a hardness, 1 (docs/mpi.md, "The default solver": with plastic nodes the method
    makes G p afresh, one iteration, only when the load's rescaling factor is not exactly 1, a branch the order
    of the sums decides; tests/mpi/test_mpi_active_set.cpp allows the same); else 0."""
    if len(distributed) != len(serial):
        failures.append(f"{what}: {len(distributed)} rows against {len(serial)}")
        return
    for d, s in zip(distributed, serial):
        if list(d) != list(s):
            failures.append(f"{what}: columns {list(d)} against {list(s)}")
            continue
        if abs(int(d["iterations"]) - int(s["iterations"])) > iteration_slack:
            failures.append(f"{what}: iterations {d['iterations']} against {s['iterations']} at load {s['load']}")
        for key in ("load", "area_fraction", "spots", "area_fraction_nodes", "area_fraction_corrected",
                    "converged"):
            if d[key] != s[key]:
                failures.append(f"{what}: {key} {d[key]} against {s[key]} at load {s['load']}")
        # The edge ring's shares of a non-periodic patch (issue 40; written as 0 under mpiexec before they
        # were summed over the slabs) and the plastic load: sums in another order.
        close = ["separation", "mean_gap", "max_pressure"]
        close += [k for k in ("plastic_load_fraction", "edge_contact_share", "edge_load_share") if k in s]
        for key in close:
            if relative(d[key], s[key]) > 1e-12:
                failures.append(f"{what}: {key} {d[key]} against {s[key]} at load {s['load']}")


with tempfile.TemporaryDirectory() as work:
    surface = os.path.join(work, "surface.txt")
    # 64 x 50 points: 50 rows split 17/17/16 on 3 ranks (uneven slabs).
    run(["generate", "--sigma", "1e-6", "--hurst", "0.7", "--qr", "1e5", "--size", "1e-4", "--size-y", "0.78125e-4",
         "--grid", "64", "--grid-y", "50", "--seed", "4", "--out", surface], distributed=False)
    loads = "1e-3,1e-2,5e-2"
    # None: the default solver (active_set), named by no flag.
    for solver in ("polonsky_keer", "preconditioned_cg", None):
        for boundary in (["--periodic"], ["--non-periodic", "--boundary", "as_is"],
                         ["--non-periodic", "--boundary", "mirrored"]):
            outputs = {}
            for distributed in (False, True):
                name = f"{solver or 'default'}{'_'.join(boundary)}{'_mpi' if distributed else ''}"
                out, fields = os.path.join(work, name + ".csv"), os.path.join(work, name)
                run(["bem", surface, "--loads", loads] + (["--solver", solver] if solver else []) + boundary +
                    ["--threads", "1", "--out", out, "--fields", fields], distributed)
                outputs[distributed] = (out, fields)
            what = f"bem {solver or 'default solver'} {' '.join(boundary)} on {ranks} ranks"
            same_bem_rows(rows(outputs[True][0]), rows(outputs[False][0]), what)
            for k in (1, 2, 3):
                for kind in ("pressure", "gap"):
                    d = field(f"{outputs[True][1]}_load{k}_{kind}.txt")
                    s = field(f"{outputs[False][1]}_load{k}_{kind}.txt")
                    scale = max(abs(v) for v in s)
                    worst = max(abs(a - b) for a, b in zip(d, s)) / scale
                    if len(d) != len(s) or worst > 1e-12:
                        failures.append(f"{what}: {kind} field of load {k} off by {worst:.3g} of its largest value")

    # The boundary left unset on the non-periodic problem (app/methods/bem_settings.hpp, resolve_boundary): the
    # mirror, under mpiexec as in one process (the default never changes on the ranks), and said so.
    bem_unset = {}
    for distributed in (False, True):
        out = os.path.join(work, f"unset_boundary{'_mpi' if distributed else ''}.csv")
        run(["bem", surface, "--loads", loads, "--non-periodic", "--threads", "1", "--out", out], distributed)
        with open(out) as f:
            bem_unset[distributed] = f.read()
    for distributed in (False, True):
        if "non-periodic mirrored" not in bem_unset[distributed]:
            failures.append(f"bem --non-periodic, boundary unset, {ranks if distributed else 1} rank(s): not "
                            f"mirrored:\n{bem_unset[distributed]}")
    mirrored_rows = rows(os.path.join(work, "default--non-periodic_--boundary_mirrored.csv"))
    same_bem_rows(rows(os.path.join(work, "unset_boundary_mpi.csv")), mirrored_rows,
                  f"bem --non-periodic, boundary unset, on {ranks} ranks against --boundary mirrored in one process")

    for levels in ("exact", "40", "paper"):
        outs = []
        for distributed in (False, True):
            out = os.path.join(work, f"sweep_{levels}{'_mpi' if distributed else ''}.csv")
            run(["sweep", surface, "--levels", levels, "--connectivity", "8", "--out", out], distributed)
            outs.append(rows(out))
        # The paper's levels end at the mean height, a sum over the ranks: its z may differ in the last bits.
        keys = [k for k in outs[0][0] if k not in ("z", "separation")] if levels == "paper" else list(outs[0][0])
        if [[r[k] for k in keys] for r in outs[1]] != [[r[k] for k in keys] for r in outs[0]]:
            failures.append(f"sweep --levels {levels} on {ranks} ranks differs from one process")

    # A scene: its summary records the ranks and the memory a rank held.
    scene = os.path.join(work, "scene.toml")
    with open(scene, "w") as f:
        f.write(f'name = "mpi"\nreference = "bem"\n[surface]\nfile = "{surface}"\n[material]\nE = 100e9\nnu = 0.3\n'
                '[loads]\nvalues = [1e-3, 1e-2]\n[methods.bem]\nsolver = "preconditioned_cg"\n'
                '[methods.plateau]\nmethod = "plateau"\n')
    # With --progress, rank 0 says each load solved as one process does (a line per load, in order).
    done = run(["run", scene, "--out", os.path.join(work, "run"), "--threads", "1", "--progress"], distributed=True)
    for k in (1, 2):
        if f"bem 64 x 50: load {k}/2 " not in done.stderr:
            failures.append(f"run --progress on {ranks} ranks: no progress line of load {k}/2 in: {done.stderr}")
    try:
        with open(os.path.join(work, "run", "summary.json")) as f:
            summary = json.load(f)
        if summary.get("distributed", {}).get("ranks") != ranks or not summary["distributed"]["bem_bytes_per_rank"] > 0:
            failures.append(f"summary.json: distributed = {summary.get('distributed')}")
        methods = summary["scene_as_understood"]["methods"]
        solvers = {m.get("solver") for m in methods.values() if m.get("method") == "bem"}
        if solvers != {"preconditioned_cg"}:
            failures.append(f"summary.json: the solver on {ranks} ranks recorded as {solvers}")
        if not summary["provenance"]["command"].startswith(f"mpiexec -np {ranks} "):
            failures.append(f"summary.json: the command {summary['provenance']['command']} does not say mpiexec")
        # The threads recorded are each rank's, with the ranks beside them (the stamp of every file says both).
        if summary["provenance"].get("ranks") != ranks or summary["provenance"].get("threads") != 1:
            failures.append(f"summary.json: provenance {summary['provenance']} lacks ranks {ranks} x 1 threads")
        with open(os.path.join(work, "run", "curves.csv")) as f:
            stamp = f.readline()
        if f", {ranks} ranks x 1 threads, " not in stamp:
            failures.append(f"curves.csv: the stamp does not say {ranks} ranks x 1 threads: {stamp}")
    except (OSError, KeyError, ValueError) as e:
        failures.append(f"run as {ranks} ranks: no readable summary.json ({e})")

    # A scene that names no solver gets the same default as one process, active_set, distributed: its curves
    # equal one process's.
    default_scene = os.path.join(work, "default_solver.toml")
    with open(default_scene, "w") as f:
        f.write(f'name = "mpi_default"\n[surface]\nfile = "{surface}"\n[material]\nE = 100e9\nnu = 0.3\n'
                '[loads]\nvalues = [1e-3, 1e-2]\n[methods.bem]\n')
    curves = scene_curves(default_scene, "default_run")
    if len(curves) == 2:
        same_bem_rows(curves[1], curves[0], f"run with the default solver on {ranks} ranks")

    # A hardness (interface.hardness, bem --hardness) with active_set, distributed: the same areas, spots,
    # plastic counts and convergence as one process, iterations within one (same_bem_rows), separation and
    # pressures to 1e-12 (as above). H/E* = 0.09 and loads 1e-3 to 1e-2 E*: 0.7 % to 9 % of the nodes plastic,
    # each load warm-started from the last scaled (the rule SolverEntry::load_path gives a capped load at
    # every grid, which the distributed solver follows through load_path_start).
    hard_scene = os.path.join(work, "hardness.toml")
    with open(hard_scene, "w") as f:
        f.write(f'name = "mpi_hard"\n[surface]\nfile = "{surface}"\n[material]\nE = 100e9\nnu = 0.3\n'
                '[interface]\nhardness = 1e10\n[loads]\nvalues = [1e-3, 1e-2, 5e-3]\n[methods.bem]\n')
    hard = scene_curves(hard_scene, "hard_run")
    if len(hard) == 2:
        bem = [[r for r in rows_ if r["method"] == "bem"] for rows_ in hard]
        same_bem_rows(bem[1], bem[0], f"run with a hardness on {ranks} ranks", iteration_slack=1)
        plastic = [r.get("plastic_area_fraction") for r in bem[0]]
        if None in plastic or not float(plastic[1]) > 0:
            failures.append(f"run with a hardness: no plastic nodes at load 1e-2 ({plastic}): the test tests no cap")
        if [r.get("plastic_area_fraction") for r in bem[1]] != plastic:
            failures.append(f"run with a hardness on {ranks} ranks: plastic area {[r.get('plastic_area_fraction') for r in bem[1]]} against {plastic}")
    outputs = {}
    for distributed in (False, True):
        name = "hard_bem" + ("_mpi" if distributed else "")
        out, fields = os.path.join(work, name + ".csv"), os.path.join(work, name)
        run(["bem", surface, "--loads", "1e-3,1e-2,5e-3", "--hardness", "1e10", "--threads", "1", "--out", out,
             "--fields", fields], distributed)
        outputs[distributed] = (out, fields)
    what = f"bem --hardness on {ranks} ranks"
    d_rows, s_rows = [rows(o[0]) if os.path.exists(o[0]) else [] for o in (outputs[True], outputs[False])]
    same_bem_rows(d_rows, s_rows, what, iteration_slack=1)
    for key in ("plastic_area_fraction", "plastic_load_fraction"):
        if [r.get(key) for r in d_rows] != [r.get(key) for r in s_rows] or s_rows[0].get(key) is None:
            failures.append(f"{what}: {key} {[r.get(key) for r in d_rows]} against {[r.get(key) for r in s_rows]}")
    for k in (1, 2, 3) if d_rows else ():
        for kind in ("pressure", "gap"):
            d = field(f"{outputs[True][1]}_load{k}_{kind}.txt")
            s = field(f"{outputs[False][1]}_load{k}_{kind}.txt")
            worst = max(abs(a - b) for a, b in zip(d, s)) / max(abs(v) for v in s)
            # 1e-12 of the largest value, as the fields above
            if len(d) != len(s) or worst > 1e-12:
                failures.append(f"{what}: {kind} field of load {k} off by {worst:.3g} of its largest value")

    # An elastic load path (loads.path = "as listed": down and up again, each load warm-started from the last
    # as one process does) and the distributions at a load (gathered to rank 0 and measured there as one
    # process measures them): every CSV the run writes equal to one process's, numbers to 1e-12 relative (as
    # above), timings aside.
    path_scene = os.path.join(work, "path.toml")
    with open(path_scene, "w") as f:
        f.write(f'name = "mpi_path"\ndistributions = {{ load = 1e-2, bins = 20 }}\n[surface]\nfile = "{surface}"\n'
                '[material]\nE = 100e9\nnu = 0.3\n[loads]\nvalues = [1e-3, 1e-2, 3e-3, 2e-2]\npath = "as listed"\n'
                '[methods.bem]\ntolerance = 1e-8\n')
    outs = []
    for distributed in (False, True):
        outs.append(os.path.join(work, "path_run" + ("_mpi" if distributed else "")))
        run(["run", path_scene, "--out", outs[-1], "--threads", "1", "--no-plots"], distributed)
    if all(os.path.isdir(o) for o in outs):
        written = sorted(n for n in os.listdir(outs[0]) if n.endswith(".csv"))
        for expected in ("bem_path.csv", "curves.csv"):
            if expected not in written:
                failures.append(f"run {path_scene}: no {expected} among {written}")
        if not any("distribution" in n for n in written):
            failures.append(f"run {path_scene}: no distributions CSV among {written}")
        for name in written:
            if not os.path.exists(os.path.join(outs[1], name)):
                failures.append(f"run {path_scene} on {ranks} ranks: {name} not written")
                continue
            failures.extend(csv_differences(os.path.join(outs[1], name), os.path.join(outs[0], name), 1e-12))

    # Refused, before any work, with the reason: what the distributed solver lacks, and commands with nothing
    # to distribute.
    pk_hard_scene = os.path.join(work, "hardness_pk.toml")
    with open(pk_hard_scene, "w") as f:
        f.write(f'name = "mpi_hard_pk"\n[surface]\nfile = "{surface}"\n[material]\nE = 100e9\nnu = 0.3\n'
                '[interface]\nhardness = 5e9\n[loads]\nvalues = [1e-3]\n[methods.bem]\nsolver = "polonsky_keer"\n')
    hard_path_scene = os.path.join(work, "hardness_path.toml")
    with open(hard_path_scene, "w") as f:
        f.write(f'name = "mpi_hard_path"\n[surface]\nfile = "{surface}"\n[material]\nE = 100e9\nnu = 0.3\n'
                '[interface]\nhardness = 2e9\n[loads]\nvalues = [1e-2, 1e-3]\npath = "as listed"\n[methods.bem]\n')
    for arguments, reason in ((["run", pk_hard_scene, "--out", os.path.join(work, "refused")],
                               "a hardness (interface.hardness) with solver polonsky_keer"),
                              (["bem", surface, "--loads", "1e-3", "--hardness", "5e9", "--solver", "preconditioned_cg"],
                               "a hardness (interface.hardness) with solver preconditioned_cg"),
                              (["run", hard_path_scene, "--out", os.path.join(work, "refused")],
                               'loads.path = "as listed" with interface.hardness'),
                              (["bem", surface, "--loads", "1e-3", "--float"], 'precision = "single"'),
                              (["bem", surface, "--loads", "1e-3", "--float", "--solver", "preconditioned_cg"], 'precision = "single"'),
                              (["stats", surface], "has no distributed stages")):
        done = run(arguments, distributed=True, expect_status=1)
        if reason not in done.stderr:
            failures.append(f"{' '.join(arguments)} on {ranks} ranks: '{reason}' not in: {done.stderr}")
        if arguments[0] == "run" and os.path.exists(os.path.join(work, "refused")):
            failures.append(f"{' '.join(arguments)} on {ranks} ranks: wrote its output folder before the refusal")

    # Larger than this machine even spread over its ranks: refused in preflight with the memory of every rank
    # here (DistributedBemSolver::estimated_bytes), before any work (no output folder).
    big_scene = os.path.join(work, "big.toml")
    with open(big_scene, "w") as f:
        f.write(f'name = "mpi_big"\n[surface]\nfile = "{surface}"\n[material]\nE = 100e9\nnu = 0.3\n'
                '[loads]\nvalues = [1e-3]\n[methods.bem]\nrefine = 65536\n')
    done = run(["run", big_scene, "--out", os.path.join(work, "big")], distributed=True, expect_status=1)
    for phrase in ("the BEM solve on 65536 x 65536 points", f"{ranks} ranks, {ranks} on this machine, about",
                   "more on rank 0", "GiB available"):
        if phrase not in done.stderr:
            failures.append(f"run {big_scene} on {ranks} ranks: '{phrase}' not in: {done.stderr}")
    if os.path.exists(os.path.join(work, "big")):
        failures.append(f"run {big_scene} on {ranks} ranks: wrote its output folder before the refusal")

    # A generated surface (issue 39): each rank generates its own slab, the moments, the heights' extremes and
    # the plateau model's mean gap are reduced over the slabs, and the BEM and the sweep take the slabs where
    # they are, so rank 0 never holds the whole heights (summary.json: rank0_surface_bytes 0) and the curves
    # equal one process's (the theories' areas and mean gaps to 1e-12: sums in another order). Persson's mean
    # gap integrates the lattice spectrum, so with it rank 0 gathers the heights: the whole grid's 8 B a point.
    generated = ('compare = ["area", "mean_gap"]\n[surface]\n'
                 'generate = { sigma = 1e-6, hurst = 0.7, qr = 1e5, size = 1e-4, grid = 64, seed = 4 }\n'
                 '[material]\nE = 100e9\nnu = 0.3\n[loads]\nvalues = [1e-3, 1e-2]\n[methods.bem]\n'
                 '[methods.gw]\nmethod = "gw_mccool"\n[methods.plateau]\nmethod = "plateau"\n')
    for name, extra, root_bytes in (("slabs", "", 0), ("gathered", '[methods.persson]\nmethod = "persson"\n',
                                                         64 * 64 * 8)):
        scene_path = os.path.join(work, f"generated_{name}.toml")
        with open(scene_path, "w") as f:
            f.write(f'name = "generated_{name}"\n' + generated + extra)
        curves = scene_curves(scene_path, f"generated_{name}", "--no-plots")
        if len(curves) == 2:
            bem = [[r for r in c if r["method"] == "bem"] for c in curves]
            same_bem_rows(bem[1], bem[0], f"run with a generated surface ({name}) on {ranks} ranks")
            theories = [[r for r in c if r["method"] != "bem"] for c in curves]
            if len(theories[0]) != len(theories[1]) or not theories[0]:
                failures.append(f"run with a generated surface ({name}) on {ranks} ranks: theory rows differ")
            for d, s in zip(theories[1], theories[0]):
                for key in ("area_fraction", "mean_gap"):
                    if (d.get(key) or "nan") != (s.get(key) or "nan") and \
                            not relative(d.get(key) or "nan", s.get(key) or "nan") <= 1e-12:
                        failures.append(f"run with a generated surface ({name}) on {ranks} ranks: {s['method']} "
                                        f"{key} {d.get(key)} against {s.get(key)}")
        what = f"generated surface ({name}) on {ranks} ranks"
        held = rank0_surface_bytes(os.path.join(work, f"generated_{name}_mpi"), what)
        if held != root_bytes:
            failures.append(f"{what}: rank 0 held {held} B of whole heights, expected {root_bytes}")
    # A file surface in the project's format is read by rank 0 a bounded buffer at a time, each rank's rows
    # sent to it as they are read (app/distributed_stages.cpp, read_surface_job): rank 0 never holds it whole
    # (rank0_surface_bytes 0), and the BEM rows and the plateau's curve equal one process's. The same heights
    # as a CSV matrix are read whole by rank 0 and scattered, as before (8 B a point: 64 x 50 points).
    with open(surface) as f:
        text_lines = [line for line in f.read().splitlines() if line.strip()]
    csv_surface = os.path.join(work, "surface.csv")
    with open(csv_surface, "w") as f:
        f.write("\n".join(",".join(line.split()) for line in text_lines[2:]) + "\n")
    # The CSV matrix is a record, not periodic: its BEM's boundary left unset, so mirrored, the extension made
    # on the ranks' slabs from the file's (project) or from rank 0's whole heights (CSV).
    file_scene = ('[material]\nE = 100e9\nnu = 0.3\n[loads]\nvalues = [1e-3, 1e-2]\n[methods.bem]\n'
                  '[methods.plateau]\nmethod = "plateau"\n')
    for name, source, root_bytes in (("project", f'file = "{surface}"', 0),
                                     ("csv", f'file = "{csv_surface}"\nsize = [1e-4, 0.78125e-4]', 64 * 50 * 8)):
        scene_path = os.path.join(work, f"file_{name}.toml")
        with open(scene_path, "w") as f:
            f.write(f'name = "file_{name}"\n[surface]\n{source}\n' + file_scene)
        curves = scene_curves(scene_path, f"file_{name}", "--no-plots")
        what = f"run of a {name} file surface on {ranks} ranks"
        if len(curves) == 2:
            same_bem_rows([r for r in curves[1] if r["method"] == "bem"],
                          [r for r in curves[0] if r["method"] == "bem"], what)
            for d, s in zip([r for r in curves[1] if r["method"] != "bem"],
                            [r for r in curves[0] if r["method"] != "bem"]):
                if not relative(d["area_fraction"], s["area_fraction"]) <= 1e-12:
                    failures.append(f"{what}: {s['method']} area {d['area_fraction']} against {s['area_fraction']}")
        held = rank0_surface_bytes(os.path.join(work, f"file_{name}_mpi"), what)
        if held != root_bytes:
            failures.append(f"{what}: rank0_surface_bytes {held}, expected {root_bytes}")
    # A defective file read in slabs stops every rank with the reader's error, naming the file and line (a row
    # short in the last rank's slab, row 41 of 50), not a hang.
    broken = os.path.join(work, "broken.txt")
    with open(broken, "w") as f:
        f.write("\n".join(text_lines[:2 + 40] + [" ".join(text_lines[2 + 40].split()[:-1])] + text_lines[2 + 41:]) +
                "\n")
    broken_scene = os.path.join(work, "broken.toml")
    with open(broken_scene, "w") as f:
        f.write(f'name = "broken"\n[surface]\nfile = "{broken}"\n' + file_scene)
    done = run(["run", broken_scene, "--out", os.path.join(work, "broken")], distributed=True, expect_status=1)
    if "broken.txt" not in done.stderr or "row has 63 values" not in done.stderr:
        failures.append(f"run of a defective file on {ranks} ranks: the error does not name it: {done.stderr}")

    # The default wisdom file (the user's cache folder): rank 0's wisdom under mpiexec names FFTW-MPI's solvers,
    # which a process without FFTW-MPI refuses, so it is kept in a file of its own; one process and mpiexec in
    # turn never find their file damaged, and each reuses its own.
    with tempfile.TemporaryDirectory() as cache:
        cached = dict(environment, XDG_CACHE_HOME=cache)
        cached.pop("CONTACTBENCH_FFTW_WISDOM", None)
        for distributed in (True, False, True, False):
            command = ([mpiexec, "--oversubscribe", "-np", str(ranks)] if distributed else []) + [
                contactbench, "bem", surface, "--loads", "1e-3", "--threads", "1",
                "--out", os.path.join(cache, "wisdom_run.csv")]
            done = subprocess.run(command, capture_output=True, text=True, env=cached, timeout=120)
            if done.returncode != 0 or "wisdom" in done.stderr:
                failures.append(f"{' '.join(command)} with a shared cache folder: exit {done.returncode}, {done.stderr}")
        files = sorted(os.listdir(os.path.join(cache, "contactbench")))
        if len(files) != 2 or not any("FFTW-MPI" in name for name in files):
            failures.append(f"wisdom files in the cache folder: {files}, expected one for each kind of process")

for failure in failures:
    print("FAILED:", failure)
print(f"test_mpi_cli on {ranks} ranks: {len(failures)} failures")
sys.exit(1 if failures else 0)
