"""The Python module and `animkit cloth` run the same simulation to the bit.

What is compared, for the lab's scene and a contact scene (drape-sphere):
- every frame of the CLI's cloth.pc2 (float32 positions, the initial state and each step's)
  with the Python run's float64 positions cast to float32, bit for bit;
- every step of the CLI's metrics.json (nlohmann writes doubles with round-trip precision, so
  json.loads gives back the exact doubles): the iteration counts (newton, line search, linear,
  projected, friction), the gradient norms at start and end, converged, the total energy, and
  with contact the contact pairs and the smallest contact distance, all exactly equal.
Timings (ms) differ from run to run and are not compared."""
import json
import struct
import subprocess

import numpy as np
import pytest

import animkit

EXACT_FIELDS = ["newton_iterations", "line_search_steps", "linear_iterations",
                "projected_iterations", "gradient_norm_start", "gradient_norm_end",
                "newton_speed_end", "converged", "energy", "step_bound_min"]
CONTACT_FIELDS = ["contact_pairs", "min_contact_distance", "friction_iterations"]


def read_pc2(path):
    data = path.read_bytes()
    signature, version, points, start, rate, samples = struct.unpack("<12siiffi", data[:32])
    assert signature == b"POINTCACHE2\0" and version == 1
    frames = np.frombuffer(data[32:], dtype="<f4")
    assert frames.size == samples * points * 3
    return frames.reshape(samples, points, 3)


@pytest.mark.parametrize("scene_name, frames", [("lab", 30), ("drape-sphere", 8)])
def test_python_run_matches_the_cli_bit_for_bit(cli, tmp_path, scene_name, frames):
    out = tmp_path / "run"
    subprocess.run([str(cli), "cloth", "--scene", scene_name, "--frames", str(frames),
                    "--out", str(out), "--no-picture"], check=True, capture_output=True)
    cache = read_pc2(out / "cloth.pc2")
    metrics = json.loads((out / "metrics.json").read_text())
    assert cache.shape[0] == frames + 1 and len(metrics["steps"]) == frames

    scene = animkit.ClothScene.builtin(scene_name)
    scene.frames = frames
    assert metrics["integrator"] == scene.integrator_name
    sim = animkit.ClothSimulator(scene)
    assert cache.shape[1] == sim.particle_count
    python_frames = [np.array(sim.positions, dtype=np.float32)]
    reports = sim.run(callback=lambda frame, report: python_frames.append(
        np.array(sim.positions, dtype=np.float32)))
    python_cache = np.stack(python_frames)
    # Bit for bit: compare the float32 patterns, not the values (so -0.0 != 0.0 would show).
    assert np.array_equal(python_cache.view(np.uint32), cache.view(np.uint32))

    assert len(reports) == frames
    for k, (report, step) in enumerate(zip(reports, metrics["steps"])):
        fields = EXACT_FIELDS + (CONTACT_FIELDS if report.has_contact else [])
        for field in fields:
            assert getattr(report, field) == step[field], f"step {k + 1}: {field}"
        assert report.has_contact == ("contact_pairs" in step)
    assert metrics["final_energy"] == reports[-1].energy
    if scene_name == "drape-sphere":  # the comparison covers steps with contact
        assert max(r.contact_pairs for r in reports) > 0
        assert sum(r.newton_iterations for r in reports) > 0
