"""radarpr.descriptors() and radarpr.Descriptor: the values equal `radarpr extract`'s, arrays of
every layout are read right or refused with ValueError, errors carry radarpr's messages."""
import numpy as np
import pytest

import radarpr
from conftest import cli_extract, synthetic_scan, write_oxford_png

#Descriptors that extract from a scan alone(open_radvlad learns a codebook first, precomputed
#reads files).
IDS = ["referee", "referee_r", "referee_r:kernel=box,z_q=3", "referee_a", "radar_scan_context",
       "raplace"]


def test_descriptors_lists_every_registered_one_with_parameters_and_shape():
    listed = {d["name"]: d for d in radarpr.descriptors()}
    assert {"referee", "referee_r", "referee_a", "precomputed", "raplace"} <= set(listed)
    referee_r = listed["referee_r"]
    assert referee_r["origin"] == "built-in"
    assert referee_r["shape"] == radarpr.Descriptor("referee_r").shape(400, 3360, 200 / 3360)
    assert referee_r["rotation_invariant"] is True
    kernel = next(p for p in referee_r["parameters"] if p["name"] == "kernel")
    assert kernel["kind"] == "choice" and "box" in kernel["choices"]
    assert listed["precomputed"]["shape"] is None  # needs its values file


def test_descriptor_id_is_canonical():
    d = radarpr.Descriptor("referee_r:z_q=3,kernel=box")
    assert d.id == "referee_r:kernel=box,z_q=3"
    assert d.name == "referee_r"
    assert d.parameters["z_q"] == 3
    value = d.extract(synthetic_scan(0), range_resolution=200 / 3360)
    assert d.shape(400, 3360, 200 / 3360) == value.shape
    assert repr(d) == "radarpr.Descriptor('referee_r:kernel=box,z_q=3')"


@pytest.mark.parametrize("descriptor_id", IDS)
def test_extract_equals_the_cli_on_the_real_samples(program, real_dir, descriptor_id):
    files = sorted((real_dir / "referee_mulran_kaist03" / "oxford_form").glob("*.png"))
    files += sorted((real_dir / "oxford_radar_robotcar_extra_evanflash").glob("*.png"))[:1]
    assert files, "no PNG in the real samples"
    d = radarpr.Descriptor(descriptor_id)
    for file, (shape, values) in zip(files, cli_extract(program, descriptor_id, files)):
        scan = radarpr.read_polar_png(file)
        value = d.extract(scan)
        assert value.dtype == np.float32 and value.shape == shape, file
        np.testing.assert_array_equal(value.ravel(), values, err_msg=str(file))


@pytest.mark.parametrize("descriptor_id", IDS)
def test_extract_equals_the_cli_on_synthetic_scans(program, tmp_path, descriptor_id):
    images = [synthetic_scan(seed) for seed in range(2)]
    files = []
    for i, image in enumerate(images):
        files.append(tmp_path / f"scan{i}.png")
        write_oxford_png(files[-1], image)
    d = radarpr.Descriptor(descriptor_id)
    expected = cli_extract(program, descriptor_id, files)
    for file, image, (shape, values) in zip(files, images, expected):
        scan = radarpr.read_polar_png(file)
        np.testing.assert_array_equal(scan.image, image)
#The decoded scan and the bare array(with the file 's encoder angles) give the CLI' s.
        np.testing.assert_array_equal(d.extract(scan).ravel(), values)
        from_array = d.extract(image, range_resolution=200.0 / 3360.0, azimuths=scan.azimuths)
        assert from_array.shape == shape
        np.testing.assert_array_equal(from_array.ravel(), values)


def test_extract_many_equals_extract_for_lists_stacks_and_threads():
    d = radarpr.Descriptor("referee_r:kernel=box,z_q=3")
    images = [synthetic_scan(seed, range_bins=1200) for seed in range(5)]
    one_by_one = np.stack([d.extract(image, range_resolution=0.1) for image in images])
    for threads in (1, 2):
        np.testing.assert_array_equal(
            d.extract_many(images, range_resolution=0.1, num_threads=threads), one_by_one)
    stack = np.stack(images)  # N x A x R
    np.testing.assert_array_equal(d.extract_many(stack, range_resolution=0.1), one_by_one)
    last_axis = np.ascontiguousarray(np.moveaxis(stack, 0, 2))  # A x R x N
    np.testing.assert_array_equal(
        d.extract_many(last_axis, range_resolution=0.1, scan_axis=2), one_by_one)
    assert d.extract_many([], range_resolution=0.1).shape == (0, 0, 0)


def test_strided_arrays_are_read_right_not_misread():
    d = radarpr.Descriptor("referee")
    wide = synthetic_scan(3, range_bins=2000)
    contiguous = np.ascontiguousarray(wide[:, 100:1300])
    expected = d.extract(contiguous, range_resolution=0.1)
#A slice of columns(rows contiguous, row stride > width) is read in place.
    np.testing.assert_array_equal(d.extract(wide[:, 100:1300], range_resolution=0.1), expected)
#Every other azimuth and a transposed(Fortran - ordered) array are copied once.
    every_other = wide[::2, 100:1300]
    np.testing.assert_array_equal(
        d.extract(every_other, range_resolution=0.1),
        d.extract(np.ascontiguousarray(every_other), range_resolution=0.1))
    fortran = np.asfortranarray(contiguous)
    np.testing.assert_array_equal(d.extract(fortran, range_resolution=0.1), expected)
    reversed_bins = contiguous[:, ::-1]
    np.testing.assert_array_equal(
        d.extract(reversed_bins, range_resolution=0.1),
        d.extract(np.ascontiguousarray(reversed_bins), range_resolution=0.1))


@pytest.mark.parametrize("bad, expected", [
    (np.zeros((400, 3360), dtype=np.float32), "2-D numpy uint8 array.*float32"),
    (np.zeros((400, 3360), dtype=np.int64), "uint8.*int64"),
    (np.zeros((2, 400, 3360), dtype=np.uint8), "2-D.*3-D uint8 array of shape \\(2, 400, 3360\\)"),
    (np.zeros(3360, dtype=np.uint8), "1-D"),
    ([[1, 2], [3, 4]], "got a list"),
    (np.zeros((0, 3360), dtype=np.uint8), "empty"),
])
def test_bad_images_are_value_errors_naming_what_was_expected(bad, expected):
    with pytest.raises(ValueError, match=expected):
        radarpr.Descriptor("referee").extract(bad, range_resolution=0.06)


def test_bad_scan_options_are_value_errors():
    d = radarpr.Descriptor("referee")
    image = synthetic_scan(0, range_bins=500)
    with pytest.raises(ValueError, match="500 range bins match no known sensor"):
        d.extract(image)
    with pytest.raises(ValueError, match="range_resolution.*> 0"):
        d.extract(image, range_resolution=-1.0)
    with pytest.raises(ValueError, match="one angle per image row \\(400\\), got 3"):
        d.extract(image, range_resolution=0.1, azimuths=[0.0, 1.0, 2.0])
    with pytest.raises(ValueError, match="images\\[1\\].*2-D numpy uint8.*float64"):
        d.extract_many([image, image.astype(np.float64)], range_resolution=0.1)
    with pytest.raises(ValueError, match="scan_axis"):
        d.extract_many(np.stack([image]), range_resolution=0.1, scan_axis=1)
    with pytest.raises(ValueError, match="num_threads"):
        d.extract_many([image], range_resolution=0.1, num_threads=-1)
    with pytest.raises(ValueError, match="images\\[1\\] gives a 42x1 value, images\\[0\\] a 6x1"):
        radarpr.Descriptor("referee_r").extract_many(
            [image, synthetic_scan(0, range_bins=3360)], range_resolution=0.1)


def test_distance_matches_the_descriptor_and_checks_its_arrays():
    d = radarpr.Descriptor("referee_r")
    a, b = (d.extract(synthetic_scan(seed), range_resolution=200.0 / 3360.0) for seed in (1, 2))
    assert d.distance(a, a) == pytest.approx(0.0, abs=1e-6)
    assert d.distance(a, b) > 0
    assert d.distance(a, b) == d.distance(a.ravel(), b.ravel())  # D x 1 either way
    with pytest.raises(ValueError, match="b: expected a 1-D or 2-D numpy float32 array.*float64"):
        d.distance(a, b.astype(np.float64))


def test_unknown_descriptors_and_parameters_are_config_errors():
    with pytest.raises(radarpr.ConfigError, match="unknown descriptor 'nope'"):
        radarpr.Descriptor("nope")
    with pytest.raises(radarpr.ConfigError, match="z_q"):
        radarpr.Descriptor("referee_r:z_q=-4")
    assert issubclass(radarpr.ConfigError, ValueError)

def test_every_function_has_a_numpy_style_docstring():
    for function in (radarpr.descriptors, radarpr.read_polar_png, radarpr.Descriptor.extract,
                     radarpr.Descriptor.extract_many, radarpr.Descriptor.distance):
        assert "Returns\n-------" in function.__doc__, function
    assert "Parameters\n----------" in radarpr.Descriptor.__doc__
