"""How much the Python module adds to an extraction, and how extract_many scales with threads.

For each descriptor, on a 400 x 3360 scan (MulRan's geometry; the real KAIST03 sample when it is
beside the checkout, else a synthetic scan of that size):
- C++: Descriptor.time_extract, the extraction timed in a C++ loop (no Python in between);
- Python: Descriptor.extract called from a Python loop on the same scan;
the ratio Python / C++ (target: at most 1.05). Then extract_many over 64 scans with 1 and 2
threads (target: 2 threads at least 1.7 times as fast). Each figure is the fastest of several
rounds, the usual way to read timings on a shared machine.

    PYTHONPATH=build/python python3 benchmarks/python/extract_speed.py [--rounds 7]
"""
import argparse
import pathlib
import time

import numpy as np

import radarpr

REAL = (pathlib.Path(__file__).resolve().parents[2].parent / "shared" / "data" / "real" /
        "referee_mulran_kaist03" / "oxford_form" / "000000.png")
DESCRIPTORS = ["referee", "referee_r:kernel=box,z_q=3", "referee_a"]
RESOLUTION = 200.0 / 3360.0


def scans():
    if REAL.exists():
        first = radarpr.read_polar_png(REAL).image.copy()
        source = f"real scan {REAL.name}"
    else:
        first = np.random.default_rng(0).gamma(1.5, 12.0, size=(400, 3360)).clip(0, 255)
        first = first.astype(np.uint8)
        source = "synthetic scan"
    # 64 different scans for extract_many: the first one turned by k azimuths.
    return first, [np.ascontiguousarray(np.roll(first, k, axis=0)) for k in range(64)], source


def fastest(function, rounds):
    best = float("inf")
    for _ in range(rounds):
        start = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - start)
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--repeats", type=int, default=200, help="extractions per round")
    args = parser.parse_args()
    image, many, source = scans()
    print(f"{source}, {image.shape[0]} x {image.shape[1]}; fastest of {args.rounds} rounds")
    print(f"{'descriptor':<28} {'C++ ms':>8} {'Python ms':>10} {'ratio':>6}  "
          f"{'1 thread ms':>11} {'2 threads ms':>12} {'speed-up':>8}")
    for descriptor_id in DESCRIPTORS:
        d = radarpr.Descriptor(descriptor_id)
        d.extract(image, range_resolution=RESOLUTION)  # warm-up
        cpp = min(d.time_extract(image, range_resolution=RESOLUTION, repeats=args.repeats)
                  for _ in range(args.rounds))

        def python_loop():
            for _ in range(args.repeats):
                d.extract(image, range_resolution=RESOLUTION)

        python = fastest(python_loop, args.rounds) / args.repeats
        one = fastest(lambda: d.extract_many(many, range_resolution=RESOLUTION, num_threads=1),
                      args.rounds)
        two = fastest(lambda: d.extract_many(many, range_resolution=RESOLUTION, num_threads=2),
                      args.rounds)
        print(f"{d.id:<28} {cpp * 1e3:8.3f} {python * 1e3:10.3f} {python / cpp:6.3f}  "
              f"{one / len(many) * 1e3:11.3f} {two / len(many) * 1e3:12.3f} {one / two:8.2f}")


if __name__ == "__main__":
    main()
