#!/usr/bin/env python3
"""DFG 2D-2 from a run's forces.csv: max c_D, max c_L and the Strouhal number against the benchmark.

Schaefer & Turek (1996), case 2D-2 (Re = 100, periodic): max c_D = 3.2299, max c_L = 1.0,
St = D f / U = 0.300, f the lift's frequency, U = 1 m/s the mean inflow, D = 0.1 m; within 3%.
c = 2 F / (rho U^2 D) = 20 F with F the cylinder's pressure + viscous load (forces.csv, the row
with obstacle = 1).

Prints, per 2 s window, the lift's mean, its frequency (the least-squares sinusoid of largest
amplitude, 0.025 Hz steps) and that sinusoid's amplitude, and the drag's mean: a periodic state
shows as windows with the same amplitude and frequency. Over the analysis window [T0, end]
(default the last 4 s) it refines the frequency (0.001 Hz steps), fits c_L and c_D with that
frequency and its harmonics 1-4 (least squares) and reports the maxima of the fits (the
particles' step-to-step noise, about 0.03-0.05 in c, filtered out) beside the raw maxima of the
samples, and the frequency from the lift's upward zero crossings as a check.

usage: analyse.py OUT_DIR [--from T0] [--plot PNG]   (--plot needs matplotlib)
"""
import csv
import math
import os
import sys

REF = {"max c_D": 3.2299, "max c_L": 1.0, "St": 0.300}
D, U = 0.1, 1.0  # m, m/s (mean of the parabolic inflow with U_m = 1.5)
HARMONICS = 4


def load(out):
    """t, c_D, c_L of the cylinder (obstacle = 1) from OUT_DIR/forces.csv."""
    t, cd, cl = [], [], []
    with open(os.path.join(out, "forces.csv")) as f:
        for r in csv.DictReader(f):
            if r["obstacle"] != "1":
                continue
            t.append(float(r["t"]))
            # c = 2 F / (rho U^2 D) with rho = 1, U = 1, D = 0.1
            cd.append(2.0 * (float(r["pressure_x"]) + float(r["viscous_x"])) / (U * U * D))
            cl.append(2.0 * (float(r["pressure_z"]) + float(r["viscous_z"])) / (U * U * D))
    return t, cd, cl


def solve(a, b):
    """Gaussian elimination with partial pivoting (small dense systems)."""
    n = len(b)
    m = [row[:] + [b[i]] for i, row in enumerate(a)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        for r in range(c + 1, n):
            k = m[r][c] / m[c][c]
            for j in range(c, n + 1):
                m[r][j] -= k * m[c][j]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        x[r] = (m[r][n] - sum(m[r][j] * x[j] for j in range(r + 1, n))) / m[r][r]
    return x


def fit(t, y, f, harmonics):
    """Least squares y ~ a0 + sum_k (a_k cos + b_k sin)(2 pi k f t); returns the coefficients."""
    n = 1 + 2 * harmonics
    ata = [[0.0] * n for _ in range(n)]
    aty = [0.0] * n
    for ti, yi in zip(t, y):
        row = [1.0]
        for k in range(1, harmonics + 1):
            w = 2.0 * math.pi * k * f * ti
            row += [math.cos(w), math.sin(w)]
        for i in range(n):
            aty[i] += row[i] * yi
            for j in range(n):
                ata[i][j] += row[i] * row[j]
    return solve(ata, aty)


def evaluate(c, f, ti):
    v = c[0]
    for k in range(1, (len(c) - 1) // 2 + 1):
        w = 2.0 * math.pi * k * f * ti
        v += c[2 * k - 1] * math.cos(w) + c[2 * k] * math.sin(w)
    return v


def best_frequency(t, y, lo, hi, step):
    """The frequency in [lo, hi] whose least-squares sinusoid has the largest amplitude."""
    best = (-1.0, lo)
    f = lo
    while f <= hi + 1e-12:
        c = fit(t, y, f, 1)
        best = max(best, (math.hypot(c[1], c[2]), f))
        f += step
    return best[1], best[0]


def up_crossing_frequency(t, y, mean, smooth=0.06):
    """Frequency from the upward crossings of mean by y averaged over +-smooth / 2 s."""
    s, j0, j1 = [], 0, 0
    for ti in t:
        while t[j0] < ti - smooth / 2:
            j0 += 1
        while j1 < len(t) and t[j1] <= ti + smooth / 2:
            j1 += 1
        s.append(sum(y[j0:j1]) / (j1 - j0))
    ups = []
    for i in range(1, len(t)):
        if s[i - 1] < mean <= s[i]:
            ups.append(t[i - 1] + (mean - s[i - 1]) / (s[i] - s[i - 1]) * (t[i] - t[i - 1]))
    if len(ups) < 2:
        return float("nan"), len(ups)
    return (len(ups) - 1) / (ups[-1] - ups[0]), len(ups)


def windows(t, cd, cl):
    print("window [s] | c_L mean | c_L frequency [Hz] (St) | c_L amplitude | c_D mean")
    a = 0.0
    while a + 2.0 <= t[-1] + 1e-9:
        idx = [i for i, x in enumerate(t) if a <= x < a + 2.0]
        if len(idx) > 50:
            tw, lw = [t[i] for i in idx], [cl[i] for i in idx]
            f, amp = best_frequency(tw, lw, 0.5, 10.0, 0.025)
            print(f"[{a:4.1f}, {a + 2:4.1f}) | {sum(lw) / len(lw):+.4f} | {f:.3f} ({D * f / U:.3f}) | "
                  f"{amp:.4f} | {sum(cd[i] for i in idx) / len(idx):.4f}")
        a += 2.0


def main():
    args = sys.argv[1:]
    if not args or args[0].startswith("-"):
        sys.exit(__doc__)
    out, t0, png = args[0], None, None
    if "--from" in args:
        t0 = float(args[args.index("--from") + 1])
    if "--plot" in args:
        png = args[args.index("--plot") + 1]
    t, cd, cl = load(out)
    if t0 is None:
        t0 = max(t[0], t[-1] - 4.0)
    print(f"{out}: {len(t)} force samples, t = {t[0]:.3f} .. {t[-1]:.3f} s")
    windows(t, cd, cl)
    idx = [i for i, x in enumerate(t) if x >= t0]
    tw, dw, lw = [t[i] for i in idx], [cd[i] for i in idx], [cl[i] for i in idx]
    f0, _ = best_frequency(tw, lw, 0.5, 10.0, 0.025)
    f, _ = best_frequency(tw, lw, f0 - 0.05, f0 + 0.05, 0.001)
    fl, fd = fit(tw, lw, f, HARMONICS), fit(tw, dw, f, HARMONICS)
    grid = [tw[0] + k / (1000.0 * f) for k in range(1000)]  # one period
    fit_l = [evaluate(fl, f, x) for x in grid]
    fit_d = [evaluate(fd, f, x) for x in grid]
    res = math.sqrt(sum((y - evaluate(fl, f, x)) ** 2 for x, y in zip(tw, lw)) / len(tw))
    fz, n_up = up_crossing_frequency(tw, lw, fl[0])
    print(f"analysis window [{t0:.3f}, {t[-1]:.3f}] s ({len(tw)} samples, {(t[-1] - t0) * f:.1f} periods)")
    print(f"  lift frequency {f:.3f} Hz (least squares), {fz:.3f} Hz ({n_up} upward zero crossings)")
    print(f"  c_L: mean {fl[0]:+.4f}, fit {min(fit_l):+.4f} .. {max(fit_l):+.4f}, samples "
          f"{min(lw):+.4f} .. {max(lw):+.4f}, rms of samples about the fit {res:.4f}")
    print(f"  c_D: mean {fd[0]:.4f}, fit {min(fit_d):.4f} .. {max(fit_d):.4f}, samples "
          f"{min(dw):.4f} .. {max(dw):.4f}")
    got = {"max c_D": max(fit_d), "max c_L": max(fit_l), "St": D * f / U}
    raw = {"max c_D": max(dw), "max c_L": max(lw), "St": D * fz / U}
    print("quantity | reference | this run (fit) | error | within 3% | samples' max / crossings")
    for k, ref in REF.items():
        e = got[k] / ref - 1.0
        print(f"{k} | {ref:.4f} | {got[k]:.4f} | {100 * e:+.2f}% | {'yes' if abs(e) <= 0.03 else 'NO'}"
              f" | {raw[k]:.4f}")
    if png:
        plot(png, t, cd, cl, tw, grid, fit_d, fit_l, f)


def plot(png, t, cd, cl, tw, grid, fit_d, fit_l, f):
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("--plot needs matplotlib (Debian's python3-matplotlib: /usr/bin/python3)")
    fig, ax = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    ax[0].plot(t, cd, lw=0.4, color="tab:blue", label="c_D (samples)")
    ax[0].axhline(REF["max c_D"], color="k", ls="--", lw=0.8, label="reference max 3.2299")
    ax[1].plot(t, cl, lw=0.4, color="tab:red", label="c_L (samples)")
    for s in (1.0, -1.0):
        ax[1].axhline(s * REF["max c_L"], color="k", ls="--", lw=0.8)
    periods = int((tw[-1] - tw[0]) * f)
    ts = [tw[0] + p / f + (x - grid[0]) for p in range(periods) for x in grid]
    ax[0].plot(ts, fit_d * periods, color="navy", lw=0.8, label="fit over the analysis window")
    ax[1].plot(ts, fit_l * periods, color="darkred", lw=0.8, label="fit; reference +-1.0 dashed")
    late = sorted(y for x, y in zip(t, cd) if x >= 1.0)  # the impulsive start off the scale
    if late:
        ax[0].set_ylim(late[len(late) // 1000] - 0.1, late[-1 - len(late) // 1000] + 0.1)
    ax[0].set_ylabel("c_D (start off scale)")
    ax[1].set_ylabel("c_L")
    ax[1].set_xlabel("t [s]")
    for a in ax:
        a.legend(loc="lower left", fontsize=8)
    fig.suptitle("DFG 2D-2 (Re = 100): drag and lift on the cylinder")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
