#!/usr/bin/env python3
"""Renders a pattern with three methods, scores each against the exact answer and times it,
scores an array of your own (here a hand-made one: 4x4 supersampling done in NumPy), and plots
error against time with matplotlib when it is installed (docs/python.md).

    PYTHONPATH=build/python /usr/bin/python3 python/examples/compare_methods.py [--out plot.png]
"""

import argparse
import statistics
import time

import numpy as np

import aabench

METHODS = ["none", "box-multiscan:n=3", "exact"]
# Timed runs per method: the median is what is shown (single-threaded, as compare times).
RUNS = 5


def timed_render(scene, method):
    """The image and the median wall time of RUNS renders, in ms."""
    times = []
    for _ in range(RUNS):
        start = time.perf_counter()
        image = aabench.render(scene, method)
        times.append((time.perf_counter() - start) * 1e3)
    return image, statistics.median(times)


def my_renderer(pattern, width, height, k=4):
    """Your own renderer's output, as a NumPy array: here the pattern rendered k times finer
    by point sampling and averaged over k x k blocks (a box-filtered supersampling). The star
    is laid out relative to the image size, so the finer scene is the same picture (a pattern
    with sizes in pixels, such as strips, is not: score your own renderer's image instead)."""
    fine = aabench.Scene.pattern(pattern, size=(width * k, height * k))
    samples = aabench.render(fine, "none")
    return samples.reshape(height, k, width, k).mean(axis=(1, 3))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pattern", default="star", help="pattern spec (aabench.patterns())")
    parser.add_argument("--size", type=int, default=256, help="image side in pixels")
    parser.add_argument("--out", default="compare_methods.png", help="the plot (PNG)")
    args = parser.parse_args()

    scene = aabench.Scene.pattern(args.pattern, size=(args.size, args.size))
    print(scene)
    points = []
    for method in METHODS:
        image, ms = timed_render(scene, method)
        figures = aabench.score(test=image, scene=scene)
        points.append((method, ms, figures["box_rmse"]))
        print(f"  {method:<20} box_rmse {figures['box_rmse']:.5f}  dropout "
              f"{100 * figures['dropout']:.2f}%  {ms:8.3f} ms")

    start = time.perf_counter()
    mine = my_renderer(args.pattern, scene.width, scene.height)  # float64, linear light
    ms = (time.perf_counter() - start) * 1e3
    figures = aabench.score(test=mine, scene=scene)
    points.append(("mine (4x4 in NumPy)", ms, figures["box_rmse"]))
    print(f"  {'mine (4x4 in NumPy)':<20} box_rmse {figures['box_rmse']:.5f}  dropout "
          f"{100 * figures['dropout']:.2f}%  {ms:8.3f} ms")
    # An 8-bit image must say how its codes encode light: here sRGB, as displays expect.
    codes = np.round(255 * np.where(mine <= 0.0031308, 12.92 * mine,
                                    1.055 * mine ** (1 / 2.4) - 0.055)).astype(np.uint8)
    srgb = aabench.score(test=codes, scene=scene, encoding="srgb")
    print(f"  the same as 8-bit sRGB codes: box_rmse {srgb['box_rmse']:.5f}")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not installed: no plot (Debian: python3-matplotlib)")
        return
    fig, ax = plt.subplots(figsize=(6, 4))
    for name, ms, rmse in points:
        ax.plot(ms, rmse, "o")
        ax.annotate(name, (ms, rmse), textcoords="offset points", xytext=(5, 5))
    ax.set_xscale("log")
    # exact's error is 0: linear near zero, logarithmic above.
    ax.set_yscale("symlog", linthresh=1e-4)
    ax.set_ylim(bottom=0.0)
    ax.margins(x=0.4)
    ax.set_xlabel("time (ms, median)")
    ax.set_ylabel("box RMSE")
    ax.set_title(f"{args.pattern} at {args.size}x{args.size}")
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print(f"plot: {args.out}")


if __name__ == "__main__":
    main()
