"""Each example of examples/python runs to its end and prints what it promises."""
import os
import subprocess
import sys

from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples" / "python"


def run_example(name, *args):
    result = subprocess.run([sys.executable, str(EXAMPLES / name), *map(str, args)],
                            capture_output=True, text=True, env=dict(os.environ))
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_extract_real_scans(real_dir):
    out = run_example("extract_real_scans.py", real_dir / "referee_mulran_kaist03" / "oxford_form")
    assert "3 scans of 400 azimuths x 3360 range bins (oxford layout)" in out
    assert "referee_r:kernel=box,z_q=3: shape (42, 1), rotation invariant: True" in out


def test_numpy_descriptor_gives_identical_metrics_both_ways(tmp_path):
    # The quickstart's town (600 scans, 388 revisit queries), whose scans the other tests cached.
    out = run_example("numpy_descriptor.py", "--out", tmp_path)
    assert "revisits: registered                  388  precomputed                  388" in out
    assert "identical metrics through register_descriptor and precomputed" in out


def test_read_results_of_the_committed_quickstart():
    out = run_example("read_results.py", SOURCE_DIR / "results" / "quickstart")
    assert "quickstart: 2 datasets x 4 descriptors" in out
    assert "PR areas recomputed from every curve.csv match the summary" in out
