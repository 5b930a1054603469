"""Runs the Python module's pytest files; exits 77 (a skip for ctest) when numpy or pytest is
missing from this interpreter, saying which."""
import sys

missing = []
for name in ("numpy", "pytest"):
    try:
        __import__(name)
    except ImportError:
        missing.append(name)
if missing:
    print(f"SKIPPED: {sys.executable} has no {' or '.join(missing)} "
          "(apt install python3-numpy python3-pytest)")
    sys.exit(77)

import pytest  # noqa: E402

sys.exit(pytest.main(sys.argv[1:]))
