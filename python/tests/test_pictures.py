"""render_png and render_image: the CLI's final.png of a cloth run, from Python."""
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import animkit

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def png_size(path):
    data = path.read_bytes()
    assert data[:8] == PNG_SIGNATURE
    assert data[12:16] == b"IHDR"
    return int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")


def drape(frames):
    sim = animkit.ClothSimulator(animkit.ClothScene.builtin("drape-sphere"))
    sim.run(frames=frames)
    return sim


def test_render_png_is_the_clis_final_png(cli, tmp_path):
    sim = drape(5)
    path = tmp_path / "python.png"
    animkit.render_png(path, sim)
    assert png_size(path) == (960, 720)
    out = tmp_path / "cli"
    subprocess.run([str(cli), "cloth", "--scene", "drape-sphere", "--frames", "5", "--out",
                    str(out)], check=True, capture_output=True)
    assert path.read_bytes() == (out / "final.png").read_bytes()


def test_render_image_is_a_picture_of_the_cloth(tmp_path):
    sim = animkit.ClothSimulator(animkit.ClothScene())
    image = animkit.render_image(sim, 320, 240)
    assert image.shape == (240, 320, 4) and image.dtype == np.uint8
    colours = np.unique(image[..., :3].reshape(-1, 3), axis=0)
    assert len(colours) > 50  # not blank: cloth, floor grid, shading
    assert (image[..., 3] == 255).all()
    sim.run(frames=30)
    moved = animkit.render_image(sim, 320, 240)
    assert np.abs(moved.astype(int) - image.astype(int)).sum() > 0  # the cloth swung
    path = tmp_path / "small.png"
    animkit.render_png(str(path), sim, width=320, height=240)
    assert png_size(path) == (320, 240)


def test_render_errors(tmp_path):
    sim = animkit.ClothSimulator(animkit.ClothScene())
    with pytest.raises(animkit.Error, match="between 16 and 8192 pixels per side, got 2x2"):
        animkit.render_png(tmp_path / "tiny.png", sim, width=2, height=2)
    with pytest.raises(animkit.Error, match="got 960x9000"):
        animkit.render_image(sim, 960, 9000)
    with pytest.raises(animkit.Error):
        animkit.render_image(sim, 0, 100)
    with pytest.raises(animkit.Error):
        animkit.render_png(tmp_path / "no" / "such" / "folder" / "x.png", sim)
    assert not (tmp_path / "tiny.png").exists()
    with pytest.raises(TypeError):
        animkit.render_png(tmp_path / "x.png", "not a simulator")


def test_no_opengl_is_an_error_and_writes_nothing(tmp_path):
    # As the CLI's test does: no display and no EGL vendor, so no context can be made.
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    env.pop("WAYLAND_DISPLAY", None)
    env["__EGL_VENDOR_LIBRARY_FILENAMES"] = "/nonexistent.json"
    script = textwrap.dedent(f"""
        import animkit
        sim = animkit.ClothSimulator(animkit.ClothScene())
        try:
            animkit.render_png({str(tmp_path / "x.png")!r}, sim)
        except animkit.Error as error:
            print("ERROR:", error)
    """)
    result = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True,
                            text=True, check=True)
    assert result.stdout.startswith("ERROR: cannot render pictures: no OpenGL 3.3 context ("), \
        result.stdout + result.stderr
    assert not (tmp_path / "x.png").exists()


def test_pictures_from_two_threads_at_once(tmp_path, run_watched):
    # A worker renders drawing pictures while this thread renders cloth pictures on each of
    # its turns, which it gets only because the drawing's render_png lets go of the GIL (see
    # run_watched in conftest.py). The module lets one renderer work at a time (GLFW is not
    # thread-safe), this thread waiting for it without the GIL; every picture has the bits of
    # one rendered alone.
    run = animkit.run_drawing(animkit.Chain.lab_arm(), animkit.lab_shape("heart"))
    sim = drape(5)
    try:
        animkit.render_png(tmp_path / "alone.png", run, width=320, height=240)
    except animkit.Error as error:
        if "cannot render pictures" in str(error):
            pytest.skip(f"no OpenGL here: {error}")
        raise
    cloth_alone = animkit.render_image(sim, 320, 240)
    paths = [tmp_path / f"drawing{i}.png" for i in range(6)]

    def draw_all():
        for path in paths:
            animkit.render_png(path, run, width=320, height=240)

    turns, _, images = run_watched(draw_all, each_turn=lambda: animkit.render_image(sim, 320, 240))
    assert turns > 0, "this thread never ran while the worker was inside render_png"
    alone = (tmp_path / "alone.png").read_bytes()
    for path in paths:
        assert path.read_bytes() == alone
    for image in images:
        np.testing.assert_array_equal(image, cloth_alone)
