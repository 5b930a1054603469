"""The descriptor cache on disk as numpy sees it: each entry is a .npy that numpy.load opens (also
memory-mapped) beside a JSON sidecar saying what it holds; a damaged entry is reported naming
the file and recomputed, never used."""
import json
import os
import shutil
import subprocess

import numpy as np
import pytest

import radarpr
from conftest import SOURCE_DIR

QUICKSTART = SOURCE_DIR / "configs" / "quickstart.json"
ONLY_REFEREE = ["--set", 'descriptors=["referee"]']


def run_cli(program, cache, *arguments):
    """`radarpr ARGUMENTS` with its own cache folder; returns the finished process."""
    environment = dict(os.environ, RADARPR_CACHE_DIR=str(cache))
    return subprocess.run([program, *map(str, arguments)], check=True, capture_output=True,
                          text=True, env=environment)


def entries(cache):
    """{sidecar path: parsed sidecar} of every entry of the cache."""
    return {path: json.loads(path.read_text())
            for path in sorted((cache / "descriptors").rglob("*.json"))}


@pytest.fixture(scope="module")
def filled_cache(program, tmp_path_factory):
    """A cache filled by `radarpr run` of the quickstart (ReFeree only), and the values
    `radarpr export` writes from it."""
    folder = tmp_path_factory.mktemp("cache_files")
    cache = folder / "cache"
    run_cli(program, cache, "run", QUICKSTART, "--out", folder / "out", "--quiet", *ONLY_REFEREE)
    run_cli(program, cache, "export", QUICKSTART, "--out", folder / "export", "--quiet",
            *ONLY_REFEREE)
    return cache, folder / "export", folder / "out"


def exported_sessions(export):
    """(timestamps, referee values) of every session `radarpr export` wrote."""
    return [(np.load(times), np.load(times.parent / "referee.npy"))
            for times in sorted(export.rglob("timestamps.npy"))]


def test_numpy_opens_every_entry_with_the_values_radarpr_evaluates(filled_cache):
    cache, export, _ = filled_cache
    found = entries(cache)
    sessions = exported_sessions(export)
    # One entry per distinct sequence (the single-session dataset is one of the other's).
    assert len(found) >= 2
    matched = set()
    for sidecar, fields in found.items():
        values_file = sidecar.with_name(fields["values_file"])
        assert values_file == sidecar.with_suffix(".npy")
        values = np.load(values_file)
        assert values.dtype == np.float32
        assert list(values.shape) == fields["shape"]
        assert values.shape[0] == len(fields["timestamps_ns"])
        mapped = np.load(values_file, mmap_mode="r")
        assert isinstance(mapped, np.memmap)
        np.testing.assert_array_equal(mapped, values)
        times = np.array(fields["timestamps_ns"], dtype=np.int64)
        for index, (exported_times, exported_values) in enumerate(sessions):
            if np.array_equal(exported_times, times):
                np.testing.assert_array_equal(values.reshape(len(values), -1), exported_values)
                matched.add(index)
    assert matched == set(range(len(sessions)))


def test_the_sidecar_says_what_the_values_are(filled_cache):
    cache, _, _ = filled_cache
    for sidecar, fields in entries(cache).items():
        assert fields["format"] == "radarpr descriptor values"
        assert fields["format_version"] == 3
        assert fields["descriptor"] == "referee"
        assert fields["sequence_fingerprint"].startswith("synthetic")
        assert fields["radarpr_version"] == radarpr.__version__
        assert fields["dtype"] == "float32"
        assert fields["values_bytes"] == sidecar.with_suffix(".npy").stat().st_size
        assert fields["mean_extract_ms"] > 0
        assert fields["training"] is None
        assert np.all(np.diff(fields["timestamps_ns"]) > 0)
        assert len(fields["checksum"]) == 16


@pytest.mark.parametrize("damage", ["flip a value", "truncate the values", "edit the sidecar"])
def test_a_damaged_entry_is_reported_naming_the_file_and_recomputed(program, filled_cache,
                                                                     tmp_path, damage):
    cache = tmp_path / "cache"
    shutil.copytree(filled_cache[0], cache)
    first = filled_cache[2]
    sidecar, fields = next(iter(entries(cache).items()))
    values_file = sidecar.with_suffix(".npy")
    if damage == "flip a value":
        data = bytearray(values_file.read_bytes())
        data[-3] ^= 0x10
        values_file.write_bytes(bytes(data))
        damaged = values_file
    elif damage == "truncate the values":
        os.truncate(values_file, values_file.stat().st_size - 4)
        damaged = values_file
    else:
        fields["timestamps_ns"][0] += 1
        sidecar.write_text(json.dumps(fields))
        damaged = sidecar
    second = run_cli(program, cache, "run", QUICKSTART, "--out", tmp_path / "second", "--quiet",
                     *ONLY_REFEREE)
    assert str(damaged) in second.stderr
    assert "recomputing" in second.stderr
    assert (tmp_path / "second" / "summary.md").read_text() == \
        (first / "summary.md").read_text()
    # Recomputed and stored again: numpy reads the repaired entry, and the next run is quiet.
    assert np.load(values_file, mmap_mode="r").shape[0] == len(fields["timestamps_ns"])
    third = run_cli(program, cache, "run", QUICKSTART, "--out", tmp_path / "third", "--quiet",
                    *ONLY_REFEREE)
    assert "warning" not in third.stderr
