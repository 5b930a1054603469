"""Shared fixtures of the Python module's tests: the built module, the radarpr program it is
compared with, the real samples beside the checkout, and synthetic polar PNGs."""
import json
import os
import pathlib
import struct
import subprocess
import zlib

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("RADARPR_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
REAL_DIR = SOURCE_DIR.parent / "shared" / "data" / "real"


@pytest.fixture(scope="session")
def program():
    """The `radarpr` program of the same build (ctest sets RADARPR_PROGRAM)."""
    path = os.environ.get("RADARPR_PROGRAM")
    if not path or not os.path.exists(path):
        pytest.skip("RADARPR_PROGRAM does not name the radarpr program (run through ctest)")
    return path


@pytest.fixture(scope="session")
def real_dir():
    if not REAL_DIR.is_dir():
        pytest.skip(f"real radar samples not found at {REAL_DIR}")
    return REAL_DIR


def cli_extract(program, descriptor_id, files, *extra):
    """`radarpr extract` of each file: a list of (shape, float32 values)."""
    out = subprocess.run([program, "extract", descriptor_id, *map(str, files), *extra],
                         check=True, capture_output=True, text=True).stdout
    lines = [json.loads(line) for line in out.splitlines()]
    return [(tuple(line["shape"]), np.array(line["values"], dtype=np.float32)) for line in lines]


def write_png(path, pixels):
    """An 8-bit greyscale PNG of a 2-D uint8 array (zlib and struct only)."""
    height, width = pixels.shape

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    raw = b"".join(b"\x00" + pixels[row].tobytes() for row in range(height))
    png = (b"\x89PNG\r\n\x1a\n" +
           chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))
    pathlib.Path(path).write_bytes(png)


def write_oxford_png(path, image, start_ns=1_600_000_000_000_000_000):
    """A scan in the Oxford layout: per row an int64 LE time (ns), a uint16 LE encoder count
    (5600 a revolution), a valid byte, then the range bins."""
    azimuths = image.shape[0]
    rows = np.zeros((azimuths, 11 + image.shape[1]), dtype=np.uint8)
    for a in range(azimuths):
        rows[a, 0:8] = np.frombuffer(struct.pack("<q", start_ns + a * 625_000), dtype=np.uint8)
        rows[a, 8:10] = np.frombuffer(struct.pack("<H", a * 5600 // azimuths), dtype=np.uint8)
        rows[a, 10] = 255
    rows[:, 11:] = image
    write_png(path, rows)


def synthetic_scan(seed, azimuths=400, range_bins=3360):
    """A polar scan with speckle and a few bright returns, so that every descriptor sees
    structure (not only noise)."""
    rng = np.random.default_rng(seed)
    image = rng.gamma(1.5, 12.0, size=(azimuths, range_bins)).clip(0, 255)
    for _ in range(60):
        a, r = rng.integers(azimuths), rng.integers(40, range_bins - 40)
        image[max(a - 2, 0):a + 3, r:r + rng.integers(3, 30)] += rng.uniform(60, 200)
    return image.clip(0, 255).astype(np.uint8)
