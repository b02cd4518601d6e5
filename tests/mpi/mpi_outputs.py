"""Reading the CSV outputs a serial and a distributed run write, for the MPI command-line tests
(test_mpi_cli.py, test_mpi_scenes.py), which compare them."""
import csv


def rows(path):
    """The data rows of a contactbench CSV, its '#' stamp and comment lines skipped."""
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def relative(a, b):
    """|a - b| / |b| of two CSV cells (0 when they are the same text)."""
    a, b = float(a), float(b)
    return abs(a - b) / max(abs(b), 1e-300) if a != b else 0.0


def csv_differences(distributed_path, serial_path, bound, skip=("solve_seconds", "seconds", "residual")):
    """What differs between two CSVs of the same table: each cell equal as text, or both numbers within
    `bound` relative (the round-off of sums taken in another order); the columns in `skip` aside: timings, and
    the BEM's complementarity residual (the largest gap left on the contact set, itself of the order of the
    round-off, 1e-11 of the height range, so its relative difference is not small; its convergence test is
    the `converged` column, compared)."""
    distributed, serial = rows(distributed_path), rows(serial_path)
    if len(distributed) != len(serial) or (serial and list(distributed[0]) != list(serial[0])):
        return [f"{distributed_path}: {len(distributed)} rows against {len(serial)}, or other columns"]
    found = []
    for number, (d, s) in enumerate(zip(distributed, serial)):
        for key in s:
            if key in skip or d[key] == s[key]:
                continue
            try:
                apart = relative(d[key], s[key])
            except ValueError:
                apart = float("inf")
            if not apart <= bound:
                found.append(f"{distributed_path}: row {number + 1} {key} {d[key]} against {s[key]}")
    return found
