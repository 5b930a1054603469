"""radarpr.evaluate: the metrics `radarpr run` reports, from values exported by `radarpr export`,
whether ranked by the descriptor's own distance or as `precomputed` values; bad input raises."""
import json
import subprocess

import numpy as np
import pytest

import radarpr
from conftest import SOURCE_DIR

QUICKSTART = SOURCE_DIR / "configs" / "quickstart.json"


def folder_of(descriptor_id):
    """The folder a descriptor's files take (docs/results.md): ':' -> '__', ',' -> '_'."""
    return descriptor_id.replace(":", "__").replace(",", "_")


@pytest.fixture(scope="module")
def quickstart(program, tmp_path_factory):
    """The quickstart's values exported as .npy, and its summary as `radarpr run` writes it."""
    out = tmp_path_factory.mktemp("quickstart")
    subprocess.run([program, "export", str(QUICKSTART), "--out", str(out / "export"), "--quiet"],
                   check=True, capture_output=True)
    subprocess.run([program, "run", str(QUICKSTART), "--out", str(out / "run"), "--quiet"],
                   check=True, capture_output=True)
    summary = json.loads((out / "run" / "summary.json").read_text())
    return out / "export", summary


def session(export, dataset, role, descriptor_id):
    folder = export / dataset / role
    return (np.load(folder / f"{folder_of(descriptor_id)}.npy"), np.load(folder / "positions.npy"),
            np.load(folder / "timestamps.npy"))


METRICS = ["queries", "revisits", "correct_top1", "roc_auc", "f1_max", "f1_max_threshold",
           "pr_auc_trapezoid", "average_precision", "pr_auc_mulran", "recall_at_1", "recall_at_k",
           "recall_at_k_all_queries", "recall_at_100_precision", "extended_precision"]


def evaluate_row(export, row, protocol, distance):
    values, positions, times = session(export, row["dataset"], "query", row["descriptor"])
    extra = {}
    if row["session"] == "multi":
        db_values, db_positions, db_times = session(export, row["dataset"], "database",
                                                    row["descriptor"])
        extra = dict(database_values=db_values, database_positions=db_positions,
                     database_timestamps=db_times)
    return radarpr.evaluate(values, positions, protocol=protocol, distance=distance,
                            timestamps=times, **extra)


def test_evaluate_equals_radarpr_run_on_the_quickstart(quickstart):
    export, summary = quickstart
    protocol = json.loads(QUICKSTART.read_text())["protocol"]
    assert len(summary["rows"]) == 8
    for row in summary["rows"]:
        result = evaluate_row(export, row, protocol, radarpr.Descriptor(row["descriptor"]))
        for name in METRICS:
            assert result.metrics[name] == row[name], (row["dataset"], row["descriptor"], name)
        assert result.protocol == summary["protocol"]


def test_referee_values_evaluated_as_precomputed_l2_reproduce_referee(quickstart):
    # referee ranks by the L2 distance of its values: as `precomputed` values with distance l2
    # they give its metrics exactly.
    export, summary = quickstart
    protocol = json.loads(QUICKSTART.read_text())["protocol"]
    rows = [row for row in summary["rows"] if row["descriptor"] == "referee"]
    assert len(rows) == 2
    for row in rows:
        result = evaluate_row(export, row, protocol, "l2")
        assert {name: result.metrics[name] for name in METRICS} == \
            {name: row[name] for name in METRICS}


def test_curve_and_matches_are_numpy_columns():
    rng = np.random.default_rng(4)
    positions = np.cumsum(rng.normal(size=(300, 2)), axis=0) % 60
    values = (positions[:, :1] * [1.0, 0.5, -2.0] + rng.normal(size=(300, 3))).astype(np.float32)
    result = radarpr.evaluate(values, positions, protocol={"revisit_radius_m": 5,
                                                           "exclude_recent_frames": 10})
    assert result.metrics["queries"] == 290
    assert set(result.curve) == {"threshold", "tp", "fp", "fn", "tn", "precision", "recall",
                                 "f1", "fpr"}
    assert result.curve["threshold"].dtype == np.float64
    assert np.all(np.diff(result.curve["threshold"]) > 0)
    assert result.matches["query"].tolist() == list(range(10, 300))
    assert np.all(result.matches["match"] <= result.matches["query"] - 10)
    assert result.matches["correct"].dtype == bool
    assert result.metrics["correct_top1"] == int(result.matches["correct"].sum())
    # cosine ranks differently from l2 on values of different lengths.
    cosine = radarpr.evaluate(values, positions, protocol={"revisit_radius_m": 5,
                                                           "exclude_recent_frames": 10},
                              distance="cosine")
    assert cosine.matches["match"].tolist() != result.matches["match"].tolist()


def test_bad_input_raises_the_documented_exceptions():
    values = np.zeros((20, 4), dtype=np.float32)
    positions = np.zeros((20, 2))
    with pytest.raises(radarpr.ConfigError, match="protocol.revisit_radius_m: must be > 0"):
        radarpr.evaluate(values, positions, protocol={"revisit_radius_m": -1})
    with pytest.raises(radarpr.ConfigError, match="protocol.*radius_m"):
        radarpr.evaluate(values, positions, protocol={"radius_m": 5})
    with pytest.raises(ValueError, match="values: expected an N x D.*int64"):
        radarpr.evaluate(values.astype(np.int64), positions)
    with pytest.raises(ValueError, match="positions: 19 rows for 20 values"):
        radarpr.evaluate(values, positions[:19])
    with pytest.raises(ValueError, match="positions: expected an N x 2 to N x 3"):
        radarpr.evaluate(values, np.zeros((20, 5)))
    with pytest.raises(ValueError, match="row 3 holds a value that is not finite"):
        bad = values.copy()
        bad[3, 1] = np.nan
        radarpr.evaluate(bad, positions)
    with pytest.raises(ValueError, match="timestamps: expected 20 int64 times in ns.*a list"):
        radarpr.evaluate(values, positions, timestamps=list(range(20)))
    with pytest.raises(ValueError, match="timestamps: must increase"):
        radarpr.evaluate(values, positions, timestamps=np.zeros(20, dtype=np.int64))
    with pytest.raises(ValueError, match="exclude_recent_seconds needs timestamps"):
        radarpr.evaluate(values, positions, protocol={"exclude_recent_seconds": 3})
    with pytest.raises(ValueError, match="revisit_max_yaw_deg needs N x 3 positions.*N x 2"):
        radarpr.evaluate(values, positions, protocol={"revisit_max_yaw_deg": 30})
    with pytest.raises(radarpr.ConfigError, match="unknown descriptor 'hamming'"):
        radarpr.evaluate(values, positions, distance="hamming")


def test_a_heading_limit_drops_revisits_driven_the_other_way():
    # 60 frames east along y = 0, then the same road driven back west: every frame of the return
    # is within the radius of an outbound frame more than 50 frames older, facing the other way.
    outbound = [(float(x), 0.0, 0.0) for x in range(60)]
    back = [(float(x), 0.0, np.pi) for x in range(59, -1, -1)]
    positions = np.array(outbound + back)
    values = np.random.default_rng(7).random((120, 8), dtype=np.float32)
    anyway = radarpr.evaluate(values, positions, protocol={"revisit_radius_m": 5})
    same_heading = radarpr.evaluate(
        values, positions, protocol={"revisit_radius_m": 5, "revisit_max_yaw_deg": 30})
    assert anyway.metrics["revisits"] > 0
    assert same_heading.metrics["revisits"] == 0
