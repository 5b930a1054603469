"""radarpr.run, radarpr.load_results and radarpr.open_dataset: the same results as the
command line, folders read back as numpy columns, datasets streamed scan by scan."""
import json
import subprocess

import numpy as np
import pytest

import radarpr
from conftest import SOURCE_DIR

QUICKSTART = SOURCE_DIR / "configs" / "quickstart.json"
REFERENCE = SOURCE_DIR / "results" / "quickstart"


def test_run_with_overrides_equals_the_cli(program, tmp_path):
    overrides = {"protocol.revisit_radius_m": 10, "descriptors": ["referee", "referee_a"]}
    results = radarpr.run(QUICKSTART, out=tmp_path / "python", overrides=overrides,
                          report=False)
    subprocess.run([program, "run", str(QUICKSTART), "--out", str(tmp_path / "cli"), "--quiet",
                    "--set", "protocol.revisit_radius_m=10",
                    "--set", 'descriptors=["referee","referee_a"]'],
                   check=True, capture_output=True)
    cli = json.loads((tmp_path / "cli" / "summary.json").read_text())
    assert results.summary == cli
    assert results.summary["protocol"]["revisit_radius_m"] == 10
    assert results.descriptors == ["referee", "referee_a"]
    assert (tmp_path / "python" / "summary.md").read_text() == \
        (tmp_path / "cli" / "summary.md").read_text()


def test_run_refuses_bad_configs_with_config_errors(tmp_path):
    with pytest.raises(radarpr.ConfigError, match="--set protocol.revisit_radius_m=-5"):
        radarpr.run(QUICKSTART, out=tmp_path / "x", overrides=["protocol.revisit_radius_m=-5"])
    config = json.loads(QUICKSTART.read_text())
    config["descriptors"] = ["no_such_descriptor"]
    with pytest.raises(radarpr.ConfigError, match="unknown descriptor 'no_such_descriptor'"):
        radarpr.run(config, out=tmp_path / "y")
    with pytest.raises(OSError, match="missing.json"):
        radarpr.run(tmp_path / "missing.json")


def test_load_results_reads_the_committed_quickstart_into_numpy_columns():
    results = radarpr.load_results(REFERENCE)
    summary = json.loads((REFERENCE / "summary.json").read_text())
    assert results.experiment == "quickstart"
    assert results.datasets == ["synthetic_town", "synthetic_town_2_sessions"]
    assert results.rows == summary["rows"]
    table = results.table("synthetic_town")
    rows = [row for row in summary["rows"] if row["dataset"] == "synthetic_town"]
    assert table["descriptor"] == [row["descriptor"] for row in rows]
    np.testing.assert_array_equal(table["roc_auc"], [row["roc_auc"] for row in rows])
    np.testing.assert_array_equal(table["recall_at_5"], [row["recall_at_k"]["5"] for row in rows])
    curve = results.curve("synthetic_town", "referee")
    assert set(curve) == {"threshold", "precision", "recall", "fpr", "f1"}
    assert np.all(np.diff(curve["threshold"]) > 0)
    graph = results.matching_graph("synthetic_town", "referee")
    assert set(graph["label"]) <= {"tp", "fp", "fn"}
    with pytest.raises(KeyError, match="no dataset 'nowhere'"):
        results.table("nowhere")


def test_load_results_of_a_missing_folder_is_an_os_error(tmp_path):
    with pytest.raises(OSError, match="summary.json"):
        radarpr.load_results(tmp_path)


def test_open_dataset_streams_scans_with_times_and_poses():
    dataset = radarpr.open_dataset({"type": "synthetic", "seed": 7, "session": 0, "scans": 40})
    assert len(dataset) == 40
    assert dataset.positions.shape == (40, 3)
    assert np.all(np.diff(dataset.timestamps_ns) > 0)
    first = dataset[0]
    assert first.image.dtype == np.uint8 and first.image.ndim == 2
    assert first.timestamp_ns == dataset.timestamps_ns[0]
    assert first.pose == tuple(dataset.positions[0])
    streamed = [scan.index for scan, _ in zip(dataset, range(3))]
    assert streamed == [0, 1, 2]
    np.testing.assert_array_equal(dataset[-40].image, first.image)
    with pytest.raises(IndexError):
        dataset[40]
    value = radarpr.Descriptor("referee").extract(first.image,
                                                  range_resolution=first.range_resolution)
    assert value.shape == (50, 1)


def test_open_dataset_errors():
    with pytest.raises(radarpr.ConfigError, match="dataset.type"):
        radarpr.open_dataset({"type": "nowhere"})
    with pytest.raises(radarpr.ConfigError, match="dataset.*scanz"):
        radarpr.open_dataset({"type": "synthetic", "seed": 7, "scanz": 3})
