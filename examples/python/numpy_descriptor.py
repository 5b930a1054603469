"""A learned-style descriptor written in numpy alone, evaluated by radarpr twice.

The descriptor: the scan shrunk to 8-bin range rings, each ring's mean and spread over azimuth
(so a turn of the vehicle changes nothing), passed through a fixed random projection (a seeded
matrix standing in for trained weights) and a tanh, as a small network's last layer would be.

It is evaluated (1) registered with radarpr.register_descriptor and run as a config descriptor,
and (2) as values written to .npy files and run through the built-in `precomputed` descriptor,
as values from any other framework would be. Both give the same metrics, which the script
checks.

    PYTHONPATH=build/python python3 examples/python/numpy_descriptor.py [--scans N] [--out DIR]
"""
import argparse
import pathlib
import tempfile

import numpy as np

import radarpr

RING_BINS = 8
FEATURES = 64
# The "trained weights": fixed, so every run describes a scan the same way.
WEIGHTS = np.random.default_rng(2024).normal(size=(FEATURES, 2 * 420)) / np.sqrt(2 * 420)


def describe(image, range_resolution):
    """A scan's 64 values: ring means and spreads, projected. Any A x R image with R >= 8."""
    rings = image.shape[1] // RING_BINS
    shrunk = image[:, :rings * RING_BINS].reshape(image.shape[0], rings, RING_BINS).mean(axis=2)
    profile = np.concatenate([shrunk.mean(axis=0), shrunk.std(axis=0)]) / 255.0
    profile = np.resize(profile, WEIGHTS.shape[1])  # any bin count onto the weights' width
    return np.tanh(WEIGHTS @ profile).astype(np.float32)


def dataset(scans):
    return {"type": "synthetic", "seed": 7, "session": 0, "scans": scans}


def config(scans, descriptors):
    return {"experiment": "numpy_descriptor",
            "datasets": [{"name": "town", "query": dataset(scans)}],
            "descriptors": descriptors,
            "protocol": {"exclude_recent_frames": 50, "revisit_radius_m": 20}}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scans", type=int, default=600)
    parser.add_argument("--out", type=pathlib.Path, default=None)
    args = parser.parse_args()
    out = args.out or pathlib.Path(tempfile.mkdtemp(prefix="numpy_descriptor_"))

    # (1) Registered: radarpr extracts it from every scan of the config's datasets.
    radarpr.register_descriptor("random_rings", extract=describe, distance="cosine",
                                shape=(FEATURES, 1), rotation_invariant=True)
    registered = radarpr.run(config(args.scans, ["random_rings"]), out=out / "registered",
                             report=False)

    # (2) Precomputed: the same values written as .npy by the user, then read by `precomputed`.
    sequence = radarpr.open_dataset(dataset(args.scans))
    values = np.stack([describe(scan.image, scan.range_resolution) for scan in sequence])
    np.save(out / "values.npy", values)
    np.save(out / "timestamps.npy", sequence.timestamps_ns)
    precomputed = {"name": "precomputed", "label": "random_rings",
                   "params": {"values": str(out / "values.npy"),
                              "timestamps": str(out / "timestamps.npy"), "distance": "cosine"}}
    replayed = radarpr.run(config(args.scans, [precomputed]), out=out / "precomputed",
                           report=False)

    names = ["roc_auc", "f1_max", "recall_at_1", "queries", "revisits"]
    first, second = registered.rows[0], replayed.rows[0]
    for name in names:
        print(f"{name:>12}: registered {first[name]!s:>20}  precomputed {second[name]!s:>20}")
    metrics = [key for key in first if key in second and key not in
               ("descriptor", "label", "training")]
    different = [key for key in metrics if key not in ("rotation_invariant",) and
                 first[key] != second[key] and key not in ("query_sequence", "database_sequence")]
    if different:
        raise SystemExit(f"the two routes differ in: {', '.join(different)}")
    print(f"identical metrics through register_descriptor and precomputed ({out})")


if __name__ == "__main__":
    main()
