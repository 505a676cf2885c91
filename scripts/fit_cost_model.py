#!/usr/bin/env python3
"""Fits methods/cost_model.h's coefficients from the cost-model run recorded in docs/benchmarks.md.

t_ms = fixed + a * Mpixels + b * Medges per method, least squares on the relative error
(each equation divided by its measured time), coefficients kept >= 0 (a negative one is
dropped and the rest refitted). Input: the end points of docs/benchmarks.md's "Cost model" table, star at
128^2 and 4096^2 (180 and 576 edges), rings at 1024^2 (5,092 and 123,052 edges). Prints one
C++ initialiser per method and the predicted / measured ratios.
"""

TIMES_MS = {  # method: (star 128^2, star 4096^2, rings 5.1k edges, rings 123k edges)
    "none": (0.044, 5.77, 0.511, 8.12),
    "exact": (0.135, 8.69, 1.22, 31.3),
    "box-multiscan": (0.145, 18.3, 1.42, 13),
    "gauss-multiscan": (0.34, 76.1, 5.54, 32.6),
    "ssaa": (0.599, 466, 18.4, 35.2),
    "nishita-d": (0.39, 287, 12.5, 23.6),
    "fast-edge": (0.165, 260, 2.8, 17.2),
    "cairo": (0.189, 50.1, 4.25, 127),
    "agg": (0.189, 42.5, 2.59, 52.7),
    "exact-8bit": (0.161, 29.1, 2.85, 33.2),
    # Measured later, in one run of `--benchmark_filter` on agg, freetype and stb-truetype
    # (docs/benchmarks.md, "Cost model"), and scaled point by point by agg's time in the table
    # run over agg's in that one: agg (0.357, 67.5, 4.42, 83.4) ms there.
    "freetype": (0.502, 169.1, 3.72, 190.0),
    "stb-truetype": (0.0630, 45.0, 1.98, 17.7),
}
POINTS = [(128**2, 180), (4096**2, 576), (1024**2, 5092), (1024**2, 123052)]


def features(pixels, edges):
    return [1.0, pixels / 1e6, edges / 1e6]


def least_squares(rows, rhs):
    n = len(rows[0])
    m = [[sum(r[i] * r[j] for r in rows) for j in range(n)] +
         [sum(r[i] * b for r, b in zip(rows, rhs))] for i in range(n)]
    for i in range(n):
        pivot = m[i][i]
        m[i] = [v / pivot for v in m[i]]
        for r in range(n):
            if r != i:
                f = m[r][i]
                m[r] = [a - f * b for a, b in zip(m[r], m[i])]
    return [m[i][n] for i in range(n)]


for method, times in TIMES_MS.items():
    columns = [0, 1, 2]
    while True:
        rows = [[features(p, e)[c] / t for c in columns] for t, (p, e) in zip(times, POINTS)]
        x = least_squares(rows, [1.0] * len(times))
        if min(x) >= 0:
            break
        columns.pop(x.index(min(x)))
    coef = [0.0, 0.0, 0.0]
    for c, v in zip(columns, x):
        coef[c] = v
    ratios = [sum(a * f for a, f in zip(coef, features(p, e))) / t
              for t, (p, e) in zip(times, POINTS)]
    print(f"{method:16s} {{{coef[0]:.4g}, {coef[1]:.4g}, {coef[2]:.4g}}}  ratios "
          + " ".join(f"{r:.2f}" for r in ratios))
