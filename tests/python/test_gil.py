"""Long calls release the GIL: a second Python thread keeps running during extract_many."""
import threading
import time

import radarpr
from conftest import synthetic_scan


def test_a_python_thread_makes_progress_during_a_long_extract_many():
    d = radarpr.Descriptor("referee")
    scans = [synthetic_scan(0)] * 150  # about 0.15 s of one core, more on a busy machine
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        start = time.perf_counter()
        d.extract_many(scans, num_threads=1)
        end = time.perf_counter()
    finally:
        done.set()
        counter.join()
    # The middle half of the call: were the GIL held throughout, the counter could not tick there.
    quarter = (end - start) / 4
    inside = [t for t in ticks if start + quarter < t < end - quarter]
    assert len(inside) >= 10, f"{len(inside)} ticks in the middle of a {end - start:.3f} s call"
