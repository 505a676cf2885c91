"""render() and reference() give the images the CLI writes, bit for bit; the arrays are rows x
columns and own their pixels."""

import gc
import threading
import time

import numpy as np
import pytest

import aabench
from conftest import bits, read_pfm, run_cli_all

SIDE = 64
SIZE = f"{SIDE}x{SIDE}"
# Two methods of different engines: point sampling and the sub-scanline engine.
METHODS = ["none", "box-multiscan:n=3"]
# 3-D patterns through the world pipeline: hidden surfaces (room), and an edges block whose
# image is the composite the CLI's --out gets (terrain-edges).
WORLD_PATTERNS = ["room", "terrain-edges"]
# A thread waiting for the GIL through a whole render pauses for all of it; one that runs
# beside the render pauses only when the OS schedules it out (2 cores, shared): far below half.
GIL_PAUSE_SHARE = 0.5


@pytest.fixture(scope="session")
def cli_renders(tmp_path_factory, two_d_patterns):
    """(pattern, method) -> the CLI's render read back from its PFM."""
    out = tmp_path_factory.mktemp("renders")
    jobs = [(p, m) for p in two_d_patterns + WORLD_PATTERNS for m in METHODS]
    paths = [out / f"{k}.pfm" for k in range(len(jobs))]
    run_cli_all([("render", "--pattern", p, "--size", SIZE, "--method", m, "--out", path)
                 for (p, m), path in zip(jobs, paths)])
    return {job: read_pfm(path) for job, path in zip(jobs, paths)}


def test_render_is_the_clis_image_bit_for_bit(cli_renders):
    assert len(cli_renders) >= 2 * 12, "fewer patterns than the registry's 2-D ones?"
    for (pattern, method), expected in cli_renders.items():
        got = aabench.render(aabench.Scene.pattern(pattern, size=(SIDE, SIDE)), method)
        assert got.dtype == np.float32 and got.shape == (SIDE, SIDE)
        assert np.array_equal(bits(got), bits(expected)), f"{pattern} with {method}"


def test_reference_is_the_clis_bit_for_bit(tmp_path):
    # One scene per reference engine (polygons, exact circles, Bezier curves, glyphs, a world's
    # visible pieces) and the two radial filters: each CLI run costs its start-up.
    cases = [(p, "box") for p in ["star", "circles", "curves", "text", "room"]]
    cases += [("star", "gaussian:sigma=0.5"), ("circles", "cone:radius=1.5")]
    paths = [tmp_path / f"{k}.pfm" for k in range(len(cases))]
    run_cli_all([("reference", "--pattern", p, "--size", SIZE, "--filter", f, "--out", path)
                 for (p, f), path in zip(cases, paths)])
    for (pattern, filter_spec), path in zip(cases, paths):
        got = aabench.reference(aabench.Scene.pattern(pattern, size=(SIDE, SIDE)), filter_spec)
        assert np.array_equal(bits(got), bits(read_pfm(path))), f"{pattern} {filter_spec}"


def test_arrays_are_rows_by_columns():
    scene = aabench.Scene.pattern("star", size=(77, 53))
    assert (scene.width, scene.height) == (77, 53)
    assert aabench.render(scene, "none").shape == (53, 77)
    assert aabench.reference(scene).shape == (53, 77)


def test_threads_give_the_same_image():
    for pattern in ["star", "text", "room"]:
        scene = aabench.Scene.pattern(pattern, size=(SIDE, 48))
        one = aabench.render(scene, "box-multiscan:n=3", threads=1)
        two = aabench.render(scene, "box-multiscan:n=3", threads=2)
        assert np.array_equal(bits(one), bits(two)), pattern


def test_the_array_owns_the_render_buffer():
    image = aabench.render(aabench.Scene.pattern("star", size=(SIDE, SIDE)), "exact")
    # Not a copy: the array is a view on the render's buffer, kept alive by its base capsule.
    assert not image.flags.owndata
    assert type(image.base).__name__ == "PyCapsule"
    assert image.flags.c_contiguous and image.flags.writeable
    expected = image.copy()
    gc.collect()
    assert np.array_equal(bits(image), bits(expected))
    image[0, 0] = 0.25  # the buffer is the caller's to use
    assert image[0, 0] == np.float32(0.25)


def test_render_releases_the_gil():
    # A render of a few hundred ms in another thread while this one counts: with the GIL
    # released, this thread runs all along (its longest pause is the OS's scheduling, a few
    # ms); held, it would stand still for the whole render.
    scene = aabench.Scene.pattern("zoneplate", size=(1024, 1024))  # ~0.3 s of ssaa:k=16
    finished = threading.Event()
    worker = threading.Thread(target=lambda: (aabench.render(scene, "ssaa:k=16"), finished.set()))
    last = start = time.perf_counter()
    longest_pause = 0.0
    worker.start()
    while not finished.is_set():
        now = time.perf_counter()
        longest_pause, last = max(longest_pause, now - last), now
    worker.join()
    render_s = time.perf_counter() - start
    assert longest_pause < render_s * GIL_PAUSE_SHARE, (longest_pause, render_s)
