"""Listing 1 in Python as the world's response, and impulse.grade: the battery of `impulse grade`."""

import importlib.util
import json
import os
from pathlib import Path

import numpy as np
import pytest

import impulse
import listing1_corrected


def test_the_corrected_listing_in_python_passes_every_case_as_the_reference_does():
    reference = impulse.grade(progress=False)
    mine = impulse.grade(listing1_corrected.add_collision_impulse, progress=False)
    assert reference.failed == 0 and len(reference.cases) == len(impulse.case_names()) >= 10
    assert mine.failed == 0, str(mine)
    assert str(mine).startswith("impulse grade add_collision_impulse(): %d of %d" % (mine.passed, mine.passed))
    assert json.loads(mine.json())["passed"] == mine.passed


def printed_sign(c0, c1, hit_point, normal, penetration):
    """Eq. 8 as printed, -(1 - e): elastic hits lose their bounce."""
    dv = c0.lin_velocity - c1.lin_velocity
    if np.dot(dv, normal) > 0 or c0.inv_mass + c1.inv_mass == 0:
        return
    e = c0.restitution
    jn = -(1 - e) * np.dot(dv, normal) / (c0.inv_mass + c1.inv_mass)
    c0.lin_velocity = c0.lin_velocity + c0.inv_mass * jn * normal
    c1.lin_velocity = c1.lin_velocity - c1.inv_mass * jn * normal


def test_a_wrong_sign_fails_the_laws_it_breaks_with_hints(tmp_path):
    grade = impulse.grade(printed_sign, only="head_on_equal_e1", progress=False)
    (case,) = grade.cases
    assert not case["passed"] and case["hint"] and not grade
    videos = grade.videos(tmp_path)
    assert videos == [str(tmp_path / "head_on_equal_e1.mp4")] and os.path.getsize(videos[0]) > 0


def test_a_function_that_raises_fails_its_cases_and_the_interpreter_goes_on():
    def broken(c0, c1, hit_point, normal, penetration):
        return 1 / 0

    grade = impulse.grade(broken, progress=False)
    assert grade.passed == 0
    assert all("raised ZeroDivisionError" in case["failure"] for case in grade.cases)


def test_a_nan_or_a_wrong_shape_is_reported():
    def nan(c0, c1, hit_point, normal, penetration):
        c0.lin_velocity = c0.lin_velocity * np.nan

    def scalar(c0, c1, hit_point, normal, penetration):
        c0.lin_velocity = 0.0

    scene = impulse.load("assets/scenes/bounce.toml", response=nan)
    with pytest.raises(impulse.ResponseError, match="not a number"):
        scene.simulate(progress=False)
    with pytest.raises(impulse.ResponseError, match="not three numbers"):
        scene.with_settings(response=scalar).simulate(progress=False)


def test_a_scene_runs_with_the_python_response_as_with_the_cpp_one():
    # The same listing in C++ (assets/workshop/listing1_corrected.cpp) and in Python: the same law.
    python = impulse.load("assets/scenes/bounce.toml", response=listing1_corrected.add_collision_impulse)
    cpp = impulse.load("assets/scenes/bounce.toml", set={"world.response": "reference"})
    a = python.simulate(duration=1.5, progress=False).position("dropped ball")[:, 1]
    b = cpp.simulate(duration=1.5, progress=False).position("dropped ball")[:, 1]
    assert np.max(np.abs(a - b)) < 1e-3  # floats in C++, doubles here
    assert python.response is listing1_corrected.add_collision_impulse


def module_from(tmp_path, name, text):
    """A module written to a file of its own, as a student's is (the grade reads its lines)."""
    path = tmp_path / (name + ".py")
    path.write_text(text)
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_hints_follow_the_cause_and_name_the_students_own_line(tmp_path):
    listing = Path(listing1_corrected.__file__).read_text()
    no_friction = module_from(tmp_path, "no_friction", listing[: listing.index("    # TANGENT impulse")])
    (stack,) = impulse.grade(no_friction.add_collision_impulse, only="stack", progress=False).cases
    assert not stack["passed"] and "slid off with no friction holding it" in stack["hint"], stack
    assert "hack fix" not in stack["hint"], stack

    correction = listing[listing.index("    # Position correction") : listing.index("    jn = max(jn, 0.0)")]
    hack_line = "    jn = jn + (penetration*1.5)"
    hacked = listing.replace(correction, hack_line + "\n\n")
    hack = module_from(tmp_path, "hack", hacked)
    (rest,) = impulse.grade(hack.add_collision_impulse, only="ball_rest", progress=False).cases
    line = hacked.splitlines().index(hack_line) + 1
    assert "your line %d, the listing's hack fix" % line in rest["hint"], rest

    uncorrected = module_from(tmp_path, "uncorrected", listing.replace(correction, ""))
    (rest,) = impulse.grade(uncorrected.add_collision_impulse, only="ball_rest", progress=False).cases
    assert "the penetration is never corrected" in rest["hint"] and "hack fix" not in rest["hint"], rest
