"""tecido.run against the closed-form motion of a free particle, the command line's result for the
same scene, and the command line's error messages."""
import json

import numpy as np
import pytest

import tecido
from conftest import write_json

G = -9.81


def projectile(integrator="symplectic", steps=100, dt=0.01):
    return {"integrator": integrator, "dt": dt, "steps": steps, "gravity": [0.0, 0.0, G],
            "particles": [{"position": [0.0, 0.0, 10.0], "velocity": [1.0, 0.0, 2.0], "mass": 1.0}]}


def z_after(integrator, n, h):
    """Height after n steps of h under constant gravity: each method's closed form."""
    z0, w0 = 10.0, 2.0
    if integrator == "euler":  # x uses the old velocity
        return z0 + n * h * w0 + G * h * h * n * (n - 1) / 2
    if integrator == "symplectic":  # x uses the new velocity
        return z0 + n * h * w0 + G * h * h * n * (n + 1) / 2
    return z0 + w0 * n * h + G * (n * h) ** 2 / 2  # midpoint, rk4: exact for constant acceleration


@pytest.mark.parametrize("integrator", ["euler", "symplectic", "midpoint", "rk4"])
def test_free_particle_follows_the_closed_form(integrator):
    r = tecido.run(projectile(integrator))
    assert r["status"] == "ok" and r["steps"] == 100
    assert r["time"] == pytest.approx(1.0, rel=1e-12)
    x, z = r["positions"][0, 0], r["positions"][0, 2]
    assert x == pytest.approx(1.0, rel=1e-12)
    assert z == pytest.approx(z_after(integrator, 100, 0.01), rel=1e-12)
    assert r["velocities"][0, 2] == pytest.approx(2.0 + G * 1.0, rel=1e-12)


def test_frames_on_request():
    r = tecido.run(projectile("rk4"), frames=10)
    f = r["frames"]
    assert f["steps"].tolist() == list(range(0, 101, 10))
    assert f["positions"].shape == (11, 1, 3) and f["velocities"].shape == (11, 1, 3)
    for k, n in enumerate(f["steps"]):
        assert f["positions"][k, 0, 2] == pytest.approx(z_after("rk4", n, 0.01), rel=1e-12)
    assert "frames" not in tecido.run(projectile())


def test_same_result_as_the_command_line_bit_for_bit(tmp_path, cli):
    scene = projectile("midpoint", steps=37)
    path = write_json(tmp_path / "s.json", scene)
    doc = json.loads(cli("run", path, "--json").stdout)
    r = tecido.run(path)
    assert r["result"] == doc
    assert r["positions"].tolist() == [p["x"] for p in doc["particles"]]
    assert tecido.run(scene)["result"] == doc  # a dict and its file run alike


def test_overrides_and_an_unstable_run():
    r = tecido.run(projectile(), steps=10, dt=0.1, integrator="euler")
    assert r["steps"] == 10
    assert r["positions"][0, 2] == pytest.approx(z_after("euler", 10, 0.1), rel=1e-12)
    stiff = {"dt": 0.1, "steps": 200, "integrator": "euler",
             "particles": [{"position": [0, 0, 0], "mass": 1, "pinned": True},
                           {"position": [1.1, 0, 0], "mass": 1e-3}],
             "springs": [{"i": 0, "j": 1, "stiffness": 1e6, "rest_length": 1.0}]}
    assert tecido.run(stiff)["status"] == "unstable"


def test_scene_errors_carry_the_command_lines_message(tmp_path, cli):
    bad = projectile()
    bad["particles"][0]["mass"] = -1.0
    path = write_json(tmp_path / "bad.json", bad)
    line = cli("run", path, check=False).stderr.strip()
    assert line.startswith("tecido: " + str(path) + ": /particles/0/mass: ")
    with pytest.raises(ValueError) as e:
        tecido.run(path)
    assert "tecido: " + str(e.value) == line
    with pytest.raises(ValueError) as e:
        tecido.run(bad)
    assert str(e.value) == "scene" + line[len("tecido: " + str(path)):]


def test_file_errors_are_os_errors(tmp_path, cli):
    missing = tmp_path / "none.json"
    line = cli("run", missing, check=False).stderr.strip()
    with pytest.raises(OSError) as e:
        tecido.run(missing)
    assert "tecido: " + str(e.value) == line
    with pytest.raises(OSError, match="is a directory"):
        tecido.run(str(tmp_path))


def test_argument_errors():
    with pytest.raises(ValueError, match="steps: expected an integer"):
        tecido.run(projectile(), steps=1.5)
    with pytest.raises(ValueError, match="integrator: expected euler"):
        tecido.run(projectile(), integrator="leapfrog")
    with pytest.raises(ValueError, match=r"^scene: /: not a JSON document: Out of range float"):
        tecido.run({"dt": float("nan"), "steps": 1, "particles": []})
    with pytest.raises(ValueError, match="scene: expected a dict"):
        tecido.run(42)
