#!/usr/bin/python3
"""contactbench side by side with the peer ContactMechanics (issues 34, 35, 42); writes results/peers/.

Usage (Debian's interpreter; the peer built by scripts/peers/build_contactmechanics.sh into PEER):
  OMP_WAIT_POLICY=PASSIVE /usr/bin/python3 scripts/peers/side_by_side.py --peer PEER [--part nonadhesive]
      [--repetitions 3] [--threads 2] [--grid 1024] [--build build/release]

Parts (each writes results/peers/contactmechanics_<part>.md and .csv):
  nonadhesive  a periodic self-affine surface (surface A's spectrum, `contactbench generate`, seed 1) at three
               loads chosen for about 1, 5 and 15 % contact; each load solved, interleaved, repetition after
               repetition, by (1) contactbench's Python BemSolver (the solve call timed), (2) the whole command
               `contactbench bem FILE --periodic --loads X --threads T`, (3) the peer's whole command
               (scripts/peers/contactmechanics_bem.py: a Python process that imports the peer, reads the same
               file and solves), its solve timed inside. Accuracy: every answer's contact area (nodes) against
               a tight reference (contactbench at tolerance 1e-12).
  adhesion     a sphere (R = 1 mm, E* = 1 MPa, w = 50 mJ/m^2, 256^2 over 0.5 mm, periodic) with the exponential
               law at a Maugis parameter of 0.3 (peak stress w/rho): areas at equal positive loads, the
               pull-off force, and the time, contactbench's adhesive BEM against the peer's Adhesion package.
  adhesion_rough  a periodic self-affine surface (256^2, E* = 1 MPa, w = 50 mJ/m^2, exponential law with its
               range over 3 pixels) along a path of gaps in and out, the peer under displacement control and
               contactbench at each peer state's own mean gap: net forces and repulsive areas state by state,
               and the time.
  plastic      a sphere with a hardness: contactbench's BEM with `hardness` against the peer's PlasticSystem
               (contact and plastic area against load).
The machine is shared: the load average is recorded; timings use OMP_WAIT_POLICY=PASSIVE (set here for every
process started) and are medians over the repetitions.
"""
import argparse
import csv
import io
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
E_STAR = 100e9 / (1 - 0.3**2)  # the CLI's default material (E = 100 GPa, nu = 0.3)
# The peer's penetration tolerance for the timing, in units of the surface's Sq: on 256^2 (same spectrum) it gave a
# pressure error of 4e-10 to 7e-10 against contactbench's default's 1.5e-9 to 3e-9; each run measures it again.
PENTOL_OF_SQ = 1e-9


def stamp(threads):
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                            text=True).stdout.strip()
    if subprocess.run(["git", "diff", "--quiet", "HEAD", "--", "core", "bem", "app", "python", "scripts/peers"],
                      cwd=ROOT).returncode:
        commit += "+uncommitted"
    machine = next((line.split(":", 1)[1].strip() for line in
                    subprocess.run(["lscpu"], capture_output=True, text=True).stdout.splitlines()
                    if line.startswith("Model name")), "unknown") + f" with {os.cpu_count()} cores"
    date = time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())
    return commit, date, machine


def peer_commits(peer):
    """The peer's versions as its packages report them (the build script's table maps them to commits)."""
    code = ("import ContactMechanics, SurfaceTopography, muGrid, NuMPI\n"
            "v = {m.__name__: m.__version__ for m in (ContactMechanics, SurfaceTopography, muGrid, NuMPI)}\n"
            "try:\n import Adhesion; v['Adhesion'] = Adhesion.__version__\n"
            "except Exception as e: v['Adhesion'] = 'not importable: ' + str(e)\n"
            "import json; print(json.dumps(v))")
    done = subprocess.run([sys.executable, "-c", code], env=peer_env(peer), capture_output=True, text=True)
    if done.returncode:
        sys.exit(f"side_by_side: the peer in {peer} does not import:\n{done.stderr}")
    return json.loads(done.stdout)


def peer_env(peer):
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE", PYTHONPATH=str(peer))
    # The peer's FFT (muGrid's pocketfft) runs on one thread; numpy's BLAS is held to the same two cores.
    env.setdefault("OPENBLAS_NUM_THREADS", "2")
    return env


def cb_env():
    return dict(os.environ, OMP_WAIT_POLICY="PASSIVE")


def run(command, env):
    start = time.perf_counter()
    done = subprocess.run([str(c) for c in command], env=env, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"side_by_side: {' '.join(map(str, command))} failed ({done.returncode}):\n{done.stderr}")
    return wall, done.stdout


def csv_rows(text):
    return list(csv.DictReader(io.StringIO("".join(l + "\n" for l in text.splitlines() if not l.startswith("#")))))


def median(values):
    return statistics.median(values)


def spread(values, spec="{:.3f}"):
    return " / ".join(spec.format(v) for v in values)


def write(path, text):
    path.parent.mkdir(parents=True, exist_ok=True)
    partial = path.with_name("." + path.name + ".partial")
    partial.write_text(text)
    os.replace(partial, path)


def header(title, command, args, peer_versions, loads_seen):
    commit, date, machine = stamp(args.threads)
    return [
        f"# {title}",
        "",
        f"Made by `{command}` at commit {commit} on {date}; {args.threads} threads, machine: {machine}. "
        f"Load average (1 min) while it ran: {min(loads_seen):.1f} to {max(loads_seen):.1f} on "
        f"{os.cpu_count()} cores (the machine is shared by other sessions: times are noisy; medians of "
        f"{args.repetitions} interleaved repetitions, each listed). Every process ran with "
        "OMP_WAIT_POLICY=PASSIVE.",
        "",
        "Peer: " + ", ".join(f"{k} {v}" for k, v in peer_versions.items()) +
        " (built by scripts/peers/build_contactmechanics.sh from ContactEngineering/ContactMechanics "
        "40ad18ea9caec4a613b297e188f33f9e3bc9f254, ContactEngineering/SurfaceTopography "
        "119cb66ade8917a0a62a878c82d459f959566760, ContactEngineering/Adhesion "
        "f923c56d4b3299f500d6adb586ac0057f10f9656, muSpectre/NuMPI 4a7774e8302323535eb322a139fe98d6e4627720, "
        "muSpectre/muGrid 5b49579457fa47b520371ac514ddf76ab2a919fe; docs/peers.md).",
        "",
    ]


def write_result(name, command, lines, rows):
    """results/peers/NAME.md (the lines) and NAME.csv (the rows under the command and stamp), each written whole."""
    out = ROOT / "results" / "peers" / name
    write(out.with_suffix(".md"), "\n".join(lines) + "\n")
    buffer = io.StringIO()
    buffer.write(f"# {command}; {lines[2][len('Made by '):]}\n")
    fields = sorted({key for row in rows for key in row}, key=lambda k: (k != "kind", k))
    writer = csv.DictWriter(buffer, fieldnames=fields)
    writer.writeheader()
    writer.writerows(rows)
    write(out.with_suffix(".csv"), buffer.getvalue())
    print(f"side_by_side: wrote {out}.md and .csv", file=sys.stderr)


# ---------------------------------------------------------------------------------------------------------
# Part (a): non-adhesive periodic rough contact


def choose_loads(cb, surface, threads, targets):
    """Loads at which contactbench's node area is close to the targets: a log ladder, interpolated in log-log."""
    ladder = [10 ** (-5 + 0.25 * k) for k in range(17)]  # 1e-5 .. 1e-1
    solver = cb.BemSolver(surface, E_STAR, threads=threads)
    areas = [r.area_fraction for r in solver.solve_loads(ladder)]
    chosen = []
    for target in targets:
        k = next(i for i, a in enumerate(areas) if a >= target)
        t = (math.log(target) - math.log(areas[k - 1])) / (math.log(areas[k]) - math.log(areas[k - 1]))
        load = math.exp(math.log(ladder[k - 1]) + t * (math.log(ladder[k]) - math.log(ladder[k - 1])))
        chosen.append(float(f"{load:.3g}"))
    return chosen


def part_nonadhesive(args, cb, peer_versions):
    cli = ROOT / args.build / "app" / "contactbench"
    threads = str(args.threads)
    loads_seen = [os.getloadavg()[0]]
    with tempfile.TemporaryDirectory(prefix="side_by_side_") as work:
        work = Path(work)
        surface_file = work / f"s{args.grid}.txt"
        generate = ["generate", "--sigma", "0.5e-6", "--hurst", "0.5", "--qr", "3.14e4", "--size", "200e-6",
                    "--grid", str(args.grid), "--seed", "1"]
        run([cli, *generate, "--out", surface_file, "--threads", threads], cb_env())
        surface = cb.read_topography(str(surface_file))
        loads = choose_loads(cb, surface, args.threads, [0.01, 0.05, 0.15])
        print("loads:", loads, file=sys.stderr)

        import numpy as np

        # Accuracy, before the timing: each answer's pressure field against a tight reference (contactbench at
        # tolerance 1e-12), relative L2 norm. The peer at its default tolerances, and at the tolerances used for
        # the timing: pentol = PENTOL_OF_SQ x Sq, forcetol = 1e-9 of the mean pixel force (chosen so that its
        # error is at or below contactbench's default's; both measured here, not assumed).
        matched = ["--pentol", f"{PENTOL_OF_SQ * surface.rms_height:.6g}", "--forcetol", "1e-9"]
        peer_cmd = [sys.executable, ROOT / "scripts" / "peers" / "contactmechanics_bem.py", surface_file]
        def write_report(done):
            command = (f"OMP_WAIT_POLICY=PASSIVE /usr/bin/python3 scripts/peers/side_by_side.py --peer PEER --part "
                       f"nonadhesive --repetitions {args.repetitions} --peer-repetitions {args.peer_repetitions} --threads "
                       f"{args.threads} --grid {args.grid}")
            lines = header(f"contactbench and ContactMechanics side by side: non-adhesive periodic {args.grid}^2",
                           command, args, peer_versions, loads_seen)
            lines += [
                f"Surface: `contactbench {' '.join(generate)}` (surface A's spectrum: sigma 0.5 um, H = 0.5, "
                f"qr = 3.14e4 1/m, qs at Nyquist, 200 um, on {args.grid}^2 points), periodic, E* = {E_STAR:.4g} Pa. "
                "Loads P/(E* A0) chosen (log-log interpolation on a ladder of contactbench solves) for about 1, 5 and "
                "15 % contact.",
                "",
                "- contactbench solve: `BemSolver(surface, E*, threads=T).solve(load)` from Python (default solver "
                "active_set, tolerance 1e-8), a new solver per load (cold start), the call timed (the solver's "
                "construction, FFT planning included, is not in it).",
                f"- contactbench command: `contactbench bem FILE --periodic --loads X --threads {args.threads} "
                "--fftw-wisdom W`, the whole process (read, plan, solve, statistics, write), wall time; W was written by "
                "one untimed first run per load (the machine's first run, listed below), as the default wisdom file in "
                "the user's cache folder would be.",
                "- peer solve: ContactMechanics' `NonSmoothContactSystem.minimize_proxy(external_force=F, "
                f"pentol={PENTOL_OF_SQ:g} x Sq, forcetol=1e-9 x mean pixel force)` (constrained conjugate gradients, "
                "Polonsky-Keer; thermotol its default 1e-6; its defaults are pentol = Sq/(10 n), forcetol 1e-5 in force "
                "units, here 1e-5 of the mean pixel force), cold start, timed inside the process.",
                "- peer command: `PYTHONPATH=PEER /usr/bin/python3 scripts/peers/contactmechanics_bem.py FILE --loads "
                "X --pentol P --forcetol 1e-9` (P as above): the whole process (imports, reading the same text file with numpy, the half-space, the solve), "
                "wall time. Its FFT (muGrid's pocketfft) uses one thread; contactbench uses T.",
                "",
                "Accuracy (equal accuracy is what makes the times comparable): each answer's pressure field against "
                "contactbench at tolerance 1e-12, ||p - p_ref|| / ||p_ref||, measured in this run before the timing:",
                "",
                "| load | contactbench (default, tolerance 1e-8) | peer at its defaults | its iterations | peer as timed | "
                "its iterations | contact area, reference | areas of the three |",
                "|---:|---:|---:|---:|---:|---:|---:|---|",
                *[f"| {load:g} | {accuracy[load]['cb']:.1e} | {accuracy[load].get('peer_default', math.nan):.1e} | "
                  f"{accuracy[load].get('peer_default_iterations', '')} | {accuracy[load]['peer_matched']:.1e} | "
                  f"{accuracy[load]['peer_matched_iterations']} | {reference_area[load]:.5f} | "
                  f"{'same' if accuracy[load].get('peer_default_area', reference_area[load]) == accuracy[load]['peer_matched_area'] == reference_area[load] == median(cells[load]['cb_area']) else 'differ'} |"
                  for load in done],
                "",
                f"Timing (the peer as timed above; contactbench {args.repetitions} times per load, the peer "
                f"{args.peer_repetitions} (its run of the accuracy table{' and more' if args.peer_repetitions > 1 else ''}), "
                "each load's runs back to back; loads done so far: " + ", ".join(f"{x:g}" for x in done) + "):",
                "",
                "| load | area (reference) | cb area error | peer area error | cb iterations | peer iterations | "
                "cb solve [s] | peer solve [s] | solve ratio | cb command [s] | peer command [s] | command ratio |",
                "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
            ]
            rows = []
            totals = {"cb_solve": 0.0, "peer_solve": 0.0, "cb_command": 0.0, "peer_command": 0.0}
            for load in done:
                c = cells[load]
                ref = reference_area[load]
                m = {key: median(c[key]) for key in totals}
                for key in totals:
                    totals[key] += m[key]
                cb_error = median(c["cb_area"]) / ref - 1
                peer_error = median(c["peer_area"]) / ref - 1
                lines.append(
                    f"| {load:g} | {ref:.5f} | {cb_error:+.1e} | {peer_error:+.1e} | {median(c['cb_iterations']):.0f} | "
                    f"{median(c['peer_iterations']):.0f} | {m['cb_solve']:.3f} | {m['peer_solve']:.2f} | "
                    f"{m['peer_solve'] / m['cb_solve']:.0f}x | {m['cb_command']:.2f} | {m['peer_command']:.2f} | "
                    f"{m['peer_command'] / m['cb_command']:.0f}x |")
                rows.append({"load": load, "reference_area_fraction": ref, "cb_area_fraction": median(c["cb_area"]),
                             "cb_pressure_error": accuracy[load]["cb"], "peer_pressure_error": accuracy[load]["peer_matched"],
                             "peer_default_pressure_error": accuracy[load].get("peer_default", math.nan),
                             "peer_area_fraction": median(c["peer_area"]), "cb_iterations": median(c["cb_iterations"]),
                             "peer_iterations": median(c["peer_iterations"]),
                             "peer_converged": all(c["peer_converged"]),
                             "cb_solve_s": m["cb_solve"], "peer_solve_s": m["peer_solve"],
                             "cb_command_s": m["cb_command"], "peer_command_s": m["peer_command"],
                             "cb_first_command_s": first_command[load],
                             "cb_solve_each": spread(c["cb_solve"]), "peer_solve_each": spread(c["peer_solve"], "{:.2f}"),
                             "cb_command_each": spread(c["cb_command"]),
                             "peer_command_each": spread(c["peer_command"], "{:.2f}")})
            lines += [
                f"| all loads above | | | | | | {totals['cb_solve']:.3f} | {totals['peer_solve']:.2f} | "
                f"**{totals['peer_solve'] / totals['cb_solve']:.0f}x** | {totals['cb_command']:.2f} | "
                f"{totals['peer_command']:.2f} | **{totals['peer_command'] / totals['cb_command']:.0f}x** |",
                "",
                "Ratios: the peer's time over contactbench's (sums of the per-load medians on the last row). The peer "
                "converged at every load: " + ("yes" if all(r["peer_converged"] for r in rows) else "**no**") + ".",
                "",
                "Each repetition [s] (solve: contactbench / peer; command: contactbench / peer); the machine's first "
                "`contactbench bem` run (no wisdom file yet):",
                "",
                "| load | cb solve | peer solve | cb command | peer command | cb first command |",
                "|---:|---|---|---|---|---:|",
            ]
            for r in rows:
                lines.append(f"| {r['load']:g} | {r['cb_solve_each']} | {r['peer_solve_each']} | {r['cb_command_each']} "
                             f"| {r['peer_command_each']} | {r['cb_first_command_s']:.2f} |")
            write_result("contactmechanics_nonadhesive", command, lines, rows)



        reference = cb.BemSolver(surface, E_STAR, threads=args.threads, tolerance=1e-12)
        wisdom = work / "wisdom.txt"
        bem = [cli, "bem", surface_file, "--periodic", "--threads", threads, "--fftw-wisdom", wisdom]
        reference_area, accuracy, first_command, cells = {}, {}, {}, {}
        for k, load in enumerate(loads):
            c = cells[load] = {"cb_solve": [], "cb_iterations": [], "cb_area": [], "cb_command": [],
                               "peer_solve": [], "peer_command": [], "peer_iterations": [], "peer_area": [],
                               "peer_converged": []}
            exact = reference.solve(load)
            reference_area[load] = exact.area_fraction
            norm = np.linalg.norm(exact.pressure)
            ours = cb.BemSolver(surface, E_STAR, threads=args.threads).solve(load)
            accuracy[load] = {"cb": np.linalg.norm(ours.pressure - exact.pressure) / norm}
            # The peer at its defaults (first load only: each of its solves costs minutes at 1024^2), then at the
            # matched tolerances: that whole command is also the peer's timed run (it writes the pressure, 8 MB,
            # with np.save: a few hundredths of a second of its time).
            cases = ([("peer_default", [])] if k == 0 else []) + [("peer_matched", matched)]
            for case, options in cases:
                prefix = work / f"{case}_{k}"
                wall, out = run(peer_cmd + ["--loads", load, "--pressure-out", prefix] + options,
                                peer_env(args.peer))
                answer = json.loads(out.splitlines()[-1])
                accuracy[load][case] = np.linalg.norm(np.load(f"{prefix}_0.npy") - exact.pressure) / norm
                accuracy[load][case + "_iterations"] = answer["iterations"]
                accuracy[load][case + "_area"] = answer["area_fraction"]
                if case == "peer_matched":
                    c["peer_command"].append(wall)
                    c["peer_solve"].append(answer["solve_seconds"])
                    c["peer_iterations"].append(answer["iterations"])
                    c["peer_area"].append(answer["area_fraction"])
                    c["peer_converged"].append(answer["converged"])
            print(f"accuracy at {load}: {accuracy[load]}", file=sys.stderr)
            # A machine's first run: the wisdom file is written (reported, not in the ratio).
            first_command[load], _ = run(bem + ["--loads", load], cb_env())
            for repetition in range(args.repetitions):
                loads_seen.append(os.getloadavg()[0])
                solver = cb.BemSolver(surface, E_STAR, threads=args.threads)
                begin = time.perf_counter()
                result = solver.solve(load)
                c["cb_solve"].append(time.perf_counter() - begin)
                c["cb_iterations"].append(result.iterations)
                c["cb_area"].append(result.area_fraction)
                if not result.converged:
                    sys.exit(f"side_by_side: contactbench did not converge at load {load}")
                del solver
                wall, _ = run(bem + ["--loads", load], cb_env())
                c["cb_command"].append(wall)
                if repetition + 1 < args.peer_repetitions:
                    wall, out = run(peer_cmd + ["--loads", load] + matched, peer_env(args.peer))
                    answer = json.loads(out.splitlines()[-1])
                    c["peer_command"].append(wall)
                    c["peer_solve"].append(answer["solve_seconds"])
                    c["peer_iterations"].append(answer["iterations"])
                    c["peer_area"].append(answer["area_fraction"])
                    c["peer_converged"].append(answer["converged"])
            print(f"load {load}: cb {c['cb_solve']} s ({c['cb_command']} s command), peer {c['peer_solve']} s "
                  f"({c['peer_command']} s command)", file=sys.stderr)
            loads_seen.append(os.getloadavg()[0])
            write_report(loads[:k + 1])



# ---------------------------------------------------------------------------------------------------------
# Parts (b) and (c): a sphere, adhesive and plastic


def sphere_heights(radius, size, n):
    """A paraboloid -r^2/(2R) centred on the grid, rows along y [m]."""
    import numpy as np

    x = (np.arange(n) - n // 2) * (size / n)
    return np.ascontiguousarray(-(x[None, :] ** 2 + x[:, None] ** 2) / (2 * radius))


def relative(a, b):
    return a / b - 1 if b else math.nan


def part_adhesion(args, cb, peer_versions):
    import numpy as np

    radius, modulus, work, size, n, maugis = 1e-3, 1e6, 0.05, 0.5e-3, 256, 0.3
    # Maugis' parameter lambda = 2 sigma0 (9R/(16 pi w E*^2))^(1/3) (docs/theory.md 10.2), with the exponential
    # law's peak stress sigma0 = w/rho: the law with the same work and peak stress as Dugdale's at that lambda.
    peak = maugis / (2 * (9 * radius / (16 * math.pi * work * modulus**2)) ** (1 / 3))
    rho = work / peak
    heights = sphere_heights(radius, size, n)
    area0 = size * size
    lift = heights.max() - heights.mean()  # the apex above the mean plane: separation d = lift - indentation
    start, turn, steps = 2 * rho, -1.2 * rho, 20  # indentations: from 2 rho apart to 1.2 rho into contact
    loads_seen = [os.getloadavg()[0]]
    surface = cb.Surface(heights, lx=size, periodic=True)
    law = {"model": "exponential", "work": work, "range": rho}
    with tempfile.TemporaryDirectory(prefix="side_by_side_") as work_dir:
        heights_file = Path(work_dir) / "sphere.npy"
        np.save(heights_file, heights)
        cb_seconds, peer_seconds, peer_states, path = [], [], None, None
        for repetition in range(args.repetitions):
            loads_seen.append(os.getloadavg()[0])
            solver = cb.BemSolver(surface, modulus, adhesion=law, threads=args.threads)
            begin = time.perf_counter()
            path = solver.approach_retract(lift + start, lift + turn, steps)
            cb_seconds.append(time.perf_counter() - begin)
            indentations = [lift - d for d in path.separation]
            wall, out = run([sys.executable, ROOT / "scripts" / "peers" / "contactmechanics_sphere.py", "adhesion",
                             heights_file, "--size", size, "--modulus", modulus, "--work", work, "--range", rho,
                             "--indentations=" + ",".join(f"{d:.17g}" for d in indentations)], peer_env(args.peer))
            answer = json.loads(out)
            peer_seconds.append(sum(s["seconds"] for s in answer["states"]))
            peer_states = answer["states"]
            print(f"rep {repetition}: cb path {cb_seconds[-1]:.2f} s, peer path {peer_seconds[-1]:.2f} s",
                  file=sys.stderr)
        # Equal states: each peer state's own mean gap is contactbench's separation on a periodic surface, so
        # the same state is solved by both; followed along the path, each from the last (not timed).
        at_peer_gap = cb.BemSolver(surface, modulus, adhesion=law, threads=args.threads)
        same_gap = [at_peer_gap.solve_for_separation(state["mean_gap"]) for state in peer_states]
        # Equal load: the peer's loaded states on the approach (positive net force) solved by contactbench under
        # load control, the repulsive contact area compared.
        load_control = cb.BemSolver(surface, modulus, adhesion=law, threads=args.threads)
        equal_load = []
        for k, state in enumerate(peer_states):
            if path.approaching[k] and state["force"] > 0 and state["contact_fraction"] > 0:
                result = load_control.solve(state["force"] / (modulus * area0))
                equal_load.append((state["force"], state["contact_fraction"], result.area_fraction,
                                   result.converged, result.zone_pixels))
    loads_seen.append(os.getloadavg()[0])

    cb_force = np.asarray(path.load) * modulus * area0
    peer_force = np.array([s["force"] for s in peer_states])
    retract = ~np.asarray(path.approaching, dtype=bool)
    cb_pull_off = path.pull_off_load * modulus * area0
    peer_pull_off = float(peer_force[retract].min())
    dmt, jkr = -2 * math.pi * radius * work, -1.5 * math.pi * radius * work
    command = (f"OMP_WAIT_POLICY=PASSIVE /usr/bin/python3 scripts/peers/side_by_side.py --peer PEER --part "
               f"adhesion --repetitions {args.repetitions} --threads {args.threads}")
    lines = header("contactbench and ContactMechanics' Adhesion side by side: an adhesive sphere", command, args,
                   peer_versions, loads_seen)
    lines += [
        f"Sphere (paraboloid) R = {radius:g} m, E* = {modulus:g} Pa, w = {work:g} J/m^2, {n}^2 points over "
        f"{size:g} m, periodic. Exponential law a(g) = (w/rho) exp(-g/rho) with rho = {rho:.4g} m (peak stress "
        f"{peak:.4g} Pa: Maugis' lambda = {maugis} for a Dugdale law of that stress; docs/theory.md 10.2); "
        f"rho is {rho / (size / n):.2f} pixels.",
        "",
        "- contactbench: `BemSolver(surface, E*, adhesion={'model': 'exponential', 'work': w, 'range': rho}, "
        f"threads={args.threads})`, `approach_retract(start, turn, {steps})` (separation control, each state "
        "from the last; default solver and tolerance), timed around the call.",
        "- peer: Adhesion's `Exponential(w, rho)` in a `BoundedSmoothContactSystem` on ContactMechanics' "
        "`PeriodicFFTElasticHalfSpace`, `minimize_proxy` (L-BFGS-B with the bound gap >= 0, its default; gtol 1e-6 "
        "of the peak stress's pixel force) at the same states (the apex's indentation lift - d, lift the apex's "
        "height above the mean plane), each from the last "
        "(scripts/peers/contactmechanics_sphere.py), the solves' seconds summed.",
        "",
        "## Pull-off (least net force on the retract branch, sampled at the path's states)",
        "",
        "| | contactbench | peer | relative difference |",
        "|---|---:|---:|---:|",
        f"| pull-off force [N] | {cb_pull_off:.5e} | {peer_pull_off:.5e} | "
        f"{relative(cb_pull_off, peer_pull_off):+.2e} |",
        f"| over pi R w | {cb_pull_off / (math.pi * radius * work):.4f} | "
        f"{peer_pull_off / (math.pi * radius * work):.4f} | (DMT -2, JKR -1.5) |",
        "",
        "## Repulsive contact area at equal net load (the peer's loaded approach states; contactbench under load "
        "control)",
        "",
        "| net force [N] | peer contact radius [m] | contactbench contact radius [m] | radius difference | area "
        "difference | contactbench converged | zone pixels |",
        "|---:|---:|---:|---:|---:|---|---:|",
    ]
    rows = []
    for force, peer_area, cb_area, converged, zone in equal_load:
        peer_a = math.sqrt(peer_area * area0 / math.pi)
        cb_a = math.sqrt(cb_area * area0 / math.pi)
        lines.append(f"| {force:.4e} | {peer_a:.4e} | {cb_a:.4e} | {relative(cb_a, peer_a):+.2e} | "
                     f"{relative(cb_area, peer_area):+.2e} | {'yes' if converged else 'no'} | "
                     f"{zone if zone is not None else math.nan:.1f} |")
        rows.append({"kind": "equal_load", "force_N": force, "peer_area_fraction": peer_area,
                     "cb_area_fraction": cb_area, "cb_converged": converged})
    same_state = [(k, cb_force[k], peer_force[k], path.contact_fraction[k], peer_states[k]["contact_fraction"])
                  for k in range(len(peer_states))]
    force_scale = math.pi * radius * work
    worst_force = max(abs(c - p) for _, c, p, _, _ in same_state) / force_scale
    both = [k for k in range(len(peer_states)) if peer_states[k]["converged"] and same_gap[k].converged]
    gap_force = [same_gap[k].load * modulus * area0 for k in range(len(peer_states))]
    gap_worst_force = max(abs(gap_force[k] - peer_force[k]) for k in both) / force_scale
    gap_worst_area = max((abs(relative(same_gap[k].area_fraction, peer_states[k]["contact_fraction"])) for k in both
                          if peer_states[k]["contact_fraction"] > 0), default=0.0)
    peer_least = min(range(len(peer_states)), key=lambda k: peer_force[k] if retract[k] else math.inf)
    lines += [
        "",
        "## The same states at the peer's own mean gap",
        "",
        "Each peer state's mean gap, which contactbench takes as its separation on a periodic surface, names the "
        "same state in both; contactbench solves the 41 states at those mean gaps, each from the last. Where both "
        f"converged ({len(both)} of {len(peer_states)} states): the net forces within {gap_worst_force:.1e} pi R w "
        f"of each other, the repulsive areas within {gap_worst_area:.1e} relative. At the peer's least net force "
        f"on the retract branch (state {peer_least}): peer {peer_force[peer_least]:.6e} N, contactbench at the "
        f"same mean gap {gap_force[peer_least]:.6e} N ({relative(gap_force[peer_least], peer_force[peer_least]):+.1e}"
        " relative).",
        "",
        "## The same path state by state, at the same indentation",
        "",
        f"The largest net-force difference at the same indentation over the {len(same_state)} states is "
        f"{worst_force:.2e} pi R w. The two do not place the flat alike for a given indentation (where the "
        "mean displacement of the periodic half-space is put), so the states at one indentation differ while the "
        "states at one load or one mean gap agree (the tables above); the pull-off, sampled at each one's own "
        "path states, inherits that shift of the samples. Peer states that did not converge (L-BFGS-B's own "
        f"flag): {sum(not s['converged'] for s in peer_states)} of {len(peer_states)}.",
        "",
        "## Time",
        "",
        f"The whole path ({len(same_state)} states): contactbench {median(cb_seconds):.2f} s (each "
        f"{spread(cb_seconds, '{:.2f}')}), peer {median(peer_seconds):.2f} s (each "
        f"{spread(peer_seconds, '{:.2f}')}): ratio **{median(peer_seconds) / median(cb_seconds):.1f}x**. "
        f"Peer converged at every state: {'yes' if all(s['converged'] for s in peer_states) else '**no**'}; "
        f"contactbench's path converged: {'yes' if path.converged else '**no**'}.",
    ]
    for k, c, p, ca, pa in same_state:
        rows.append({"kind": "path", "state": k, "approaching": bool(path.approaching[k]),
                     "indentation_m": lift - path.separation[k], "cb_force_N": c, "peer_force_N": p,
                     "cb_area_fraction": ca, "peer_area_fraction": pa,
                     "peer_converged": peer_states[k]["converged"], "peer_iterations": peer_states[k]["iterations"],
                     "peer_mean_gap_m": peer_states[k]["mean_gap"], "cb_force_at_peer_gap_N": gap_force[k],
                     "cb_area_at_peer_gap": same_gap[k].area_fraction})
    write_result("contactmechanics_adhesion", command, lines, rows)


def part_adhesion_rough(args, cb, peer_versions):
    import numpy as np

    modulus, work, size, n, seed = 1e6, 0.05, 200e-6, 256, 1
    sigma, hurst, pixels_per_range = 0.5e-6, 0.5, 3
    grid = cb.Grid(nx=n, ny=n, lx=size, ly=size, periodic=True)
    surface = cb.generate_surface(grid, cb.SelfAffinePsd(sigma=sigma, hurst=hurst, qr=2 * math.pi * 4 / size),
                                  seed=seed, threads=args.threads)
    heights = np.asarray(surface.heights)
    rho = pixels_per_range * size / n
    law = {"model": "exponential", "work": work, "range": rho}
    area0 = size * size
    # The peer places its rigid surface at heights + offset with offset = indentation - max(h) and lets the
    # periodic half-space's mean displacement follow the force, so a state is named here by the peer's own
    # mean gap after its solve, which contactbench, on a periodic surface, takes as its separation (its
    # separation is the mean gap there): the same state in both (docs/peers.md).
    approach = [2.0, 1.6, 1.3, 1.1, 0.9, 0.75, 0.6, 0.5]  # nominal gaps in units of sigma, approach ...
    nominal = [g * sigma for g in approach + approach[-2::-1]]  # ... then back out along the same gaps
    indentations = [heights.max() - heights.mean() - g for g in nominal]
    loads_seen = [os.getloadavg()[0]]
    cb_seconds, peer_seconds, states, cb_results = [], [], None, None
    with tempfile.TemporaryDirectory(prefix="side_by_side_") as work_dir:
        heights_file = Path(work_dir) / "rough.npy"
        np.save(heights_file, heights)
        for repetition in range(args.repetitions):
            loads_seen.append(os.getloadavg()[0])
            wall, out = run([sys.executable, ROOT / "scripts" / "peers" / "contactmechanics_sphere.py", "adhesion",
                             heights_file, "--size", size, "--modulus", modulus, "--work", work, "--range", rho,
                             "--indentations=" + ",".join(f"{d:.17g}" for d in indentations)], peer_env(args.peer))
            states = json.loads(out)["states"]
            peer_seconds.append(sum(s["seconds"] for s in states))
            solver = cb.BemSolver(surface, modulus, adhesion=law, threads=args.threads)
            begin = time.perf_counter()
            cb_results = [solver.solve_for_separation(state["mean_gap"]) for state in states]
            cb_seconds.append(time.perf_counter() - begin)
            print(f"rep {repetition}: cb {cb_seconds[-1]:.2f} s, peer {peer_seconds[-1]:.2f} s", file=sys.stderr)
    loads_seen.append(os.getloadavg()[0])
    rows, table = [], []
    for k, (state, result) in enumerate(zip(states, cb_results)):
        cb_force = result.load * modulus * area0
        both = state["converged"] and result.converged
        rows.append({"kind": "state", "state": k, "approaching": k < len(approach), "mean_gap_m": state["mean_gap"],
                     "cb_force_N": cb_force, "peer_force_N": state["force"],
                     "cb_area_fraction": result.area_fraction, "peer_area_fraction": state["contact_fraction"],
                     "cb_attractive_fraction": result.attractive_fraction, "cb_converged": result.converged,
                     "peer_converged": state["converged"], "cb_iterations": result.iterations,
                     "peer_iterations": state["iterations"]})
        table.append((k, state, result, cb_force, both))
    compared = [t for t in table if t[4]]
    worst_force = max(abs(relative(c, s["force"])) for _, s, _, c, _ in compared)
    worst_area = max(abs(relative(r.area_fraction, s["contact_fraction"])) for _, s, r, _, _ in compared
                     if s["contact_fraction"] > 0)
    command = (f"OMP_WAIT_POLICY=PASSIVE /usr/bin/python3 scripts/peers/side_by_side.py --peer PEER --part "
               f"adhesion_rough --repetitions {args.repetitions} --threads {args.threads}")
    lines = header("contactbench and ContactMechanics' Adhesion side by side: an adhesive rough surface", command,
                   args, peer_versions, loads_seen)
    lines += [
        f"Surface: `generate_surface` of a self-affine spectrum (sigma = {sigma:g} m, H = {hurst}, roll-off at "
        f"qr = 2 pi 4/L, cut off at the grid's Nyquist wavevector), seed {seed}, {n}^2 points over {size:g} m, "
        f"periodic; E* = {modulus:g} Pa, w = {work:g} J/m^2, the exponential law a(g) = (w/rho) exp(-g/rho) with "
        f"rho = {rho:.4g} m ({pixels_per_range} pixels; peak stress {work / rho:.4g} Pa). With the range resolved "
        "by the pixel, it is of the order of the roughness, so most of the surface lies inside the attractive "
        "range and the net force is tensile along the whole path: a hard adhesive case, not a physical one.",
        "",
        "- peer: Adhesion's `Exponential(w, rho)` in a `BoundedSmoothContactSystem` on ContactMechanics' "
        "`PeriodicFFTElasticHalfSpace`, `minimize_proxy` (L-BFGS-B with the bound gap >= 0, gtol 1e-6 of the "
        "peak stress's pixel force) along the offsets of nominal gaps " +
        ", ".join(f"{g:g}" for g in approach) + " sigma and back, each state from the last "
        "(scripts/peers/contactmechanics_sphere.py), its solves' seconds summed.",
        "- contactbench: `BemSolver(surface, E*, adhesion={'model': 'exponential', 'work': w, 'range': rho}, "
        f"threads={args.threads}).solve_for_separation(g)` at each peer state's own mean gap g (on a periodic "
        "surface contactbench's separation is the mean gap), in the same order, each from the last; default "
        "solver and tolerance; timed around the calls.",
        "",
        "## The same states",
        "",
        f"Where both converged ({len(compared)} of {len(table)} states): net force within "
        f"**{worst_force:.1e}** relative, repulsive contact area (gap 0) within **{worst_area:.1e}** relative "
        "(the issue asks 1e-3).",
        "",
        "| state | leg | mean gap [m] | net force, peer [N] | contactbench | relative | area, peer | contactbench "
        "| relative | attractive area (contactbench) | converged (peer / cb) |",
        "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|",
    ]
    for k, state, result, cb_force, both in table:
        leg = "approach" if k < len(approach) else "retract"
        area_difference = (f"{relative(result.area_fraction, state['contact_fraction']):+.1e}"
                           if state["contact_fraction"] > 0 else ("same" if result.area_fraction == 0 else "n/a"))
        lines.append(f"| {k} | {leg} | {state['mean_gap']:.5e} | {state['force']:.6e} | {cb_force:.6e} | "
                     f"{relative(cb_force, state['force']):+.1e} | {state['contact_fraction']:.6f} | "
                     f"{result.area_fraction:.6f} | {area_difference} | {result.attractive_fraction:.4f} | "
                     f"{'yes' if state['converged'] else 'no'} / {'yes' if result.converged else 'no'} |")
    lines += [
        "",
        "## Time",
        "",
        f"The {len(table)} states: contactbench {median(cb_seconds):.2f} s (each {spread(cb_seconds, '{:.2f}')}), "
        f"peer {median(peer_seconds):.2f} s (each {spread(peer_seconds, '{:.2f}')}): ratio "
        f"**{median(peer_seconds) / median(cb_seconds):.1f}x**.",
    ]
    write_result("contactmechanics_adhesion_rough", command, lines, rows)


def part_plastic(args, cb, peer_versions):
    import numpy as np

    radius, modulus, hardness, size, n = 1e-3, E_STAR, 1e9, 0.25e-3, 256
    heights = sphere_heights(radius, size, n)
    area0 = size * size
    # Hertz: the largest pressure p0 = (6 P E*^2 / (pi^3 R^2))^(1/3) reaches H at P_y = pi^3 R^2 H^3 / (6 E*^2).
    yield_force = math.pi**3 * radius**2 * hardness**3 / (6 * modulus**2)
    multiples = [0.5, 0.8, 1.0, 1.25, 2.0, 4.0, 8.0]
    loads = [m * yield_force / (modulus * area0) for m in multiples]
    loads_seen = [os.getloadavg()[0]]
    surface = cb.Surface(heights, lx=size, periodic=True)
    with tempfile.TemporaryDirectory(prefix="side_by_side_") as work_dir:
        heights_file = Path(work_dir) / "sphere.npy"
        np.save(heights_file, heights)
        cb_seconds, peer_seconds, cb_results, peer_loads = [], [], [], None
        for repetition in range(args.repetitions):
            loads_seen.append(os.getloadavg()[0])
            begin = time.perf_counter()
            cb_results = [cb.BemSolver(surface, modulus, hardness=hardness, threads=args.threads).solve(load)
                          for load in loads]
            cb_seconds.append(time.perf_counter() - begin)
            wall, out = run([sys.executable, ROOT / "scripts" / "peers" / "contactmechanics_sphere.py", "plastic",
                             heights_file, "--size", size, "--modulus", modulus, "--hardness", hardness,
                             "--loads=" + ",".join(f"{load:.17g}" for load in loads)], peer_env(args.peer))
            answer = json.loads(out)
            peer_loads = answer["loads"]
            peer_seconds.append(sum(a["seconds"] for a in peer_loads))
            print(f"rep {repetition}: cb {cb_seconds[-1]:.2f} s, peer {peer_seconds[-1]:.2f} s", file=sys.stderr)
    loads_seen.append(os.getloadavg()[0])
    command = (f"OMP_WAIT_POLICY=PASSIVE /usr/bin/python3 scripts/peers/side_by_side.py --peer PEER --part "
               f"plastic --repetitions {args.repetitions} --threads {args.threads}")
    lines = header("contactbench and ContactMechanics' PlasticSystem side by side: an elastic-perfectly plastic "
                   "sphere", command, args, peer_versions, loads_seen)
    lines += [
        f"Sphere (paraboloid) R = {radius:g} m on {n}^2 points over {size:g} m, periodic, E* = {modulus:.4g} Pa, "
        f"hardness H = {hardness:g} Pa (the pressure cap). Hertz's yield onset P_y = pi^3 R^2 H^3/(6 E*^2) = "
        f"{yield_force:.4g} N (contact radius pi R H/(2 E*) = {math.pi * radius * hardness / (2 * modulus):.3g} m, "
        f"{math.pi * radius * hardness / (2 * modulus) / (size / n):.1f} pixels). Loads are multiples of P_y.",
        "",
        "- contactbench: `BemSolver(surface, E*, hardness=H, threads=T).solve(load)` (default solver and "
        "tolerance), a new solver per load.",
        "- peer: `make_plastic_system(substrate=PeriodicFFTElasticHalfSpace, surface=PlasticTopography(topography, "
        "H))`, `minimize_proxy(external_force=F, forcetol=1e-5 x mean pixel force)` (constrained conjugate "
        "gradients with the hardness cap), a fresh system per load (scripts/peers/contactmechanics_sphere.py).",
        "",
        "Areas are node counts (contact: pressure > 0; plastic: pressure at H, to 1e-9 relative; the peer's "
        "own `plastic` flag marks every point of negative gap, elastic contact points inside its penetration "
        "tolerance included, and is in the CSV as peer_penetrating_fraction).",
        "",
        "| P/P_y | load P/(E* A0) | Hertz area fraction | cb contact | peer contact | difference | cb plastic | "
        "peer plastic | cb converged | peer converged |",
        "|---:|---:|---:|---:|---:|---:|---:|---:|---|---|",
    ]
    rows = []
    for m, load, cbr, peer in zip(multiples, loads, cb_results, peer_loads):
        force = load * modulus * area0
        hertz_radius = (3 * force * radius / (4 * modulus)) ** (1 / 3)
        hertz = math.pi * hertz_radius**2 / area0
        cb_plastic = cbr.plastic_points / n**2
        lines.append(f"| {m:g} | {load:.4g} | {hertz:.5f} | {cbr.area_fraction:.5f} | "
                     f"{peer['contact_fraction']:.5f} | {relative(cbr.area_fraction, peer['contact_fraction']):+.2e} "
                     f"| {cb_plastic:.5f} | {peer['plastic_fraction']:.5f} | {'yes' if cbr.converged else 'no'} | "
                     f"{'yes' if peer['converged'] else 'no'} |")
        rows.append({"P_over_Py": m, "load": load, "hertz_area_fraction": hertz,
                     "cb_area_fraction": cbr.area_fraction, "peer_area_fraction": peer["contact_fraction"],
                     "cb_plastic_fraction": cb_plastic, "peer_plastic_fraction": peer["plastic_fraction"],
                     "peer_penetrating_fraction": peer["penetrating_fraction"],
                     "cb_iterations": cbr.iterations, "peer_iterations": peer["iterations"],
                     "cb_converged": cbr.converged, "peer_converged": peer["converged"]})
    first_cb = next((r["P_over_Py"] for r in rows if r["cb_plastic_fraction"] > 0), None)
    first_peer = next((r["P_over_Py"] for r in rows if r["peer_plastic_fraction"] > 0), None)
    lines += [
        "",
        f"Yield onset (the first load of the ladder with plastic points): contactbench at P/P_y = {first_cb}, "
        f"peer at {first_peer} (on the grid the largest nodal pressure differs from Hertz's p0 by the "
        "discretisation, so the onset can move by a step of the ladder).",
        "",
        f"Time, all {len(loads)} loads: contactbench {median(cb_seconds):.2f} s (each "
        f"{spread(cb_seconds, '{:.2f}')}; solver construction included), peer {median(peer_seconds):.2f} s "
        f"(each {spread(peer_seconds, '{:.2f}')}; the solves only): ratio "
        f"**{median(peer_seconds) / median(cb_seconds):.1f}x**.",
    ]
    write_result("contactmechanics_plastic", command, lines, rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--peer", required=True, help="the folder the peer was built into (PYTHONPATH)")
    parser.add_argument("--part", choices=["nonadhesive", "adhesion", "adhesion_rough", "plastic", "all"],
                        default="all")
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--peer-repetitions", type=int, default=1,
                        help="nonadhesive: the peer's timed runs per load (each costs minutes at 1024^2)")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--grid", type=int, default=1024)
    parser.add_argument("--build", default="build/release")
    args = parser.parse_args()
    args.peer = Path(args.peer).resolve()
    os.environ["OMP_WAIT_POLICY"] = "PASSIVE"  # this process's own OpenMP (the Python BemSolver) too
    sys.path.insert(0, str(ROOT / args.build / "python"))
    import contactbench as cb

    peer_versions = peer_commits(args.peer)
    parts = ["nonadhesive", "adhesion", "adhesion_rough", "plastic"] if args.part == "all" else [args.part]
    for part in parts:
        {"nonadhesive": part_nonadhesive, "adhesion": part_adhesion, "adhesion_rough": part_adhesion_rough,
         "plastic": part_plastic}[part](args, cb, peer_versions)


if __name__ == "__main__":
    main()
