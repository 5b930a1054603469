"""How much the Python module adds to an extraction, and how extract_many scales with threads.

For each descriptor, on a 400 x 3360 scan (MulRan's geometry; the real KAIST03 sample when it is
beside the checkout, else a synthetic scan of that size):
- C++: Descriptor.time_extract, the extraction timed in a C++ loop (no Python in between);
- Python: Descriptor.extract called from a Python loop on the same scan;
the ratio Python / C++ (target: at most 1.05). Then extract_many over 64 scans with 1 and 2
threads (target: 2 threads at least 1.7 times as fast). The two sides of each ratio are measured
back to back in every round (their order alternating), and the ratio is taken round by round, so
that a machine whose speed drifts (other processes) moves both sides alike; each ratio is printed
as the median of the rounds with its smallest and largest value. "cores" is the process's CPU
time over the wall time of the 2-thread extract_many (median): near 2 when both threads ran at
once, near 1 when other processes left the two threads one core between them, and the speed-up
cannot then be measured.

    PYTHONPATH=build/python python3 benchmarks/python/extract_speed.py [--rounds 9]
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


def seconds(function):
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def paired(first, second, rounds):
    """Times of `first` and `second` measured back to back in each round, the order alternating:
    two lists of seconds, one entry per round."""
    a, b = [], []
    for round_index in range(rounds):
        if round_index % 2 == 0:
            a.append(first())
            b.append(second())
        else:
            b.append(second())
            a.append(first())
    return np.array(a), np.array(b)


def spread(ratios):
    """The median ratio with its smallest and largest: '1.012 [0.998-1.030]'."""
    return f"{np.median(ratios):.3f} [{ratios.min():.3f}-{ratios.max():.3f}]"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=9)
    parser.add_argument("--repeats", type=int, default=100, help="extractions per round")
    args = parser.parse_args()
    image, many, source = scans()
    print(f"{source}, {image.shape[0]} x {image.shape[1]}; {args.rounds} rounds, ratios as "
          "median [min-max] of the rounds")
    print(f"{'descriptor':<28} {'C++ ms':>8} {'Python ms':>10} {'Python/C++':>21}  "
          f"{'1 thread ms':>11} {'2 threads ms':>12} {'1 thread/2 threads':>21} {'cores':>5}")
    for descriptor_id in DESCRIPTORS:
        d = radarpr.Descriptor(descriptor_id)
        d.extract(image, range_resolution=RESOLUTION)  # warm-up

        def cpp_loop():
            return d.time_extract(image, range_resolution=RESOLUTION, repeats=args.repeats)

        def python_loop():
            def loop():
                for _ in range(args.repeats):
                    d.extract(image, range_resolution=RESOLUTION)
            return seconds(loop) / args.repeats

        cores = []

        def many_with(threads):
            def timed():
                cpu = time.process_time()
                wall = seconds(lambda: d.extract_many(many, range_resolution=RESOLUTION,
                                                      num_threads=threads))
                if threads == 2:
                    cores.append((time.process_time() - cpu) / wall)
                return wall
            return timed

        python, cpp = paired(python_loop, cpp_loop, args.rounds)
        one, two = paired(many_with(1), many_with(2), args.rounds)
        print(f"{d.id:<28} {np.median(cpp) * 1e3:8.3f} {np.median(python) * 1e3:10.3f} "
              f"{spread(python / cpp):>21}  {np.median(one) / len(many) * 1e3:11.3f} "
              f"{np.median(two) / len(many) * 1e3:12.3f} {spread(one / two):>21} "
              f"{np.median(cores):5.2f}")


if __name__ == "__main__":
    main()
