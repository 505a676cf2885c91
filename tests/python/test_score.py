"""score() gives the figures `aabench score --json` prints, under its keys; a hand-built array
scores as computed by hand."""

import math

import numpy as np

import aabench
from conftest import (figures_from_cli_json, run_cli, run_cli_all, same_value, write_grey_png,
                      write_pfm)

SIDE = 64
SIZE = f"{SIDE}x{SIDE}"
# The hand-computed figures are sums of a few hundred terms in double, in another order than
# the harness's (NumPy's pairwise sum): a few ulps apart at most, far below this.
HAND_FIGURE_RELATIVE = 1e-12


# The figures that are times of this run (the world stages of a 3-D scene, measured as they
# ran): no two runs share them, so they are compared as present and positive only.
RUN_TIMES = {"world_ms"}


def assert_same_figures(got, expected, what):
    assert list(got) == list(expected), f"{what}: keys differ"
    for key, value in expected.items():
        if key in RUN_TIMES and not math.isnan(value):
            assert got[key] > 0, f"{what}: {key}"
            continue
        assert same_value(got[key], value), f"{what}: {key}: {got[key]!r} != {value!r}"


def test_score_is_the_clis_score_json(tmp_path):
    # (pattern, method, filter): 2-D and 3-D scenes, the box and an own filter.
    cases = [("star", "none", None), ("curves", "box-multiscan:n=3", None),
             ("rings", "gauss-multiscan:n=3", "gaussian:sigma=0.5"), ("room", "none", None)]
    paths, runs = [], []
    for k, (pattern, method, filter_spec) in enumerate(cases):
        image = aabench.render(aabench.Scene.pattern(pattern, size=(SIDE, SIDE)), method)
        paths.append(tmp_path / f"{k}.pfm")
        write_pfm(paths[-1], image)
        runs.append(("score", paths[-1], "--pattern", pattern, "--size", SIZE, "--json") +
                    (("--filter", filter_spec) if filter_spec else ()))
    for (pattern, method, filter_spec), path, done in zip(cases, paths, run_cli_all(runs)):
        scene = aabench.Scene.pattern(pattern, size=(SIDE, SIDE))
        got = aabench.score(test=aabench.render(scene, method), scene=scene, filter=filter_spec)
        assert "box_rmse" in got and "dropout" in got and "flip" in got
        assert_same_figures(got, figures_from_cli_json(done.stdout), f"{pattern} {method}")


def test_a_scene_file_is_named_as_the_cli_names_it(tmp_path):
    scene_path = tmp_path / "my_scene.json"
    run_cli("export", "--pattern", "grating", "--size", "32x24", "--out", scene_path)
    scene = aabench.Scene.from_file(scene_path)
    image = aabench.render(scene, "none")
    write_pfm(tmp_path / "g.pfm", image)
    done = run_cli("score", tmp_path / "g.pfm", "--scene", scene_path, "--json")
    got = aabench.score(image, scene)
    assert got["pattern"] == "my_scene" and got["scene_file"] == str(scene_path)
    assert_same_figures(got, figures_from_cli_json(done.stdout), "scene file")


def test_integer_codes_are_decoded_as_the_cli_decodes_a_png(tmp_path):
    scene = aabench.Scene.pattern("star", size=(SIDE, SIDE))
    # Codes of a render (clipped: a render's rounding may stray a hair outside [0, 1]).
    light = np.clip(aabench.render(scene, "box-multiscan:n=3").astype(np.float64), 0.0, 1.0)
    srgb = np.where(light <= 0.0031308, 12.92 * light, 1.055 * light ** (1 / 2.4) - 0.055)
    cases = [(np.round(srgb * 255).astype(np.uint8), "srgb"),
             (np.round(light * 255).astype(np.uint8), "linear"),
             (np.round(srgb * 65535).astype(np.uint16), "srgb"),
             (np.round(light * 65535).astype(np.uint16), "linear")]
    runs = []
    for k, (codes, encoding) in enumerate(cases):
        write_grey_png(tmp_path / f"{k}.png", codes)
        runs.append(("score", tmp_path / f"{k}.png", "--pattern", "star", "--size", SIZE,
                     "--json", f"--{encoding}"))
    for (codes, encoding), done in zip(cases, run_cli_all(runs)):
        got = aabench.score(codes, scene, encoding=encoding)
        assert_same_figures(got, figures_from_cli_json(done.stdout), f"{codes.dtype} {encoding}")


def test_a_hand_built_array_scores_as_computed_by_hand():
    # A 16 x 8 image whose white rectangle ends halfway across column 10: the exact coverage is
    # 1 in columns 0..9, 0.5 in column 10, 0 beyond. The test paints column 10 fully white.
    width, height, edge_x = 16, 8, 10.5
    scene = aabench.Scene.from_json({
        "version": 1, "width": width, "height": height, "background": 0.0,
        "shapes": [{"type": "polygon", "value": 1.0,
                    "contours": [[[0, 0], [edge_x, 0], [edge_x, height], [0, height]]]}]})
    exact = np.zeros((height, width))
    exact[:, :10] = 1.0
    exact[:, 10] = 0.5
    test = np.zeros((height, width), dtype=np.float32)
    test[:, :11] = 1.0
    error = test - exact
    got = aabench.score(test=test, scene=scene)
    assert math.isclose(got["box_rmse"], math.sqrt(np.mean(error ** 2)),
                        rel_tol=HAND_FIGURE_RELATIVE)
    assert math.isclose(got["box_rmse"], 0.125, rel_tol=HAND_FIGURE_RELATIVE)  # sqrt(8/4/128)
    assert math.isclose(got["box_max_abs"], 0.5, rel_tol=HAND_FIGURE_RELATIVE)
    assert math.isclose(got["box_bias"], np.mean(error), rel_tol=HAND_FIGURE_RELATIVE)
    assert got["dropout"] == 0.0
    # The same array as float64 and as linear 8-bit codes is the same image.
    assert_same_figures(aabench.score(test.astype(np.float64), scene), got, "float64")
    codes = (test * 255).astype(np.uint8)
    assert math.isclose(aabench.score(codes, scene, encoding="linear")["box_rmse"], 0.125,
                        rel_tol=HAND_FIGURE_RELATIVE)
    # A strided view (every other column of a wider array) is read by its strides.
    wide = np.zeros((height, 2 * width), dtype=np.float32)
    wide[:, ::2] = test
    assert aabench.score(wide[:, ::2], scene)["box_rmse"] == got["box_rmse"]


def test_figures_that_do_not_apply_are_nan():
    scene = aabench.Scene.pattern("star", size=(32, 32))
    got = aabench.score(aabench.render(scene, "none"), scene)
    # seams are figures of 3-D scenes: NaN (results.json's null) on a 2-D one.
    assert math.isnan(got["seams_max"])
