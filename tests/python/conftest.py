"""Shared helpers of the Python module's tests: the ewaview program and a plain PNG reader."""
import os
import struct
import subprocess
import zlib
from pathlib import Path

import numpy as np
import pytest


def read_png(data):
    """Decodes an 8-bit RGB or RGBA, non-interlaced PNG (what ewaview writes) to uint8 (H, W, C),
    independently of the module, so the comparison does not trust the code under test."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and ctype in (2, 6) and interlace == 0
            channels = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    out = np.zeros((height, stride), np.int32)
    prev = np.zeros(stride, np.int32)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        row = np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int32)
        cur = np.zeros(stride, np.int32)
        for x in range(stride):
            a = cur[x - channels] if x >= channels else 0
            b = prev[x]
            c = prev[x - channels] if x >= channels else 0
            if kind == 0:
                p = 0
            elif kind == 1:
                p = a
            elif kind == 2:
                p = b
            elif kind == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[x] = (row[x] + p) & 255
        out[y] = cur
        prev = cur
    return out.astype(np.uint8).reshape(height, width, channels)


# Two renders with the same settings: llvmpipe gives the same bytes, a GPU may not, since its
# slab partition and compute tiles add a frame's floats in an order that varies from run to run
# (atomics); that moves a pixel by a level or so. Wrong settings move pictures by far more.
PICTURE_TOLERANCE = 2


def picture_difference(a, b):
    assert a.shape == b.shape, f"shapes {a.shape} and {b.shape}"
    return int(np.abs(a.astype(np.int32) - b.astype(np.int32)).max())


def assert_same_picture(actual, expected, tolerance=PICTURE_TOLERANCE):
    worst = picture_difference(actual, expected)
    assert worst <= tolerance, f"pictures differ by up to {worst} levels (tolerance {tolerance})"


def differs(a, b, tolerance=PICTURE_TOLERANCE):
    """Whether two pictures differ by more than run-to-run rounding."""
    return picture_difference(a, b) > tolerance


class Cli:
    """Runs the ewaview program the module was built beside."""

    def __init__(self, binary, out):
        self.binary, self.out = binary, out

    def run(self, *args):
        return subprocess.run([self.binary, *map(str, args)], capture_output=True, text=True,
                              stdin=subprocess.DEVNULL)

    def picture(self, name, *args):
        """The RGB picture `ewaview ARGS --output NAME.png` writes."""
        path = self.out / f"{name}.png"
        r = self.run(*args, "--output", path)
        assert r.returncode == 0, r.stderr
        return read_png(path.read_bytes())[:, :, :3]


@pytest.fixture(scope="session", autouse=True)
def scratch_settings(tmp_path_factory):
    """A settings folder of the tests' own: nothing of the user's (window bookmarks a tour
    would find) comes in, and the command line run beside the module sees the same one."""
    os.environ["EWAVIEW_CONFIG_DIR"] = str(tmp_path_factory.mktemp("config"))


@pytest.fixture(scope="session")
def out_dir():
    path = Path(os.environ.get("EWA_TEST_OUT", "build/test-output/python"))
    path.mkdir(parents=True, exist_ok=True)
    return path


@pytest.fixture(scope="session")
def cli(out_dir):
    return Cli(os.environ.get("EWA_BINARY", "build/ewaview"), out_dir)


@pytest.fixture(scope="session")
def shared_data():
    return Path(os.environ.get("EWA_SHARED_DATA", "../shared/data"))
