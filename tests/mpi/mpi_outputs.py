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
