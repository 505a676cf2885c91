"""Shared by the tests of the Python module (tests/python/): the CLI beside it, and the file
formats the tests read and write by hand (PFM as aabench writes it, PNG as a foreign renderer
writes it), so that nothing here goes through the module's own code."""

import json
import math
import os
import pathlib
import struct
import subprocess
import zlib
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import aabench

REPO = pathlib.Path(__file__).resolve().parents[2]
# ctest sets AABENCH_BINARY to the CLI built with the module; by hand, the default build's.
CLI = os.environ.get("AABENCH_BINARY", str(REPO / "build" / "aabench"))
# The CLI runs are processes of their own (each start costs a few tenths of a second): two
# at a time, the machine's cores.
CLI_JOBS = 2


def run_cli(*args, check=True):
    """Runs `aabench ARGS...`; returns the CompletedProcess (text)."""
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"aabench {' '.join(map(str, args))}: {done.stderr}")
    return done


def run_cli_all(arg_lists):
    """Runs every argument list, CLI_JOBS at a time; returns the CompletedProcesses in order."""
    with ThreadPoolExecutor(CLI_JOBS) as pool:
        return list(pool.map(lambda args: run_cli(*args), arg_lists))


def refusal(args, done):
    """The one-line message of a refused CLI run, without its "aabench: " prefix."""
    assert done.returncode == 2, f"aabench {args} did not refuse its input: {done.stderr}"
    line = done.stderr.strip()
    assert "\n" not in line, f"more than one line: {line!r}"
    assert line.startswith("aabench: "), line
    return line[len("aabench: "):]


def cli_error(*args):
    """The message of one refused CLI run."""
    return refusal(args, run_cli(*args, check=False))


def cli_errors(arg_lists):
    """The messages of refused CLI runs, CLI_JOBS at a time, in order."""
    with ThreadPoolExecutor(CLI_JOBS) as pool:
        runs = list(pool.map(lambda args: run_cli(*args, check=False), arg_lists))
    return [refusal(args, done) for args, done in zip(arg_lists, runs)]


def read_pfm(path):
    """A grey PFM ("Pf", little-endian: scale < 0), rows stored bottom first, as float32 H x W."""
    data = pathlib.Path(path).read_bytes()
    magic, size, scale, pixels = data.split(b"\n", 3)
    assert magic == b"Pf" and float(scale) < 0, (magic, scale)
    width, height = map(int, size.split())
    image = np.frombuffer(pixels, dtype="<f4", count=width * height).reshape(height, width)
    return np.ascontiguousarray(image[::-1]).astype(np.float32)


def write_pfm(path, image):
    """The inverse of read_pfm: what `aabench render --out X.pfm` would write for `image`."""
    height, width = image.shape
    header = f"Pf\n{width} {height}\n-1.0\n".encode()
    body = np.ascontiguousarray(image[::-1], dtype="<f4").tobytes()
    pathlib.Path(path).write_bytes(header + body)


def write_grey_png(path, codes):
    """An untagged grey PNG of uint8 or uint16 codes (big-endian samples), from zlib alone."""
    height, width = codes.shape
    depth = 8 if codes.dtype == np.uint8 else 16
    samples = codes.astype(">u2") if depth == 16 else codes
    raw = b"".join(b"\x00" + samples[j].tobytes() for j in range(height))

    def chunk(kind, payload):
        body = kind + payload
        return struct.pack(">I", len(payload)) + body + struct.pack(">I", zlib.crc32(body))

    ihdr = struct.pack(">IIBBBBB", width, height, depth, 0, 0, 0, 0)
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw)) +
           chunk(b"IEND", b""))
    pathlib.Path(path).write_bytes(png)


def figures_from_cli_json(text):
    """`score --json`'s object as the module gives it: without "image", null as NaN and
    "inf"/"-inf" as infinities (docs/python.md)."""
    def decode(value):
        if value is None:
            return math.nan
        return {"inf": math.inf, "-inf": -math.inf}.get(value, value) if isinstance(
            value, str) else value

    out = json.loads(text)
    del out["image"]
    return {key: decode(value) for key, value in out.items()}


def same_value(a, b):
    """Equal, NaN equal to NaN, and of the same type (an int count stays an int)."""
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    return type(a) is type(b) and a == b


def bits(image):
    """The float32 image as its bit patterns: equality is bit for bit (-0.0, NaN included)."""
    assert image.dtype == np.float32
    return image.view(np.uint32)


@pytest.fixture(scope="session")
def two_d_patterns():
    """Every grey 2-D pattern of the registry (a 3-D one's scene has a world; a colour one's
    images here are its luminance, the CLI's its R, G, B)."""
    scenes = {p["id"]: aabench.Scene.pattern(p["id"], size=(8, 8)) for p in aabench.patterns()}
    return [i for i, s in scenes.items() if not s.is_3d and s.channels == 1]
