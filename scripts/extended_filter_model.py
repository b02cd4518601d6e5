#!/usr/bin/python3
"""A numpy model of active_set's inner conjugate gradient on a fixed contact set, with and without the
extended filter (bem/solvers/active_set_inner_cg.cpp; docs/solvers_log.md "The extended filter").

Reads a pressure field written by `contactbench bem FILE --periodic --fields PREFIX` (PREFIX_load1_pressure.txt,
the project's surface format), takes its contact set A = {p > 0}, and solves G_AA x = b on the zero-mean
vectors of A (G the periodic half-space operator, symbol 1/|q| in lattice units; the constant 2/E* does not
change iterations) from a seeded random right-hand side, preconditioned by

    z = P E^T F E r,   F the filter |q|, P the mean removal on A,

E the extension of r off A: E r = r on A and, off A, the sum of r over the set nodes of the
(2 radius + 1)^2 window times 1 / max(the window's count of set nodes, floor x window size). Radius 0 is the
plain filter (r zero off A). For each radius it prints the CG iterations to reduce the residual 1e6-fold and the
extreme eigenvalues of the preconditioned operator estimated from the CG's Lanczos coefficients.

Usage: scripts/extended_filter_model.py PRESSURE_FILE [--radius 0,4,8,12] [--floor 0.25]
"""
import argparse

import numpy as np


def read_field(path):
    return np.loadtxt(path, comments="#")


def window_sum(x, radius):
    """Periodic sum over the (2 radius + 1)^2 window at every point."""
    for axis in (0, 1):
        total = x.copy()
        for s in range(1, radius + 1):
            total += np.roll(x, s, axis) + np.roll(x, -s, axis)
        x = total
    return x


def model(pressure, radius, floor, reduction=1e-6, seed=1):
    n_y, n_x = pressure.shape
    on = pressure > 0
    qx = np.fft.fftfreq(n_x) * n_x
    qy = np.fft.fftfreq(n_y) * n_y
    q = np.sqrt(qx[None, :] ** 2 + qy[:, None] ** 2)
    g = np.zeros_like(q)
    g[q > 0] = 1 / q[q > 0]

    def convolve(x, symbol):
        return np.real(np.fft.ifft2(np.fft.fft2(x) * symbol))

    def on_set_zero_mean(x):
        x = np.where(on, x, 0.0)
        return np.where(on, x - x[on].mean(), 0.0)

    if radius > 0:
        weight = np.where(on, 0.0, 1 / np.maximum(window_sum(on.astype(float), radius), floor * (2 * radius + 1) ** 2))

        def precondition(r):
            extended = np.where(on, r, weight * window_sum(np.where(on, r, 0.0), radius))
            y = convolve(extended, q)
            return on_set_zero_mean(y + window_sum(np.where(on, 0.0, weight * y), radius))
    else:

        def precondition(r):
            return on_set_zero_mean(convolve(np.where(on, r, 0.0), q))

    rng = np.random.default_rng(seed)
    r = on_set_zero_mean(rng.standard_normal(pressure.shape))
    z = precondition(r)
    t = z.copy()
    rz = (r * z).sum()
    r0 = np.sqrt((r * r).sum())
    alphas, betas, iterations = [], [], None
    for k in range(400):
        gt = on_set_zero_mean(convolve(t, g))
        alpha = rz / (t * gt).sum()
        r -= alpha * gt
        alphas.append(alpha)
        norm = np.sqrt((r * r).sum())
        if iterations is None and norm <= reduction * r0:
            iterations = k + 1
        if norm <= 1e-11 * r0:  # Lanczos coefficients beyond round-off would be noise
            break
        z = precondition(r)
        rz_new = (r * z).sum()
        betas.append(rz_new / rz)
        rz = rz_new
        t = z + betas[-1] * t
    # The CG's Lanczos tridiagonal matrix: its eigenvalues estimate the preconditioned operator's.
    size = len(alphas)
    tri = np.zeros((size, size))
    for k in range(size):
        tri[k, k] = 1 / alphas[k] + (betas[k - 1] / alphas[k - 1] if k else 0)
        if k + 1 < size:
            tri[k, k + 1] = tri[k + 1, k] = np.sqrt(betas[k]) / alphas[k]
    eigenvalues = np.linalg.eigvalsh(tri)
    return on.mean(), iterations, eigenvalues[0], eigenvalues[-1]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("pressure", help="PREFIX_loadK_pressure.txt from contactbench bem --periodic --fields")
    parser.add_argument("--radius", default="0,4,8,12", help="window radii, comma-separated (0: the plain filter)")
    parser.add_argument("--floor", type=float, default=0.25, help="the weight's floor, a fraction of the window")
    args = parser.parse_args()
    pressure = read_field(args.pressure)
    print(f"{args.pressure}: {pressure.shape[1]} x {pressure.shape[0]}")
    print("radius | contact | CG iterations to 1e-6 | smallest eigenvalue | largest | ratio")
    for radius in (int(v) for v in args.radius.split(",")):
        fraction, iterations, low, high = model(pressure, radius, args.floor)
        print(f"{radius} | {fraction:.3f} | {iterations} | {low:.3f} | {high:.2f} | {high / low:.1f}")


if __name__ == "__main__":
    main()
