"""radarpr.read_polar_png: what a scan carries, and OSError / ValueError for bad files."""
import numpy as np
import pytest

import radarpr
from conftest import synthetic_scan, write_oxford_png, write_png


def test_an_oxford_png_decodes_into_image_times_angles_and_layout(tmp_path):
    image = synthetic_scan(7, range_bins=600)
    write_oxford_png(tmp_path / "scan.png", image, start_ns=1_600_000_000_000_000_000)
    scan = radarpr.read_polar_png(tmp_path / "scan.png", range_resolution=0.25)
    assert scan.layout == "oxford"
    assert scan.range_resolution == 0.25
    np.testing.assert_array_equal(scan.image, image)
    assert scan.image.dtype == np.uint8 and not scan.image.flags.writeable
    assert scan.azimuths.shape == (400,) and scan.azimuths[1] == pytest.approx(2 * np.pi / 400)
    assert scan.azimuth_times_ns[0] == 1_600_000_000_000_000_000
    assert scan.timestamp_ns == scan.azimuth_times_ns[200]
    assert (scan.row_flags == 255).all()
    assert "400x600 oxford" in repr(scan)


def test_a_native_png_is_transposed_into_azimuth_rows(tmp_path):
    image = synthetic_scan(8, azimuths=400, range_bins=3360)
    write_png(tmp_path / "native.png", np.ascontiguousarray(image.T))
    scan = radarpr.read_polar_png(tmp_path / "native.png")
    assert scan.layout == "mulran_native" and scan.timestamp_ns is None
    assert scan.range_resolution == pytest.approx(200 / 3360)
    np.testing.assert_array_equal(scan.image, image)


def test_missing_and_malformed_files_are_os_errors_naming_the_file(tmp_path):
    with pytest.raises(OSError, match="missing.png"):
        radarpr.read_polar_png(tmp_path / "missing.png")
    (tmp_path / "text.png").write_text("not a png")
    with pytest.raises(OSError, match="text.png"):
        radarpr.read_polar_png(tmp_path / "text.png")


def test_bad_options_are_value_errors(tmp_path):
    write_oxford_png(tmp_path / "scan.png", synthetic_scan(1, range_bins=600))
    with pytest.raises(ValueError, match="layout: expected 'auto', 'oxford' or 'mulran_native'"):
        radarpr.read_polar_png(tmp_path / "scan.png", layout="polar")
    with pytest.raises(ValueError, match="600 range bins match no known sensor"):
        radarpr.read_polar_png(tmp_path / "scan.png")
