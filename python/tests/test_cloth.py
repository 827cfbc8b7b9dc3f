"""The cloth bindings: descriptions (materials, sheets, colliders, settings, scenes), the
simulator and its reports, and animkit.Error for every kind of bad argument."""
import json
import math

import numpy as np
import pytest

import animkit


# ---- materials and sheets ----

def test_material_presets_and_repr():
    names = animkit.material_names()
    assert names == ["cotton", "silk", "denim", "leather", "rubber"]
    cotton = animkit.material("cotton")
    assert cotton.density > 0 and cotton.stretch > cotton.shear > 0
    assert repr(cotton).startswith("Material(density=")
    custom = animkit.Material(density=0.2, stretch=500, shear=20)
    assert (custom.density, custom.stretch, custom.shear) == (0.2, 500, 20)
    assert custom.bending == animkit.Material().bending  # the library's default


def test_material_errors():
    with pytest.raises(animkit.Error, match="unknown material 'wool'.*cotton"):
        animkit.material("wool")
    with pytest.raises(animkit.Error, match="density"):
        animkit.Material(density=math.nan)
    with pytest.raises(animkit.Error, match="shear"):
        animkit.Material(stretch=10, shear=20)


def test_grid_cloth_defaults_are_the_labs():
    grid = animkit.GridCloth()
    assert (grid.cells, grid.size, grid.height, grid.mass) == (10, 2.0, 1.5, 1.0)
    assert (grid.stiffness, grid.damping, grid.gravity, grid.pins) == (100.0, 0.2, 0.3, "corners")
    assert grid.material is None
    np.testing.assert_array_equal(grid.rotation, [1, 0, 0, 0])
    np.testing.assert_array_equal(grid.offset, [0, 0, 0])
    assert repr(grid).startswith("GridCloth(cells=10, size=2.0, height=1.5")
    # A material makes the sheet physical: SI gravity unless given.
    assert animkit.GridCloth(material=animkit.material("silk")).gravity == 9.81
    assert animkit.GridCloth(material=animkit.material("silk"), gravity=1.0).gravity == 1.0


def test_grid_cloth_errors():
    with pytest.raises(animkit.Error, match="unknown pins 'all'.*corners, edge, none"):
        animkit.GridCloth(pins="all")
    with pytest.raises(animkit.Error):
        animkit.GridCloth(cells=0)
    with pytest.raises(animkit.Error):
        animkit.GridCloth(cells=100000)
    with pytest.raises(animkit.Error):
        animkit.GridCloth(mass=math.nan)
    with pytest.raises(animkit.Error):
        animkit.GridCloth(size=-1)
    with pytest.raises(animkit.Error, match="rotation"):
        animkit.GridCloth(rotation=(1, 2))
    with pytest.raises(animkit.Error):
        animkit.GridCloth(rotation=(2, 0, 0, 0))  # not a unit quaternion
    with pytest.raises(TypeError):
        animkit.GridCloth(cells="ten")


SQUARE_VERTICES = [[0, 1, 0], [1, 1, 0], [1, 1, 1], [0, 1, 1], [0.5, 1, 0.5]]
SQUARE_TRIANGLES = [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]


def test_mesh_cloth():
    mesh = animkit.MeshCloth(SQUARE_VERTICES, SQUARE_TRIANGLES, pins=[0, 1])
    np.testing.assert_array_equal(mesh.vertices, SQUARE_VERTICES)
    np.testing.assert_array_equal(mesh.triangles, SQUARE_TRIANGLES)
    assert mesh.pins == [0, 1] and mesh.gravity == 0.3
    boxed = animkit.MeshCloth(SQUARE_VERTICES, SQUARE_TRIANGLES,
                              pin_boxes=[[-0.1, 0.9, -0.1, 1.1, 1.1, 0.1]])
    np.testing.assert_array_equal(boxed.pin_boxes, [[-0.1, 0.9, -0.1, 1.1, 1.1, 0.1]])
    sim = animkit.ClothSimulator(animkit.ClothScene(cloth=boxed))
    np.testing.assert_array_equal(sim.pinned, [True, True, False, False, False])
    assert "MeshCloth(vertices=<5>" in repr(mesh)


def test_mesh_cloth_errors():
    with pytest.raises(animkit.Error, match="triangles"):
        animkit.MeshCloth(SQUARE_VERTICES, [[0, 1]])
    with pytest.raises(animkit.Error, match="integer"):
        animkit.MeshCloth(SQUARE_VERTICES, [[0, 1, 4.5]])
    with pytest.raises(animkit.Error, match="vertices"):
        animkit.MeshCloth([[0, 1]], SQUARE_TRIANGLES)
    with pytest.raises(animkit.Error):
        animkit.MeshCloth(SQUARE_VERTICES, [[0, 1, 9]])  # index out of range
    with pytest.raises(animkit.Error):
        animkit.MeshCloth(SQUARE_VERTICES, SQUARE_TRIANGLES, pins=[7])
    with pytest.raises(animkit.Error):
        animkit.MeshCloth([[0, 1, 0], [1, 1, 0], [math.nan, 1, 1], [0, 1, 1], [0.5, 1, 0.5]],
                          SQUARE_TRIANGLES)
    with pytest.raises(animkit.Error, match="pin_boxes"):
        animkit.MeshCloth(SQUARE_VERTICES, SQUARE_TRIANGLES, pin_boxes=[[0, 0, 0]])


# ---- colliders, ground, contact, air ----

def test_colliders():
    ball = animkit.Collider.sphere("ball", 0.3, position=(0, 1, 0), velocity=(0, 0, 1))
    assert ball.shape == "sphere" and ball.name == "ball" and ball.moving
    np.testing.assert_array_equal(ball.velocity, [0, 0, 1])
    position, rotation = ball.pose_at(2.0)
    np.testing.assert_allclose(position, [0, 1, 2])
    np.testing.assert_allclose(rotation, [1, 0, 0, 0])
    box = animkit.Collider.box("table", (1, 0.1, 1), friction=0.5)
    assert box.shape == "box" and not box.moving and box.friction == 0.5
    capsule = animkit.Collider.capsule("arm", 0.1, 0.4, angular_velocity=(0, 1, 0))
    assert capsule.shape == "capsule" and capsule.moving
    plane = animkit.Collider.plane("floor")
    assert plane.shape == "plane"
    keyed = animkit.Collider.sphere("k", 0.2, keyframes=[(0, (0, 0, 0)),
                                                         (1, (0, 2, 0), (1, 0, 0, 0))])
    assert len(keyed.keyframes) == 2 and keyed.moving
    np.testing.assert_allclose(keyed.pose_at(0.5)[0], [0, 1, 0])
    tetra = animkit.Collider.mesh("tet", [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
                                  [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    assert tetra.shape == "mesh"
    for c in (ball, box, capsule, plane, keyed, tetra):
        assert repr(c).startswith("Collider." + c.shape + "(")


def test_collider_errors():
    with pytest.raises(animkit.Error, match="ball"):
        animkit.Collider.sphere("ball", -1)
    with pytest.raises(animkit.Error):
        animkit.Collider.sphere("ball", math.nan)
    with pytest.raises(animkit.Error, match="position"):
        animkit.Collider.sphere("ball", position=(0, 1))
    with pytest.raises(animkit.Error):
        animkit.Collider.sphere("ball", rotation=(0.5, 0, 0, 0))
    with pytest.raises(animkit.Error):
        animkit.Collider.sphere("", 1.0)
    with pytest.raises(animkit.Error, match="not both"):
        animkit.Collider.sphere("b", velocity=(1, 0, 0), keyframes=[(0, (0, 0, 0))])
    with pytest.raises(animkit.Error):
        animkit.Collider.sphere("b", keyframes=[(1, (0, 0, 0)), (0.5, (0, 1, 0))])
    with pytest.raises(animkit.Error):
        animkit.Collider.sphere("b", keyframes=[])
    with pytest.raises(animkit.Error, match="keyframes"):
        animkit.Collider.sphere("b", keyframes=[(0,)])
    with pytest.raises(animkit.Error):
        animkit.Collider.box("b", (1, 0, 1))
    with pytest.raises(animkit.Error):
        animkit.Collider.sphere("b", friction=-0.1)
    with pytest.raises(animkit.Error):
        animkit.Collider.mesh("m", [[0, 0, 0]], [[0, 1, 2]])
    with pytest.raises(animkit.Error, match="finite"):
        animkit.Collider.sphere("b").pose_at(math.inf)


def test_ground_contact_air():
    ground = animkit.Ground(height=-0.5, friction=0.1)
    assert (ground.height, ground.friction) == (-0.5, 0.1)
    assert repr(ground) == "Ground(height=-0.5, friction=0.1)"
    contact = animkit.ContactSettings(thickness=0.004)
    assert contact.thickness == 0.004 and contact.self_contact
    assert repr(contact).startswith("ContactSettings(thickness=0.004")
    assert contact.hessian == "projected" and repr(contact).endswith("hessian='projected')")
    contact.hessian = "gauss_newton"
    assert animkit.ContactSettings(hessian="gauss_newton").hessian == contact.hessian
    air = animkit.AirSettings(wind=(1, 0, 0), gust=(0.5, 0, 0))
    np.testing.assert_array_equal(air.wind, [1, 0, 0])
    assert air.density == 1.2
    with pytest.raises(animkit.Error):
        animkit.Ground(height=math.nan)
    with pytest.raises(animkit.Error):
        animkit.Ground(friction=-1)
    with pytest.raises(animkit.Error):
        animkit.ContactSettings(thickness=0)
    with pytest.raises(animkit.Error):
        animkit.ContactSettings(min_separation=1.5)
    with pytest.raises(animkit.Error, match="unknown hessian 'exact'"):
        animkit.ContactSettings(hessian="exact")
    with pytest.raises(animkit.Error, match="unknown hessian"):
        contact.hessian = "exact"
    with pytest.raises(animkit.Error):
        animkit.AirSettings(gust_frequency=0)
    with pytest.raises(animkit.Error):
        animkit.AirSettings(density=math.nan)
    with pytest.raises(animkit.Error, match="wind"):
        animkit.AirSettings(wind=(1, 0))


# ---- integrator settings ----

def test_integrator_settings():
    newton = animkit.NewtonSettings()
    assert newton.linear_solver == "pcg" and newton.tolerance == 1e-6
    assert newton.projection == "when_indefinite" and not newton.record_iterations
    assert repr(newton).startswith("NewtonSettings(linear_solver='pcg', tolerance=1e-06, ")
    newton.linear_solver = "multigrid"
    assert newton.linear_solver == "multigrid"
    newton.projection = "with_terms"
    assert newton.projection == "with_terms"
    assert newton.velocity_tolerance == 0.0
    assert animkit.NewtonSettings(velocity_tolerance=1e-3).velocity_tolerance == 1e-3
    assert repr(animkit.NewtonSettings(velocity_tolerance=1e-3)).endswith(
        ", velocity_tolerance=0.001, linear_forcing=0.0)")
    assert animkit.VbdSettings().max_iterations == 1000
    assert animkit.LocalGlobalSettings(chebyshev=False).chebyshev is False
    assert repr(animkit.ExplicitEulerSettings()) == "ExplicitEulerSettings()"
    names = animkit.integrator_names()
    assert names[0] == "implicit-pcg" and "explicit" in names
    assert isinstance(animkit.integrator_settings("vbd"), animkit.VbdSettings)


def test_integrator_settings_errors():
    with pytest.raises(animkit.Error, match="unknown linear solver 'lu'.*direct, pcg, multigrid"):
        animkit.NewtonSettings(linear_solver="lu")
    with pytest.raises(animkit.Error, match="when_indefinite, always, with_terms"):
        animkit.NewtonSettings(projection="never")
    with pytest.raises(animkit.Error):
        animkit.NewtonSettings(tolerance=2.0)
    with pytest.raises(animkit.Error, match=r"velocity tolerance must be in \[0, 1\), got -1"):
        animkit.NewtonSettings(velocity_tolerance=-1.0)
    with pytest.raises(animkit.Error):
        animkit.NewtonSettings(tolerance=math.nan)
    with pytest.raises(animkit.Error):
        animkit.NewtonSettings(max_iterations=0)
    with pytest.raises(animkit.Error):
        animkit.VbdSettings(chebyshev_rho=1.0)
    with pytest.raises(animkit.Error):
        animkit.LocalGlobalSettings(spectral_radius=0)
    with pytest.raises(animkit.Error, match="unknown integrator 'rk4'"):
        animkit.integrator_settings("rk4")
    newton = animkit.NewtonSettings()
    with pytest.raises(animkit.Error):
        newton.linear_solver = "cholesky"


# ---- scenes ----

def test_scene_defaults_and_builtins():
    scene = animkit.ClothScene()
    assert isinstance(scene.cloth, animkit.GridCloth) and scene.cloth.cells == 10
    assert scene.colliders == [] and scene.ground is None and scene.air is None
    assert scene.dt == pytest.approx(1 / 60) and scene.frames == 300
    assert isinstance(scene.integrator, animkit.NewtonSettings)
    assert scene.integrator_name == "implicit-pcg"
    assert repr(scene).startswith("ClothScene(cloth=GridCloth(cells=10")
    # A material without colliders: the fast settings, not the lab's CG to 1e-6.
    cotton = animkit.ClothScene(cloth=animkit.GridCloth(material=animkit.material("cotton")))
    assert cotton.integrator_name == "implicit-multigrid"
    assert cotton.integrator.velocity_tolerance == 1e-3
    assert cotton.integrator.projection == "with_terms"
    names = animkit.builtin_cloth_scene_names()
    assert names[0] == "lab" and "drape-sphere" in names
    for name in names:
        builtin = animkit.ClothScene.builtin(name)
        assert builtin.frames >= 1
    drape = animkit.ClothScene.builtin("drape-sphere")
    assert drape.colliders and drape.colliders[0].shape == "sphere"
    scene.integrator = "implicit-direct"
    assert scene.integrator.linear_solver == "direct"
    scene.integrator = animkit.VbdSettings(tolerance=1e-3)
    assert scene.integrator_name == "vbd" and scene.integrator.tolerance == 1e-3
    scene.ground = animkit.Ground(height=-1)
    assert scene.ground.height == -1
    contact = scene.contact  # a copy: change it, then assign it back
    contact.thickness = 0.01
    assert scene.contact.thickness != 0.01
    scene.contact = contact
    assert scene.contact.thickness == 0.01


def test_sub_objects_are_copies():
    # One rule for every attribute holding a sub-object: it returns a copy. Changing the copy
    # leaves the scene (or sheet) as it was; assigning it back changes it.
    scene = animkit.ClothScene(
        cloth=animkit.GridCloth(material=animkit.material("cotton")),
        colliders=[animkit.Collider.sphere("ball", 0.3, position=(0, 0.5, 0))],
        ground=animkit.Ground(height=-1.0), air=animkit.AirSettings(density=1.2))
    edits = {
        "cloth": ("cells", 20),
        "integrator": ("tolerance", 0.5),
        "contact": ("thickness", 0.01),
        "ground": ("height", 3.0),
        "air": ("density", 0.5),
    }
    for name, (field, value) in edits.items():
        part = getattr(scene, name)
        setattr(part, field, value)
        assert getattr(getattr(scene, name), field) != value, name
        setattr(scene, name, part)
        assert getattr(getattr(scene, name), field) == value, name
    colliders = scene.colliders
    colliders[0].friction = 0.9
    assert scene.colliders[0].friction == 0.3
    scene.colliders = colliders
    assert scene.colliders[0].friction == 0.9
    for cloth in (scene.cloth, animkit.MeshCloth(
            [[0, 0, 0], [1, 0, 0], [0, 0, 1]], [[0, 1, 2]], material=animkit.material("silk"))):
        material = cloth.material
        material.density = 7.0
        assert cloth.material.density != 7.0
        cloth.material = material
        assert cloth.material.density == 7.0
        cloth.material = None
        assert cloth.material is None
    # A copy outlives what it was copied from (no pointer into the scene's memory).
    first = scene.colliders[0]
    ground, air, contact = scene.ground, scene.air, scene.contact
    scene.colliders = [animkit.Collider.box(f"box{i}") for i in range(50)]
    scene.ground = None
    scene.air = None
    scene.contact = animkit.ContactSettings()
    assert first.name == "ball" and first.friction == 0.9
    assert ground.height == 3.0 and air.density == 0.5 and contact.thickness == 0.01
    # The docstrings say so.
    for cls, names in ((animkit.ClothScene, list(edits) + ["colliders"]),
                       (animkit.GridCloth, ["material"]), (animkit.MeshCloth, ["material"])):
        for name in names:
            assert "a copy" in getattr(cls, name).__doc__ or "copies" in getattr(
                cls, name).__doc__, (cls, name)


def test_scene_errors(tmp_path):
    with pytest.raises(animkit.Error, match="unknown scene 'nope'.*lab"):
        animkit.ClothScene.builtin("nope")
    with pytest.raises(animkit.Error):
        animkit.ClothScene(frames=0)
    with pytest.raises(animkit.Error):
        animkit.ClothScene(dt=math.nan)
    with pytest.raises(animkit.Error):
        animkit.ClothScene(colliders=[animkit.Collider.sphere("a"), animkit.Collider.sphere("a")])
    with pytest.raises(animkit.Error, match="unknown integrator"):
        animkit.ClothScene(integrator="rk4")
    with pytest.raises(TypeError):
        animkit.ClothScene(integrator=3)
    with pytest.raises(TypeError):
        animkit.ClothScene(cloth="grid")
    with pytest.raises(animkit.Error):
        animkit.read_cloth_scene(tmp_path / "missing.json")
    bad = tmp_path / "bad.json"
    bad.write_text("{\"frames\": ")
    with pytest.raises(animkit.Error, match="bad.json"):
        animkit.read_cloth_scene(bad)
    with pytest.raises(animkit.Error, match="frame"):
        animkit.parse_cloth_scene('{"frames": "many"}')
    with pytest.raises(animkit.Error, match="unknown|frams"):
        animkit.parse_cloth_scene('{"frams": 3}')


def test_read_and_parse_scene(tmp_path, source_dir):
    text = json.dumps({"cloth": {"grid": 6, "material": "denim"},
                       "colliders": [{"name": "ball", "shape": "sphere", "radius": 0.3,
                                      "position": [1, 0.5, 0]}],
                       "ground": {"height": 0}, "frames": 12, "dt": 0.02})
    scene = animkit.parse_cloth_scene(text)
    assert scene.cloth.cells == 6 and scene.cloth.gravity == 9.81 and scene.frames == 12
    assert scene.colliders[0].name == "ball" and scene.ground.height == 0
    path = tmp_path / "scene.json"
    path.write_text(text)
    assert repr(animkit.read_cloth_scene(path)) == repr(scene)
    assert animkit.read_cloth_scene(str(path)).dt == 0.02
    pillow = animkit.read_cloth_scene(source_dir / "docs" / "scenes" / "pillow-drop.json")
    assert pillow.frames >= 1


# ---- the simulator ----

def test_simulator_lab():
    sim = animkit.ClothSimulator(animkit.ClothScene())
    assert sim.particle_count == 121 and sim.steps_taken == 0 and sim.time == 0
    assert sim.triangles.shape == (200, 3) and sim.triangles.dtype == np.int32
    assert sim.springs.shape[1] == 2
    assert sim.pinned.sum() == 2 and sim.pinned[0] and sim.pinned[10]
    np.testing.assert_array_equal(sim.masses, np.ones(121))
    start = np.array(sim.positions)
    before = sim.energy()
    report = sim.step()
    assert isinstance(report, animkit.StepReport)
    assert report.converged and report.newton_iterations >= 1 and report.substeps == 1
    assert report.energy == pytest.approx(sim.energy().total, rel=0, abs=0)
    assert report.energy < before.total  # damping and implicit Euler lose energy
    assert sim.steps_taken == 1 and sim.time == pytest.approx(1 / 60)
    assert not np.array_equal(sim.positions, start)
    np.testing.assert_array_equal(sim.positions[sim.pinned], start[sim.pinned])
    e = sim.energy()
    assert e.total == pytest.approx(e.kinetic + e.elastic + e.gravitational)
    assert "StepReport(substeps=1, newton_iterations=" in repr(report)
    assert repr(sim).startswith("ClothSimulator(particles=121")
    reports = sim.run(frames=5)
    assert len(reports) == 5 and sim.steps_taken == 6
    frames = []
    sim.run(frames=4, callback=lambda frame, r: frames.append((frame, r.energy)))
    assert [f for f, _ in frames] == [1, 2, 3, 4] and sim.steps_taken == 10
    stopped = sim.run(frames=10, callback=lambda frame, r: frame < 3)
    assert len(stopped) == 3 and sim.steps_taken == 13
    assert len(sim.run()) == sim.scene.frames  # None: the scene's frames


def test_record_iterations():
    scene = animkit.ClothScene(integrator=animkit.NewtonSettings(record_iterations=True))
    report = animkit.ClothSimulator(scene).step()
    assert len(report.iterations) == report.newton_iterations >= 1
    last = report.iterations[-1]
    assert isinstance(last, animkit.IterationRecord)
    assert last.gradient_norm == report.gradient_norm_end and 0 < last.alpha <= 1
    assert repr(last).startswith("IterationRecord(gradient_norm=")
    assert animkit.ClothSimulator(animkit.ClothScene()).step().iterations == []


@pytest.mark.parametrize("integrator", animkit.integrator_names())
def test_every_integrator_steps(integrator):
    substeps = 10 if integrator == "explicit" else 0
    scene = animkit.ClothScene(integrator=integrator, substeps=substeps)
    sim = animkit.ClothSimulator(scene)
    assert sim.integrator_name == integrator
    start = np.array(sim.positions)
    sim.run(frames=3)
    assert sim.steps_taken == 3 and not np.array_equal(start, sim.positions)


def test_contact_scene_and_collider_poses():
    scene = animkit.ClothScene(
        cloth=animkit.GridCloth(cells=6, size=1.0, height=1.0, material=animkit.material("cotton"),
                                pins="none", offset=(-0.5, 0, 0)),
        colliders=[animkit.Collider.sphere("ball", 0.3, position=(0, 0.5, 0),
                                           velocity=(0, 0, 0.5))],
        ground=animkit.Ground(height=0.0), dt=1 / 30, frames=10)
    sim = animkit.ClothSimulator(scene)
    poses = sim.collider_poses
    assert [p.name for p in poses] == ["ball"]
    np.testing.assert_allclose(poses[0].position, [0, 0.5, 0])
    report = sim.step()
    assert report.has_contact
    np.testing.assert_allclose(sim.collider_poses[0].position, [0, 0.5, 0.5 / 30], atol=1e-12)
    assert "ColliderPose(name='ball'" in repr(sim.collider_poses[0])
    vertices = sim.collider_vertices()
    assert len(vertices) == 1 and vertices[0].shape[1] == 3
    assert np.all(np.linalg.norm(vertices[0] - sim.collider_poses[0].position, axis=1) < 0.31)


def test_set_state_and_external_forces():
    sim = animkit.ClothSimulator(animkit.ClothScene())
    n = sim.particle_count
    moved = np.array(sim.positions) + [0.0, 0.1, 0.0]
    sim.set_state(moved, time=2.0)
    np.testing.assert_array_equal(sim.positions, moved)
    np.testing.assert_array_equal(sim.velocities, np.zeros((n, 3)))
    assert sim.time == 2.0
    velocities = np.ones((n, 3))
    sim.set_state(moved, velocities)
    assert sim.time == 2.0  # unchanged
    np.testing.assert_array_equal(sim.velocities[sim.pinned], 0.0)  # pinned: at rest
    np.testing.assert_array_equal(sim.velocities[~sim.pinned], 1.0)
    # A force on every particle pushes the cloth along it.
    free = animkit.ClothSimulator(animkit.ClothScene())
    pushed = animkit.ClothSimulator(animkit.ClothScene())
    pushed.set_external_forces(np.tile([0.0, 0.0, 5.0], (n, 1)))
    free.step()
    pushed.step()
    assert (pushed.positions[:, 2] - free.positions[:, 2])[~pushed.pinned].min() > 0
    pushed.clear_external_forces()
    again = animkit.ClothSimulator(animkit.ClothScene())
    again.set_state(pushed.positions, pushed.velocities, time=pushed.time)
    pushed.step()
    again.step()
    np.testing.assert_array_equal(pushed.positions, again.positions)


def test_simulator_errors():
    sim = animkit.ClothSimulator(animkit.ClothScene())
    n = sim.particle_count
    with pytest.raises(animkit.Error, match="time step"):
        sim.step(dt=0)
    with pytest.raises(animkit.Error, match="time step"):
        sim.step(dt=math.nan)
    with pytest.raises(animkit.Error, match="time step"):
        sim.step(dt=100)
    with pytest.raises(animkit.Error, match="frames"):
        sim.run(frames=0)
    with pytest.raises(animkit.Error, match="positions must have one row per particle"):
        sim.set_state(np.zeros((n - 1, 3)))
    with pytest.raises(animkit.Error, match="positions"):
        sim.set_state(np.zeros((n, 2)))
    with pytest.raises(animkit.Error, match="non-finite"):
        sim.set_state(np.full((n, 3), math.nan))
    with pytest.raises(animkit.Error, match="non-finite"):
        sim.set_state(np.zeros((n, 3)), time=math.inf)
    with pytest.raises(animkit.Error, match="forces"):
        sim.set_external_forces(np.zeros((3, 3)))
    with pytest.raises(animkit.Error, match="non-finite"):
        sim.set_external_forces(np.full((n, 3), math.inf))
    with pytest.raises(ValueError):  # animkit.Error is a ValueError
        sim.set_external_forces([[1, 2]])
    with pytest.raises(TypeError):
        sim.step(dt="fast")
    assert sim.steps_taken == 0 and sim.time == 0  # nothing above changed the state

    def fail(frame, report):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        sim.run(frames=3, callback=fail)
    assert sim.steps_taken == 1


def test_build_errors():
    # A particle starting inside a collider, or below the ground.
    inside = animkit.ClothScene(colliders=[animkit.Collider.sphere("ball", 0.5,
                                                                   position=(1, 1.5, 0))])
    with pytest.raises(animkit.Error, match="inside collider 'ball'"):
        animkit.ClothSimulator(inside)
    with pytest.raises(animkit.Error):
        animkit.ClothSimulator(animkit.ClothScene(ground=animkit.Ground(height=2.0)))
    # Attributes are checked when the scene is used.
    scene = animkit.ClothScene()
    scene.frames = -3
    with pytest.raises(animkit.Error):
        animkit.ClothSimulator(scene)
    with pytest.raises(animkit.Error):
        scene.validate()
    grid = animkit.GridCloth()
    grid.mass = math.nan
    with pytest.raises(animkit.Error):
        animkit.ClothScene(cloth=grid)
    scene = animkit.ClothScene()
    scene.cloth = grid
    with pytest.raises(animkit.Error):
        animkit.ClothSimulator(scene)


def test_divergence_raises_and_keeps_the_state():
    explicit = dict(integrator="explicit", substeps=1)
    sim = animkit.ClothSimulator(animkit.ClothScene(**explicit))
    sim.run(frames=2)
    n = sim.particle_count
    # Explicit Euler without substeps: velocities of 5e7 units/s over a 10 s step carry
    # particles beyond 1e8, an exploded state.
    sim.set_state(np.array(sim.positions), np.full((n, 3), 5e7))
    positions, velocities = np.array(sim.positions), np.array(sim.velocities)
    time, steps = sim.time, sim.steps_taken
    with pytest.raises(animkit.Error, match="diverged in step 3"):
        sim.step(dt=10)
    np.testing.assert_array_equal(sim.positions, positions)
    np.testing.assert_array_equal(sim.velocities, velocities)
    assert (sim.time, sim.steps_taken) == (time, steps)
    # The same through run(): the state is the last good one.
    scene = animkit.ClothScene(dt=10, **explicit)
    runner = animkit.ClothSimulator(scene)
    runner.set_state(np.array(runner.positions), np.full((n, 3), 5e7))
    kept = np.array(runner.positions)
    with pytest.raises(animkit.Error, match="diverged in step 1"):
        runner.run(frames=5)
    np.testing.assert_array_equal(runner.positions, kept)
    assert runner.steps_taken == 0


def test_a_scene_asking_for_auto_gets_a_measured_integrator_that_takes_contact():
    scene = animkit.parse_cloth_scene(
        '{"cloth": {"grid": 4, "size": 1, "height": 0.3, "material": "cotton", "pins": "none"},'
        ' "ground": {}, "solver": {"integrator": "auto"}, "frames": 2}')
    assert scene.integrator_name == "auto" and "integrator='auto'" in repr(scene)
    simulator = animkit.ClothSimulator(scene)
    assert simulator.integrator_name.startswith("implicit-")
    simulator.run()
    # The same from Python; a name assigned afterwards replaces it.
    scene.integrator = "implicit-direct"
    assert scene.integrator_name == "implicit-direct"
    scene.integrator = "auto"
    assert animkit.ClothSimulator(scene).integrator_name.startswith("implicit-")
