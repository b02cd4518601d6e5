"""What every step of the tutorial shares: its command line (--out for the plots, by default a new temporary
folder, so that an example never writes into the clone; --threads) and matplotlib when it is installed."""
import argparse
import pathlib
import tempfile


def arguments(description):
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--out", type=pathlib.Path,
                        help="folder for the plots (default: a new temporary folder, printed at the end)")
    parser.add_argument("--threads", type=int, default=2, help="threads for the FFTs (default 2)")
    args = parser.parse_args()
    if args.out is None:
        args.out = pathlib.Path(tempfile.mkdtemp(prefix="contactbench-tutorial-"))
    args.out.mkdir(parents=True, exist_ok=True)
    return args


def pyplot():
    """matplotlib.pyplot drawing to files (no display needed), or None when matplotlib is not installed."""
    try:
        import matplotlib
    except ImportError:
        print("matplotlib is not installed (pip install matplotlib, or Debian's python3-matplotlib): no plot")
        return None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt
