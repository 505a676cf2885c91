"""Bad input raises ValueError with the CLI's one-line message (or, for what only the module
takes, a message that names what was expected), and nothing is printed."""

import numpy as np
import pytest

import aabench
from conftest import cli_error, cli_errors

SIZE = (32, 24)


@pytest.fixture
def star():
    return aabench.Scene.pattern("star", size=SIZE)


def raises_with(message, call, *args, **kwargs):
    with pytest.raises(ValueError) as caught:
        call(*args, **kwargs)
    assert str(caught.value) == message
    return caught.value


def test_scene_errors_are_the_clis(tmp_path, capfd):
    missing = tmp_path / "missing.json"
    raises_with(cli_error("render", "--scene", missing, "--method", "none", "--out",
                          tmp_path / "x.pfm"), aabench.Scene.from_file, missing)
    bad = tmp_path / "bad.json"
    bad.write_text('{"version": 1, "width": 8, "height": 8, "shapes": [{"type": "polygon", '
                   '"contours": [[[0, 0], [1, 0]]]}]}')
    message = cli_error("render", "--scene", bad, "--method", "none", "--out", tmp_path / "x.pfm")
    raises_with(message, aabench.Scene.from_file, bad)
    # The same reader on the text: the same message, with the text's source name.
    raises_with(message.replace(str(bad), "<json>"), aabench.Scene.from_json, bad.read_text())
    syntax = tmp_path / "syntax.json"
    syntax.write_text('{"version": 1,')
    message = cli_error("render", "--scene", syntax, "--method", "none", "--out",
                        tmp_path / "x.pfm")
    raises_with(message.replace(str(syntax), "<json>"), aabench.Scene.from_json, '{"version": 1,')
    assert capfd.readouterr() == ("", "")


def test_spec_errors_are_the_clis(tmp_path, star, capfd):
    out = tmp_path / "x.pfm"
    render = ("render", "--size", "32x24", "--out", out)
    # A scene whose edge stage needs a depth image, and a method that draws none.
    flat = next(m["spec"] for m in aabench.methods()
                if not m["traits"]["affine_values"] and not m["traits"]["temporal"])
    edges = aabench.Scene.pattern("terrain-edges", size=SIZE)
    test = aabench.render(star, "none")
    # (the CLI's arguments, then the module's call that must raise its message)
    cases = []
    for spec in ["stra", "star:spokes=1", "star:nope=3", "star:spokes=abc"]:
        cases.append((render + ("--pattern", spec, "--method", "none"),
                      lambda spec=spec: aabench.Scene.pattern(spec, size=SIZE)))
    for method in ["nonee", "ssaa:k=0", "ssaa:x=1", "aa-circle"]:
        cases.append((render + ("--pattern", "star", "--method", method),
                      lambda method=method: aabench.render(star, method)))
    cases.append((render + ("--pattern", "terrain-edges", "--method", flat),
                  lambda: aabench.render(edges, flat)))
    for filter_spec in ["gauss", "gaussian:sigma=-1"]:
        # score checks its filter as reference does (harness/measure/score.cpp).
        reference = ("reference", "--pattern", "star", "--size", "32x24", "--filter",
                     filter_spec, "--out", out)
        cases.append((reference, lambda f=filter_spec: aabench.reference(star, f)))
        cases.append((reference, lambda f=filter_spec: aabench.score(test, star, filter=f)))
    for (args, call), message in zip(cases, cli_errors([args for args, _ in cases])):
        raises_with(message, call)
    assert capfd.readouterr() == ("", "")


def test_size_and_thread_errors_name_the_range(star):
    for size in [(0, 24), (32, 10**6)]:
        with pytest.raises(ValueError, match=r"^size: .* is out of range 1\.\.\d+ per side$"):
            aabench.Scene.pattern("star", size=size)
    with pytest.raises(ValueError, match=r"^size: expected \(width, height\), two integers$"):
        aabench.Scene.pattern("star", size=(32,))
    for threads in [0, 257]:
        with pytest.raises(ValueError, match=rf"^threads: {threads} is out of range 1\.\.256$"):
            aabench.render(star, "none", threads=threads)


def test_score_refuses_what_it_cannot_read_as_light(star, capfd):
    image = aabench.render(star, "none")
    shape = r"shape \(24, 32\) \(rows x columns of the 32x24 scene\)"
    with pytest.raises(ValueError, match=rf"^test: shape \(32, 24\); expected {shape}$"):
        aabench.score(image.T.copy(), star)
    with pytest.raises(ValueError, match=rf"^test: a 3-D array; expected a 2-D array of "
                                         rf"{shape}$"):
        aabench.score(image[:, :, None], star)
    with pytest.raises(ValueError, match=rf"^test: a 1-D array; "):
        aabench.score(image.ravel(), star)
    codes = (image * 255).astype(np.uint8)
    for dtype in [np.uint8, np.uint16]:
        with pytest.raises(ValueError, match=rf"^test: {np.dtype(dtype).name} codes need "
                                             r"encoding='srgb' or encoding='linear': .*no "
                                             r"decoding is guessed$"):
            aabench.score(codes.astype(dtype), star)
    for dtype in [np.int32, np.bool_, np.float16, np.complex64]:
        with pytest.raises(ValueError, match=rf"^test: dtype {np.dtype(dtype).name}; expected "
                                             r"float32 or float64 \(linear light\), or uint8 or "
                                             r"uint16 codes"):
            aabench.score(image.astype(dtype), star, encoding="linear")
    with pytest.raises(ValueError, match=r"^encoding: 'gamma' is not one of srgb, linear"):
        aabench.score(codes, star, encoding="gamma")
    with pytest.raises(ValueError, match=r"^encoding: 'srgb' on float32 data, linear by "
                                         r"definition"):
        aabench.score(image, star, encoding="srgb")
    assert capfd.readouterr() == ("", "")
