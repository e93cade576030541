"""impulse.load and impulse.scene: the scene room's checks and messages, from Python."""

import numpy as np
import pytest

import impulse


def test_load_reads_the_scene_and_its_settings():
    scene = impulse.load("assets/scenes/bounce.toml", set={"world.friction": False, "body[0].restitution": 0.25})
    assert scene.bodies[:1] and scene.duration > 0
    assert scene.settings == ["world.friction=false", "body[0].restitution=0.25"]


def test_a_malformed_file_names_file_line_and_field(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text('[scene]\ntitle = "x"\n\n[[body]]\nshape = "sphere"\nradius = 0.5\nmass = -2\n')
    with pytest.raises(impulse.SceneError) as raised:
        impulse.load(path)
    error = raised.value
    assert isinstance(error, ValueError)
    assert (error.file, error.line, error.field, error.setting) == (str(path), 7, "mass", None)
    assert "[[body]]" in error.table and str(path) + ":7:" in str(error)


def test_a_bad_setting_names_the_setting_and_suggests():
    with pytest.raises(impulse.SceneError) as raised:
        impulse.load("assets/scenes/bounce.toml", set={"world.frction": False})
    assert raised.value.setting == "world.frction=false"
    assert "did you mean 'friction'" in str(raised.value)
    with pytest.raises(impulse.SceneError) as raised:
        impulse.load("assets/scenes/bounce.toml", set={"body[0].restitution": 2})
    assert raised.value.field == "restitution" and "must be" in str(raised.value)


def test_a_missing_file_is_a_scene_error():
    with pytest.raises(impulse.SceneError, match="no such scene file"):
        impulse.load("assets/scenes/no_such_scene.toml")


def ball_tables(restitution):
    return {
        "scene": {"duration": 1.5},
        "world": {"friction": False},
        "body": [
            {"name": "ground", "shape": "plane", "normal": [0, 1, 0], "restitution": 0.0},
            {"name": "ball", "shape": "sphere", "radius": 0.2, "mass": 1.0, "position": np.array([0, 2.0, 0]),
             "restitution": restitution},
        ],
    }


def test_a_scene_from_tables_is_the_scene_of_the_same_file(tmp_path):
    path = tmp_path / "ball.toml"
    path.write_text('[scene]\nduration = 1.5\n[world]\nfriction = false\n'
                    '[[body]]\nname = "ground"\nshape = "plane"\nnormal = [0, 1, 0]\nrestitution = 0.0\n'
                    '[[body]]\nname = "ball"\nshape = "sphere"\nradius = 0.2\nmass = 1.0\nposition = [0, 2.0, 0]\n'
                    'restitution = 0.5\n')
    from_tables = impulse.scene(ball_tables(0.5)).simulate(progress=False)
    from_file = impulse.load(path).simulate(progress=False)
    assert np.array_equal(from_tables.position("ball"), from_file.position("ball"))
    # The law, too: the ball rises to e² of its drop (to within the step's).
    y = from_tables.position("ball")[:, 1]
    first_bounce = np.argmax(from_tables.velocity("ball")[:, 1] > 0)
    peak = y[first_bounce:].max()
    assert abs((peak - 0.2) / (2.0 - 0.2) - 0.25) < 0.02


def test_tables_with_a_wrong_value_name_the_field_without_a_line():
    with pytest.raises(impulse.SceneError) as raised:
        impulse.scene(ball_tables(1.5), name="my tables")
    error = raised.value
    assert (error.file, error.line, error.field) == ("my tables", None, "restitution")
    assert str(error).startswith("my tables: [[body]]")
    with pytest.raises(impulse.SceneError, match="not a scene value"):
        impulse.scene({"body": [{"shape": object()}]})


def test_import_without_numpy_says_which_python_has_it_and_how_to_install_it():
    """A Python without numpy (here: numpy blocked) is told what to run or install, not left with
    a bare ModuleNotFoundError."""
    import os
    import subprocess
    import sys
    package = os.path.dirname(os.path.dirname(impulse.__file__))
    run = subprocess.run([sys.executable, "-c", "import sys; sys.modules['numpy'] = None; import impulse"],
                         env=dict(os.environ, PYTHONPATH=package), capture_output=True, text=True)
    assert run.returncode != 0
    last = run.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: impulse needs numpy, which this Python lacks: " + sys.executable), run.stderr
    assert "sudo apt-get install python3-numpy" in last and f"{sys.executable} -m pip install numpy" in last
