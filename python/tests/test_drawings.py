"""Drawings as numpy arrays: the lab's shapes and the spiral, text, image and MNIST skeletons,
CSV curves, resampling, spacing statistics, placement, pen-up travel, prepare_drawing() with
the same targets as `animkit ik`, a picture of a run, and bad input as animkit.Error."""
import csv
import math
import struct
import subprocess

import numpy as np
import pytest

import animkit

LAB = ["circle", "square", "heart", "triangle", "star"]


def write_pgm(path, pixels):
    """A binary PGM (P5) of a (height, width) uint8 array."""
    height, width = pixels.shape
    path.write_bytes(b"P5\n%d %d\n255\n" % (width, height) + pixels.astype(np.uint8).tobytes())
    return path


def ring_image(size=64):
    """Black ring on white paper."""
    y, x = np.mgrid[0:size, 0:size]
    r = np.hypot(x - size / 2, y - size / 2)
    return np.where((r > size * 0.25) & (r < size * 0.35), 0, 255).astype(np.uint8)


def write_mnist(path, images):
    """An MNIST IDX image file (magic 0x00000803, big-endian sizes) of uint8 images."""
    count, rows, cols = images.shape
    path.write_bytes(struct.pack(">IIII", 0x803, count, rows, cols) +
                     images.astype(np.uint8).tobytes())
    return path


def mnist_digits():
    """Two 28x28 'digits', white on black: a vertical bar and a cross."""
    images = np.zeros((2, 28, 28), np.uint8)
    images[0, 4:24, 12:16] = 255
    images[1, 12:16, 4:24] = 255
    images[1, 4:24, 12:16] = 255
    return images


# ---- shapes ---------------------------------------------------------------------------------

def test_lab_shapes_are_the_labs():
    assert animkit.lab_shape_names() == LAB
    assert animkit.builtin_shape_names() == LAB + ["spiral"]
    counts = {name: len(animkit.lab_shape(name)) for name in LAB}
    assert counts == {"circle": 150, "square": 150, "heart": 150, "triangle": 150, "star": 400}
    for name in LAB:
        points = animkit.lab_shape(name)
        assert points.shape[1] == 3 and points.dtype == np.float64
        np.testing.assert_array_equal(points[:, 1], 0.0)
    circle = animkit.lab_shape("circle")
    np.testing.assert_allclose(np.hypot(circle[:, 0], circle[:, 2]), 0.6, rtol=1e-12)
    np.testing.assert_array_equal(animkit.builtin_shape("star"), animkit.lab_shape("star"))


def test_spiral_is_uneven_until_resampled():
    spiral = animkit.builtin_shape("spiral")
    stroke = spiral[:, [0, 2]]
    assert animkit.spacing_stats(stroke).cv > 0.8
    even = animkit.resample(stroke, spacing=0.02)
    assert animkit.spacing_stats(even).cv < 0.05
    assert animkit.stroke_length(even) == pytest.approx(animkit.stroke_length(stroke), rel=1e-2)


@pytest.mark.parametrize("call, message", [
    (lambda: animkit.lab_shape("spiral"),
     "unknown lab shape 'spiral' (expected one of: circle, square, heart, triangle, star)"),
    (lambda: animkit.lab_shape("Star"), "unknown lab shape 'Star'"),
    (lambda: animkit.builtin_shape("hexagon"),
     "unknown shape 'hexagon' (expected one of: circle, square, heart, triangle, star, spiral)"),
])
def test_unknown_shapes_raise(call, message):
    with pytest.raises(animkit.Error) as raised:
        call()
    assert str(raised.value).startswith(message)


# ---- text -----------------------------------------------------------------------------------

def test_text_outlines_are_closed_strokes_and_centre_lines_are_fewer():
    outlines = animkit.text_strokes("QD")
    assert len(outlines) == 4  # Q: 2 contours, D: 2
    for stroke in outlines:
        assert stroke.ndim == 2 and stroke.shape[1] == 2
        np.testing.assert_array_equal(stroke[0], stroke[-1])
    points = np.vstack(outlines)
    assert 0.0 < points[:, 1].max() < 1.0  # an em of 1, baseline at 0
    centre = animkit.text_strokes("QD", centerline=True)
    assert len(centre) < len(outlines)
    coarse = animkit.text_strokes("QD", tolerance=0.05)
    assert sum(map(len, coarse)) < sum(map(len, outlines))
    two_lines = np.vstack(animkit.text_strokes("A\nA"))
    assert two_lines[:, 1].min() < -0.5  # the second line is below the first


@pytest.mark.parametrize("kwargs, message", [
    ({"text": ""}, "the text is empty"),
    ({"text": "x", "font": "/no/such/font.ttf"}, "font /no/such/font.ttf: no such file"),
    ({"text": "x", "tolerance": 0.0}, "text tolerance must be in (0, 0.1] of the em, got 0"),
    ({"text": "x", "tolerance": 0.5}, "text tolerance must be in (0, 0.1] of the em, got 0.5"),
    ({"text": "   "}, ""),
])
def test_bad_text_raises(kwargs, message):
    with pytest.raises(animkit.Error) as raised:
        animkit.text_strokes(**kwargs)
    assert str(raised.value).startswith(message)


def test_a_folder_is_not_a_font(tmp_path):
    with pytest.raises(animkit.Error, match="is a folder, not a file"):
        animkit.text_strokes("x", font=tmp_path)


# ---- images ---------------------------------------------------------------------------------

def test_image_strokes_from_a_file_and_from_an_array_agree(tmp_path):
    pixels = ring_image()
    path = write_pgm(tmp_path / "ring.pgm", pixels)
    np.testing.assert_array_equal(animkit.read_gray_image(path), pixels)
    from_file = animkit.image_strokes(path)
    from_array = animkit.image_strokes(pixels)
    from_str = animkit.image_strokes(str(path))
    assert len(from_file.strokes) == 1  # a ring is one closed stroke
    for other in (from_array, from_str):
        assert len(other.strokes) == len(from_file.strokes)
        np.testing.assert_array_equal(other.strokes[0], from_file.strokes[0])
    ring = from_file.strokes[0]
    np.testing.assert_array_equal(ring[0], ring[-1])
    radius = np.hypot(ring[:, 0] - 32, ring[:, 1] + 32)  # y is up: row r is at y = -r
    np.testing.assert_allclose(radius, 19.2, atol=2.0)
    assert from_file.threshold == 0  # Otsu's split of black (0) and white (255)
    skeleton = from_file.skeleton
    assert skeleton.shape == (64, 64) and skeleton.dtype == np.uint8
    assert set(np.unique(skeleton)) == {0, 1}
    extent = from_file.extent
    assert extent.shape == (2, 2) and (extent[1] > extent[0]).all()
    assert repr(from_file).startswith("ImageStrokes(strokes=1, threshold=")


def test_image_options_are_used():
    pixels = ring_image()
    dark = animkit.image_strokes(pixels, threshold=128, polarity="dark")
    assert dark.threshold == 128 and len(dark.strokes) == 1
    # Light ink: the paper outside and the disc inside are the ink, the ring is the gap.
    light = animkit.image_strokes(pixels, threshold=128, polarity="light")
    assert not np.array_equal(light.skeleton, dark.skeleton)
    guo = animkit.image_strokes(pixels, thinning="guo-hall")
    assert len(guo.strokes) == 1
    rough = animkit.image_strokes(pixels, smoothing_radius=0)
    assert not np.array_equal(rough.strokes[0], dark.strokes[0])


@pytest.mark.parametrize("image, kwargs, message", [
    (np.full((8, 8), 7), {}, "the image is a single shade (gray 7): nothing to draw"),
    (np.zeros((4, 4, 3)), {}, "image must be a non-empty 2-D array of gray levels"),
    (np.zeros((0, 5)), {}, "image must be a non-empty 2-D array of gray levels"),
    (np.array([[0, 300], [0, 0]]), {}, "image pixel 1 is 300, not a gray level 0..255"),
    (np.array([[0, np.nan], [0, 0]]), {}, "image pixel 1 is nan, not a gray level 0..255"),
    (np.array([[0, 0.5], [0, 0]]), {}, "image pixel 1 is 0.5, not a gray level 0..255"),
    (np.zeros((5000, 2)), {}, "image is 2x5000 pixels, larger than 4096 on a side"),
    ("/no/such/picture.png", {}, "/no/such/picture.png: no such file"),
    (ring_image(), {"threshold": 255}, "threshold must be a gray level from 0 to 254, got 255"),
    (ring_image(), {"thinning": "skeletonize"},
     "unknown thinning 'skeletonize' (expected zhang-suen or guo-hall)"),
    (ring_image(), {"polarity": "bright"},
     "unknown polarity 'bright' (expected automatic, dark or light)"),
    (ring_image(), {"speck_fraction": 1.0}, "speck fraction must be in [0, 1)"),
    (ring_image(), {"smoothing_radius": -1}, "smoothing radius must be >= 0"),
])
def test_bad_images_raise(image, kwargs, message):
    with pytest.raises(animkit.Error) as raised:
        animkit.image_strokes(image, **kwargs)
    assert str(raised.value).startswith(message)


def test_unreadable_image_files_raise(tmp_path):
    with pytest.raises(animkit.Error, match="no such file"):
        animkit.read_gray_image(tmp_path / "missing.png")
    junk = tmp_path / "junk.png"
    junk.write_bytes(b"not a picture at all")
    with pytest.raises(animkit.Error, match="junk.png"):
        animkit.read_gray_image(junk)
    with pytest.raises(animkit.Error, match="junk.png"):
        animkit.image_strokes(junk)


def test_mnist_images_and_their_strokes(tmp_path):
    path = write_mnist(tmp_path / "digits.idx", mnist_digits())
    np.testing.assert_array_equal(animkit.read_mnist_image(path, 1), mnist_digits()[1])
    np.testing.assert_array_equal(animkit.read_mnist_image(path), mnist_digits()[0])
    bar = animkit.image_strokes(animkit.read_mnist_image(path, 0))
    assert len(bar.strokes) == 1
    prepared = animkit.prepare_drawing(mnist=path, index=1)
    assert prepared.name == "mnist digits.idx #1"
    assert prepared.stroke_count == 2  # a cross: two strokes, travel between
    assert not prepared.pen_down.all()
    with pytest.raises(animkit.Error, match="index"):
        animkit.read_mnist_image(path, 2)
    with pytest.raises(animkit.Error, match="index"):
        animkit.read_mnist_image(path, -1)
    bad = tmp_path / "bad.idx"
    bad.write_bytes(struct.pack(">IIII", 0x801, 1, 28, 28) + bytes(784))
    with pytest.raises(animkit.Error, match="bad.idx"):
        animkit.read_mnist_image(bad, 0)
    short = write_mnist(tmp_path / "short.idx", mnist_digits())
    short.write_bytes(short.read_bytes()[:100])
    with pytest.raises(animkit.Error, match="short.idx"):
        animkit.read_mnist_image(short, 1)


# ---- curves ---------------------------------------------------------------------------------

def test_curves_from_csv_text_and_files(tmp_path):
    text = "# a zigzag, then a dot\n0,0\n1,0\n1,1\n\n2,2\n"
    strokes = animkit.parse_curve_csv(text)
    assert [s.shape for s in strokes] == [(3, 2), (1, 2)]
    np.testing.assert_array_equal(strokes[0], [[0, 0], [1, 0], [1, -1]])  # v = -z
    path = tmp_path / "zigzag.csv"
    path.write_text(text)
    from_file = animkit.read_curve_csv(path)
    for a, b in zip(from_file, strokes):
        np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("text, message", [
    ("0,0\nzero,1\n", "mine line 2: expected two finite numbers x,z, got 'zero,1'"),
    ("0,0\n1,nan\n", "mine line 2: the point is not finite, got '1,nan'"),
    ("# nothing\n\n", "mine: no points"),
    ("0,0\n1\n", "mine line 2"),
])
def test_bad_curves_raise(text, message):
    with pytest.raises(animkit.Error) as raised:
        animkit.parse_curve_csv(text, "mine")
    assert str(raised.value).startswith(message)


def test_missing_curve_file_raises(tmp_path):
    with pytest.raises(animkit.Error, match="no such file"):
        animkit.read_curve_csv(tmp_path / "none.csv")


# ---- resampling and statistics --------------------------------------------------------------

def test_spacing_stats_by_hand():
    s = animkit.spacing_stats([[0, 0], [1, 0], [3, 0]])
    assert (s.segments, s.mean, s.min, s.max) == (2, 1.5, 1.0, 2.0)
    assert s.cv == pytest.approx(0.5 / 1.5)
    both = animkit.spacing_stats([np.array([[0, 0], [1, 0]]), np.array([[5, 5], [5, 7]])])
    assert both.segments == 2 and both.mean == 1.5  # the gap between strokes is no segment
    assert repr(s) == "SpacingStats(segments=2, mean=1.5, min=1.0, max=2.0, cv=0.3333333333333333)"


def test_resample_keeps_corners_and_evens_the_spacing():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]], float)
    even = animkit.resample(square, spacing=0.1)
    assert isinstance(even, np.ndarray) and even.shape == (41, 2)
    for corner in square:
        assert np.min(np.linalg.norm(even - corner, axis=1)) == 0.0
    stats = animkit.spacing_stats(even)
    assert stats.max <= 0.1 + 1e-12 and stats.cv < 1e-9
    rounded = animkit.resample(square, spacing=0.1, corner_angle=math.pi)
    assert len(rounded) < len(even) + 1
    as_list = animkit.resample([square, square[:2] + 3], spacing=0.25)
    assert isinstance(as_list, list) and [len(s) for s in as_list] == [17, 5]
    ragged = animkit.resample([square, square[:3]], spacing=0.5)
    assert [len(s) for s in ragged] == [9, 5]
    as_nested_list = animkit.resample(square.tolist(), spacing=0.1)
    np.testing.assert_array_equal(as_nested_list, even)


@pytest.mark.parametrize("strokes, kwargs, message", [
    ([[0, 0], [1, 1]], {"spacing": 0}, "spacing must be a positive finite number, got 0"),
    ([[0, 0], [1, 1]], {"spacing": np.nan}, "spacing must be a positive finite number, got nan"),
    ([[0, 0], [1, 1]], {"corner_angle": 0}, "corner angle must be in (0, pi] radians, got 0"),
    ([[0, 0], [1, 1]], {"corner_angle": 4}, "corner angle must be in (0, pi] radians, got 4"),
    ([[0, 0], [np.inf, 1]], {}, "stroke point 1 has a non-finite coordinate"),
    ([[[0, 0], [1, 1]], [[0, np.nan], [1, 1]]], {}, "stroke 1 point 0 has a non-finite"),
    ([[0, 0, 0], [1, 1, 1]], {}, "stroke must be an array of shape (n, 2), got shape (2, 3)"),
    ([[0, 0], [1e9, 0]], {"spacing": 1e-3}, "spacing 0.001 would make about 1e+12 points"),
    ("strokes", {}, "stroke must be a list of (k, 2) arrays, got str"),
    (7, {}, "stroke must be a list of (k, 2) arrays, got int"),
])
def test_bad_resampling_raises(strokes, kwargs, message):
    with pytest.raises(animkit.Error) as raised:
        animkit.resample(strokes, **kwargs)
    assert str(raised.value).startswith(message)


# ---- placement and travel -------------------------------------------------------------------

def test_fit_to_box_scales_centres_and_flips_v():
    square = np.array([[0, 0], [2, 0], [2, 2], [0, 2], [0, 0]], float)
    box = animkit.DrawingBox(center_x=1.0, center_z=2.0, half_extent=0.5)
    assert repr(box) == "DrawingBox(center_x=1.0, center_z=2.0, half_extent=0.5)"
    (placed,) = animkit.fit_to_box([square], box)
    np.testing.assert_allclose(placed, [[0.5, 2.5], [1.5, 2.5], [1.5, 1.5], [0.5, 1.5],
                                        [0.5, 2.5]], atol=1e-15)
    (framed,) = animkit.fit_to_box([square], box, frame=[[0, 0], [4, 4]])
    np.testing.assert_allclose(framed[2], [1.0, 2.0], atol=1e-15)  # the frame's centre
    (default,) = animkit.fit_to_box(square)
    assert np.abs(default).max() == pytest.approx(0.6)
    box.half_extent = 2.0
    assert box.half_extent == 2.0


def test_reachable_box_of_the_lab_arm():
    arm = animkit.Chain.lab_arm()
    box = animkit.reachable_box(arm.root_position, arm.reach)
    assert (box.center_x, box.center_z) == (0.0, 0.0)
    # Corners at 0.7 of the radius where y = 0 leaves the reach: sqrt(2.6^2 - 1.7^2).
    assert box.half_extent * math.sqrt(2) == pytest.approx(0.7 * math.sqrt(2.6**2 - 1.7**2))
    with pytest.raises(animkit.Error, match="reach > 0"):
        animkit.reachable_box(arm.root_position, -1.0)
    with pytest.raises(animkit.Error, match="fill in"):
        animkit.reachable_box(arm.root_position, 2.6, fill=1.5)


@pytest.mark.parametrize("strokes, box, message", [
    ([], None, "the drawing has no points"),
    ([np.zeros((0, 2))], None, "the drawing has no points"),
    ([[[0, 0], [1, 1]]], animkit.DrawingBox(half_extent=0),
     "the drawing box must have a finite centre and a positive half extent"),
    ([[[0, 0], [1, 1]]], animkit.DrawingBox(center_x=np.nan),
     "the drawing box must have a finite centre"),
])
def test_bad_placement_raises(strokes, box, message):
    with pytest.raises(animkit.Error) as raised:
        animkit.fit_to_box(strokes, box)
    assert str(raised.value).startswith(message)


def test_to_trajectory_lifts_the_pen_between_strokes():
    strokes = [np.array([[0, 0], [0.1, 0]]), np.array([[0.3, 0], [0.4, 0]])]
    t = animkit.to_trajectory(strokes)
    targets, pen = t.targets, t.pen_down
    assert len(t) == len(targets) == len(pen)
    assert pen.dtype == bool
    assert pen[:2].all() and pen[-2:].all() and not pen[2:-2].any()
    np.testing.assert_array_equal(targets[pen][:, 1], 0.0)
    np.testing.assert_allclose(targets[~pen][:, 1], 0.05)  # the default pen lift
    np.testing.assert_allclose(np.diff(targets[2:-2, 0]), 0.02)  # the travel spacing
    low = animkit.to_trajectory(strokes, pen_lift=0.0, spacing=0.05)
    assert len(low) < len(t)
    drawn = t.pen_down_strokes()
    assert len(drawn) == 2
    np.testing.assert_array_equal(drawn[1], strokes[1])
    assert repr(t) == f"Trajectory(targets={len(t)}, pen_up={int((~pen).sum())})"
    with pytest.raises(animkit.Error, match="pen lift must be a finite number >= 0, got -1"):
        animkit.to_trajectory(strokes, pen_lift=-1)
    with pytest.raises(animkit.Error, match="travel spacing must be a positive finite number"):
        animkit.to_trajectory(strokes, spacing=0)
    with pytest.raises(animkit.Error, match="the drawing has no points"):
        animkit.to_trajectory([])


def test_trajectory_from_arrays():
    t = animkit.Trajectory(np.zeros((3, 3)))
    assert t.pen_down.all() and len(t) == 3
    t = animkit.Trajectory(np.zeros((3, 3)), [1, 0, 1])
    np.testing.assert_array_equal(t.pen_down, [True, False, True])
    with pytest.raises(animkit.Error, match=r"pen_down must have one flag per target \(3\)"):
        animkit.Trajectory(np.zeros((3, 3)), [1, 0])
    with pytest.raises(animkit.Error, match="pen_down 1 is not a finite number"):
        animkit.Trajectory(np.zeros((3, 3)), [1, np.nan, 1])
    with pytest.raises(animkit.Error, match=r"targets must be an array of shape \(n, 3\)"):
        animkit.Trajectory(np.zeros((3, 2)))


# ---- prepare_drawing, as the CLI does it -----------------------------------------------------

def test_prepare_drawing_sources(tmp_path):
    circle = animkit.prepare_drawing()
    assert circle.name == "circle" and len(circle.targets) == 150
    np.testing.assert_array_equal(circle.targets, animkit.lab_shape("circle"))
    assert circle.stroke_count == 1 and circle.pen_down.all()
    text = animkit.prepare_drawing(text="QD")
    assert text.name == "text QD" and text.stroke_count == 4
    assert text.spacing_after.mean == pytest.approx(0.01, rel=0.05)
    assert text.spacing_before.cv > text.spacing_after.cv
    assert repr(text).startswith("PreparedDrawing(name='text QD', targets=")
    image = animkit.prepare_drawing(image=write_pgm(tmp_path / "ring.pgm", ring_image()))
    assert image.name == "image ring.pgm" and image.stroke_count == 1
    curve_file = tmp_path / "c.csv"
    curve_file.write_text("0,0\n1,0\n\n0,1\n1,1\n")
    curve = animkit.prepare_drawing(curve=curve_file)
    assert curve.name == "curve c.csv" and curve.stroke_count == 2
    boxed = animkit.prepare_drawing(curve=curve_file, box=animkit.DrawingBox(center_x=0.5,
                                                                             half_extent=0.1))
    drawn = boxed.targets[boxed.pen_down]
    np.testing.assert_allclose([drawn[:, 0].min(), drawn[:, 0].max()], [0.4, 0.6], atol=1e-12)
    small = animkit.Chain([[0, 1, 0], [0, -0.6, 0], [0, -0.6, 0]])
    near = animkit.prepare_drawing(chain=small, curve=curve_file)
    assert np.abs(near.targets[:, 0]).max() < np.abs(curve.targets[:, 0]).max()
    sparse = animkit.prepare_drawing(shape="star", spacing=0.05)
    assert len(sparse.targets) < 400
    trajectory = animkit.drawing_targets(text="QD")
    np.testing.assert_array_equal(trajectory.targets, text.targets)
    np.testing.assert_array_equal(trajectory.pen_down, text.pen_down)


@pytest.mark.parametrize("kwargs, message", [
    ({"shape": "star", "text": "x"},
     "give one drawing source (shape, text, image, mnist or curve), got shape and text"),
    ({"shape": "hexagon"}, "unknown shape 'hexagon' (expected one of: circle, square"),
    ({"shape": "star", "threshold": 100}, "threshold applies to image and mnist only"),
    ({"text": "x", "thinning": "guo-hall"}, "thinning applies to image and mnist only"),
    ({"shape": "star", "font": "/x.ttf"}, "font applies to text only"),
    ({"shape": "star", "index": 3}, "index applies to mnist only"),
    ({"shape": "star", "box": animkit.DrawingBox()}, "box applies to text, image, mnist and"),
    ({"shape": "star", "spacing": 0.0}, "spacing must be a positive finite number, got 0"),
    ({"shape": "star", "spacing": 1e-9}, "spacing 1e-09 would make about"),
    ({"text": "x", "pen_lift": -1.0}, "pen lift must be a finite number >= 0, got -1"),
    ({"text": "x", "travel_spacing": 0.0}, "travel spacing must be a positive finite number"),
    ({"text": "x", "box": animkit.DrawingBox(half_extent=-1)}, "the drawing box must have"),
    ({"image": "/no/such.png"}, "/no/such.png: no such file"),
    ({"mnist": "/no/such.idx"}, "/no/such.idx: no such file"),
    ({"curve": "/no/such.csv"}, "/no/such.csv: no such file"),
    ({"text": ""}, "the text is empty"),
])
def test_bad_drawing_requests_raise(kwargs, message):
    with pytest.raises(animkit.Error) as raised:
        animkit.prepare_drawing(**kwargs)
    assert str(raised.value).startswith(message)
    with pytest.raises(animkit.Error):
        animkit.drawing_targets(**kwargs)


def test_sources_are_keyword_only():
    with pytest.raises(TypeError):
        animkit.prepare_drawing(None, "star")


def cli_targets(cli, tmp_path, source):
    out = tmp_path / "out"
    subprocess.run([str(cli), "ik", *source, "--out", str(out), "--no-picture"], check=True,
                   capture_output=True)
    with open(out / "path.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    targets = np.array([[float(r[f"target_{a}"]) for a in "xyz"] for r in rows])
    return targets, np.array([r["pen_down"] == "1" for r in rows])


@pytest.mark.parametrize("kind", ["image", "mnist", "curve", "text"])
def test_prepared_targets_equal_the_clis_bit_for_bit(cli, tmp_path, kind):
    if kind == "image":
        source, kwargs = ["--image", str(write_pgm(tmp_path / "r.pgm", ring_image()))], {}
        kwargs = {"image": source[1]}
    elif kind == "mnist":
        path = write_mnist(tmp_path / "d.idx", mnist_digits())
        source = ["--mnist", str(path), "--index", "1", "--thinning", "guo-hall"]
        kwargs = {"mnist": path, "index": 1, "thinning": "guo-hall"}
    elif kind == "curve":
        path = tmp_path / "c.csv"
        path.write_text("0,0\n3,1\n2,2\n\n5,5\n4,0\n")
        source = ["--curve", str(path), "--spacing", "0.03", "--box", "0.2,0.1,0.5"]
        kwargs = {"curve": path, "spacing": 0.03,
                  "box": animkit.DrawingBox(center_x=0.2, center_z=0.1, half_extent=0.5)}
    else:
        source = ["--text", "a", "--centerline"]
        kwargs = {"text": "a", "centerline": True}
    targets, pen = cli_targets(cli, tmp_path, source)
    prepared = animkit.prepare_drawing(**kwargs)
    np.testing.assert_array_equal(prepared.targets, targets)
    np.testing.assert_array_equal(prepared.pen_down, pen)


# ---- pictures -------------------------------------------------------------------------------

def read_png_size(path):
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", data[16:24])


def test_render_png_of_a_run(tmp_path):
    arm = animkit.Chain.lab_arm()
    run = animkit.run_drawing(arm, animkit.drawing_targets(text="QD"), solver="fabrik")
    path = tmp_path / "drawing.png"
    try:
        animkit.render_png(path, run)
    except animkit.Error as error:
        if "cannot render pictures" in str(error):
            pytest.skip(f"no OpenGL here: {error}")
        raise
    assert read_png_size(path) == (960, 720)
    pixels = animkit.read_gray_image(path)
    assert pixels.std() > 5  # not a blank picture
    mid = tmp_path / "mid.png"
    animkit.render_png(mid, run, width=320, height=200, frame=100)
    assert read_png_size(mid) == (320, 200)
    with pytest.raises(animkit.Error, match=r"frame 5000 is not a frame of the run \(0 to "):
        animkit.render_png(mid, run, frame=5000)
    with pytest.raises(animkit.Error, match="frame -1 is not a frame"):
        animkit.render_png(mid, run, frame=-1)
    with pytest.raises(animkit.Error):
        animkit.render_png(mid, run, width=0)
    with pytest.raises(animkit.Error):
        animkit.render_png(tmp_path / "no" / "such" / "dir" / "x.png", run)


def test_render_png_of_a_run_takes_the_clis_sizes(tmp_path):
    # 16..8192 pixels per side like the CLI's --picture-size and the cloth's render_png,
    # checked before any OpenGL (so on any machine).
    run = animkit.run_drawing(animkit.Chain.lab_arm(), animkit.lab_shape("star"))
    for width, height in ((8, 720), (960, 15), (8193, 720), (960, 9000)):
        with pytest.raises(animkit.Error, match=f"picture size must be between 16 and 8192 "
                                                f"pixels per side, got {width}x{height}"):
            animkit.render_png(tmp_path / "x.png", run, width=width, height=height)
    assert not (tmp_path / "x.png").exists()


def test_render_png_is_the_clis_drawing_png(cli, tmp_path):
    # The same scene code, camera and renderer as `animkit ik --out`: the same pixels.
    out = tmp_path / "out"
    subprocess.run([str(cli), "ik", "--shape", "heart", "--solver", "ccd", "--out", str(out)],
                   check=True, capture_output=True)
    run = animkit.run_drawing(animkit.Chain.lab_arm(), animkit.drawing_targets(shape="heart"))
    try:
        animkit.render_png(tmp_path / "py.png", run)
    except animkit.Error as error:
        if "cannot render pictures" in str(error):
            pytest.skip(f"no OpenGL here: {error}")
        raise
    np.testing.assert_array_equal(animkit.read_gray_image(tmp_path / "py.png"),
                                  animkit.read_gray_image(out / "drawing.png"))
