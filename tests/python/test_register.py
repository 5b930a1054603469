"""radarpr.register_descriptor: a Python function as a descriptor of configs run from this
process, ranked like `precomputed` for l2/cosine, and its errors reported with the name."""
import numpy as np
import pytest

import radarpr


def ring_means(image, range_resolution):
    """16 range rings' mean power: rotation invariant, any A x R with R >= 16."""
    rings = image.shape[1] // 16
    return image[:, :rings * 16].reshape(image.shape[0], 16, rings).mean(axis=(0, 2))


def config(descriptors, scans=600):
    return {"experiment": "python_descriptor",
            "datasets": [{"name": "town",
                          "query": {"type": "synthetic", "seed": 7, "session": 0,
                                    "scans": scans}}],
            "descriptors": descriptors,
            "protocol": {"exclude_recent_frames": 50, "revisit_radius_m": 20}}


def test_a_registered_descriptor_runs_like_any_other_and_matches_evaluate(tmp_path):
    radarpr.register_descriptor("ring_means_l2", extract=ring_means, shape=(16,),
                                rotation_invariant=True)
    listed = {d["name"]: d for d in radarpr.descriptors()}["ring_means_l2"]
    assert listed["origin"].startswith("plugin python ") and listed["shape"] == (16, 1)
    results = radarpr.run(config(["ring_means_l2", "referee"]), out=tmp_path / "run",
                          report=False)
    row = results.rows[0]
    assert row["descriptor"] == "ring_means_l2" and row["shape"] == [16, 1]
    assert row["rotation_invariant"] is True
    # The same values through radarpr.Descriptor and evaluate give the run's metrics.
    dataset = radarpr.open_dataset(config([])["datasets"][0]["query"])
    d = radarpr.Descriptor("ring_means_l2")
    values = np.stack([d.extract(s.image, range_resolution=s.range_resolution).ravel()
                       for s in dataset])
    np.testing.assert_array_equal(
        values[3], ring_means(dataset[3].image, dataset[3].range_resolution).astype(np.float32))
    assert row["revisits"] > 100
    result = radarpr.evaluate(values, dataset.positions, protocol=config([])["protocol"],
                              timestamps=dataset.timestamps_ns)
    for name in ("roc_auc", "f1_max", "recall_at_1", "recall_at_k", "queries", "revisits"):
        assert result.metrics[name] == row[name], name


def test_a_python_distance_is_ranked_exhaustively(tmp_path):
    def hellinger(a, b):
        a, b = np.sqrt(np.abs(a) / np.abs(a).sum()), np.sqrt(np.abs(b) / np.abs(b).sum())
        return float(np.linalg.norm(a - b))

    radarpr.register_descriptor("ring_means_hellinger", extract=ring_means, distance=hellinger,
                                shape=(16, 1))
    results = radarpr.run(config(["ring_means_hellinger"], scans=80), out=tmp_path / "run",
                          report=False)
    dataset = radarpr.open_dataset(config([], scans=80)["datasets"][0]["query"])
    values = np.stack([ring_means(s.image, s.range_resolution) for s in dataset])
    values = values.astype(np.float32)
    # Exhaustive: each query's top-1 is the nearest eligible frame by the Python distance.
    row = results.rows[0]
    eligible = range(50, 80)
    expected = [min(range(q - 50 + 1), key=lambda m: hellinger(values[q], values[m]))
                for q in eligible]
    evaluated = radarpr.evaluate(values, dataset.positions, protocol=config([])["protocol"],
                                 distance=radarpr.Descriptor("ring_means_hellinger"))
    assert evaluated.matches["match"].tolist() == expected
    assert evaluated.metrics["roc_auc"] == row["roc_auc"]


def test_registration_and_extraction_errors():
    with pytest.raises(ValueError, match="name: expected lower-case"):
        radarpr.register_descriptor("Bad-Name", extract=ring_means, shape=(16,))
    with pytest.raises(ValueError, match="shape: expected"):
        radarpr.register_descriptor("bad_shape", extract=ring_means, shape=(0, 3))
    with pytest.raises(ValueError, match="distance: expected 'l2', 'cosine'"):
        radarpr.register_descriptor("bad_distance", extract=ring_means, distance="manhattan",
                                    shape=(16,))
    with pytest.raises(ValueError, match="referee.*registered"):
        radarpr.register_descriptor("referee", extract=ring_means, shape=(16,))

    def broken(image, range_resolution):
        raise ZeroDivisionError("no weights")

    radarpr.register_descriptor("broken", extract=broken, shape=(4,))
    radarpr.register_descriptor("wrong_size", extract=ring_means, shape=(5,))
    image = np.zeros((40, 160), dtype=np.uint8)
    with pytest.raises(RuntimeError, match="descriptor 'broken': extract raised.*no weights"):
        radarpr.Descriptor("broken").extract(image, range_resolution=0.1)
    with pytest.raises(RuntimeError, match="'wrong_size': extract returned.*expected 5 numbers"):
        radarpr.Descriptor("wrong_size").extract(image, range_resolution=0.1)
