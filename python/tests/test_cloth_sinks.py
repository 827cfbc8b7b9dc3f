"""The library's frame sinks from Python: ClothSimulator.run(sinks=[...]) writes a point cache,
OBJ meshes and a glTF file whole (or nothing for a run that diverged or was stopped), a callable
is a sink too, and write_glb writes a skeleton's motion."""
import json
import struct

import numpy as np
import pytest

import animkit


def glb_json(path):
    """The JSON chunk of a .glb."""
    data = path.read_bytes()
    magic, version, length = struct.unpack("<4sII", data[:12])
    assert (magic, version, length) == (b"glTF", 2, len(data))
    chunk_length, chunk_type = struct.unpack("<I4s", data[12:20])
    assert chunk_type == b"JSON"
    return json.loads(data[20:20 + chunk_length])


def read_pc2(path):
    data = path.read_bytes()
    _, _, points, start, _, samples = struct.unpack("<12siiffi", data[:32])
    return start, np.frombuffer(data[32:], dtype="<f4").reshape(samples, points, 3)


def small_drape(frames=4):
    drape = animkit.ClothScene.builtin("spinning-sphere")
    drape.frames = frames
    return drape


def test_the_sinks_write_every_frame_and_a_callable_sees_each(tmp_path):
    sim = animkit.ClothSimulator(small_drape())
    start = np.array(sim.positions)
    seen = []
    reports = sim.run(sinks=[animkit.PointCacheSink(tmp_path), animkit.ObjSink(tmp_path),
                             animkit.GltfSink(tmp_path / "cloth.glb"),
                             lambda frame, report: seen.append(frame)])
    assert seen == [1, 2, 3, 4] and len(reports) == 4
    _, frames = read_pc2(tmp_path / "cloth.pc2")
    assert frames.shape == (5, len(start), 3)
    np.testing.assert_allclose(frames[0], start, atol=1e-6)
    np.testing.assert_allclose(frames[-1], sim.positions, atol=1e-6)
    assert (tmp_path / "colliders.pc2").exists()  # the ball turns
    assert (tmp_path / "cloth.obj").exists() and (tmp_path / "colliders.obj").exists()
    gltf = glb_json(tmp_path / "cloth.glb")
    assert len(gltf["meshes"][0]["primitives"][0]["targets"]) == 4


def test_a_point_cache_in_another_space(tmp_path):
    sim = animkit.ClothSimulator(small_drape(2))
    transform = np.diag([2.0, 2.0, 2.0, 1.0])
    transform[:3, 3] = [1.0, 0.0, -1.0]
    sink = animkit.PointCacheSink(tmp_path, file="moved.pc2", colliders=False,
                                  transform=transform, start_frame=7)
    sim.run(sinks=[sink])
    start, frames = read_pc2(tmp_path / "moved.pc2")
    assert start == 7.0
    np.testing.assert_allclose(frames[-1], 2.0 * np.asarray(sim.positions) + [1.0, 0.0, -1.0],
                               atol=1e-5)
    assert not (tmp_path / "colliders.pc2").exists()


def test_a_stopped_or_diverged_run_leaves_no_files(tmp_path):
    sim = animkit.ClothSimulator(small_drape(10))
    reports = sim.run(sinks=[animkit.GltfSink(tmp_path / "cloth.glb"),
                             animkit.PointCacheSink(tmp_path)],
                      callback=lambda frame, report: frame < 2)
    assert len(reports) == 2
    assert sorted(p.name for p in tmp_path.iterdir()) == []

    stiff = animkit.ClothScene(cloth=animkit.GridCloth(cells=6, stiffness=1e4),
                               integrator=animkit.ExplicitEulerSettings(), substeps=1,
                               dt=1 / 30, frames=600)
    with pytest.raises(animkit.Error, match="diverged"):
        animkit.ClothSimulator(stiff).run(sinks=[animkit.PointCacheSink(tmp_path)])
    assert sorted(p.name for p in tmp_path.iterdir()) == []


def test_bad_sinks_are_refused(tmp_path):
    sim = animkit.ClothSimulator(small_drape(2))
    with pytest.raises(animkit.Error, match="sinks must be animkit sinks .* got int"):
        sim.run(sinks=[3])
    with pytest.raises(animkit.Error, match="transform must be a 4 x 4"):
        animkit.PointCacheSink(tmp_path, transform=np.eye(3))
    with pytest.raises(animkit.Error, match="last row"):
        animkit.PointCacheSink(tmp_path, transform=2 * np.eye(4))
    with pytest.raises(animkit.Error, match="cannot"):
        sim.run(sinks=[animkit.PointCacheSink(tmp_path / "missing" / "deeper")])
    assert sim.steps_taken == 0


def test_write_glb_writes_a_skeleton_in_metres(tmp_path, data_dir):
    clip = animkit.read_bvh(data_dir / "cmu" / "131_01.bvh", scale=0.056444)
    animkit.write_glb(tmp_path / "walk.glb", clip)
    gltf = glb_json(tmp_path / "walk.glb")
    assert [n["name"] for n in gltf["nodes"][:2]] == ["Hips", "LHipJoint"]
    assert len(gltf["skins"][0]["joints"]) == clip.joint_count
    with pytest.raises(animkit.Error, match="metres per unit"):
        animkit.write_glb(tmp_path / "bad.glb", clip, metres_per_unit=0)
    assert not (tmp_path / "bad.glb").exists()


def test_sinks_from_a_generator_twice_the_same_and_reused(tmp_path):
    sim = animkit.ClothSimulator(small_drape(2))
    # A generator's items are held for the whole run.
    sim.run(sinks=(animkit.GltfSink(tmp_path / f"{k}.glb") for k in range(2)))
    assert (tmp_path / "0.glb").exists() and (tmp_path / "1.glb").exists()
    cache = animkit.PointCacheSink(tmp_path / "again")
    (tmp_path / "again").mkdir()
    with pytest.raises(animkit.Error, match="the same sink is in sinks twice"):
        sim.run(sinks=[cache, cache])
    # A run the callback stops drops the sink's temporaries at once, even while the sink is
    # kept; the sink then serves the next run whole.
    sim.run(sinks=[cache], callback=lambda frame, report: False)
    assert list((tmp_path / "again").iterdir()) == []
    sim.run(frames=2, sinks=[cache])
    assert sorted(p.name for p in (tmp_path / "again").iterdir()) == ["cloth.pc2",
                                                                     "colliders.pc2"]
