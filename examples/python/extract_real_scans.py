"""Extract radarpr's descriptors from real polar radar scans and compare the scans.

Reads every PNG of a folder (MulRan's Oxford-form scans by default, from the real samples beside
the checkout), extracts each descriptor and prints, per descriptor, the value's shape and the
distance between every pair of scans.

    PYTHONPATH=build/python python3 examples/python/extract_real_scans.py [FOLDER]
"""
import pathlib
import sys

import numpy as np

import radarpr

DEFAULT = (pathlib.Path(__file__).resolve().parents[2].parent / "shared" / "data" / "real" /
           "referee_mulran_kaist03" / "oxford_form")
DESCRIPTORS = ["referee", "referee_r:kernel=box,z_q=3", "referee_a", "radar_scan_context"]


def main(folder):
    files = sorted(pathlib.Path(folder).glob("*.png"))
    if not files:
        sys.exit(f"no PNG in {folder}")
    scans = [radarpr.read_polar_png(file) for file in files]
    names = [file.stem for file in files]
    print(f"{len(scans)} scans of {scans[0].image.shape[0]} azimuths x "
          f"{scans[0].image.shape[1]} range bins ({scans[0].layout} layout)")
    for descriptor_id in DESCRIPTORS:
        d = radarpr.Descriptor(descriptor_id)
        values = [d.extract(scan) for scan in scans]
        distances = np.array([[d.distance(a, b) for b in values] for a in values])
        print(f"\n{d.id}: shape {values[0].shape}, rotation invariant: {d.rotation_invariant}")
        print("          " + " ".join(f"{name:>10}" for name in names))
        for name, row in zip(names, distances):
            print(f"{name:>10} " + " ".join(f"{x:10.4f}" for x in row))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT)
