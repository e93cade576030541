"""Scene.simulate: the numbers `impulse simulate` writes, bit for bit, as numpy arrays."""

import csv
import os
import subprocess
import threading
import time

import numpy as np
import pytest

import impulse


def read_csv(path):
    with open(path, newline="") as file:
        return list(csv.reader(file))


def g(value):
    return "%.9g" % value


@pytest.mark.parametrize("scene_file", ["assets/scenes/bounce.toml", "assets/scenes/s4_angular.toml", "assets/scenes/s5_shapes.toml",
                                        "assets/scenes/s5_hulls.toml", "assets/scenes/s5_half_pipe.toml"])
def test_the_trace_is_what_impulse_simulate_writes(program, tmp_path, scene_file):
    bodies_csv, contacts_csv, world_csv = (str(tmp_path / n) for n in ("bodies.csv", "contacts.csv", "world.csv"))
    subprocess.run([program, "simulate", scene_file, "--every", "3", "--trace", bodies_csv, "--contacts", contacts_csv,
                    "--world", world_csv], check=True, capture_output=True)
    trace = impulse.load(scene_file).simulate(every=3, progress=False)

    rows = read_csv(bodies_csv)[1:]
    assert len(rows) == len(trace) * len(trace.bodies)
    k = 0
    for i in range(len(trace)):
        for b, name in enumerate(trace.bodies):
            row = rows[k]
            k += 1
            values = [trace.time[i]] + list(trace.position(b)[i]) + list(trace.orientation(b)[i]) + \
                list(trace.velocity(b)[i]) + list(trace.angular_velocity(b)[i])
            assert row[1] == str(trace.step[i]) and row[2] == name
            assert row[:1] + row[3:] == [g(v) for v in values], f"row {k}"

    world = read_csv(world_csv)[1:]
    assert len(world) == len(trace)
    for i, row in enumerate(world):
        values = [trace.time[i], trace.kinetic_energy[i], trace.potential_energy[i], *trace.momentum[i],
                  *trace.angular_momentum[i]]
        assert row[:1] + row[2:] == [g(v) for v in values]

    contacts = read_csv(contacts_csv)[1:]
    c = trace.contacts
    assert len(contacts) == len(c) > 0
    for j, row in enumerate(contacts):
        values = [c.time[j], *c.point[j], *c.normal[j], c.penetration[j], c.normal_impulse[j], *c.friction_impulse[j]]
        assert row[1:4] == [str(c.step[j]), c.body_a[j], c.body_b[j]]
        assert row[:1] + row[4:] == [g(v) for v in values]


def test_the_race_of_a_ball_a_cylinder_and_a_ring_from_a_notebook():
    # a = g sin(theta) / (1 + I/mR^2) down the 15-degree incline: 5/7, 2/3 and 1/2 of g sin(theta).
    trace = impulse.load("assets/scenes/s5_rolling_race.toml").simulate(progress=False)
    g_sin = 9.81 * np.sin(np.radians(15))
    first, last = np.searchsorted(trace.time, 0.5), np.searchsorted(trace.time, 2.0)
    for b, share in zip(range(2, 5), (5 / 7, 2 / 3, 1 / 2)):
        speed = np.linalg.norm(trace.velocity(b), axis=1)
        a = (speed[last] - speed[first]) / (trace.time[last] - trace.time[first])
        assert a == pytest.approx(share * g_sin, rel=0.01), trace.bodies[b]


def test_to_pandas_has_the_csv_columns(program, tmp_path):
    pandas = pytest.importorskip("pandas")
    bodies_csv = str(tmp_path / "bodies.csv")
    subprocess.run([program, "simulate", "assets/scenes/bounce.toml", "--every", "10", "--trace", bodies_csv],
                   check=True, capture_output=True)
    frame = impulse.load("assets/scenes/bounce.toml").simulate(every=10, progress=False).to_pandas()
    expected = pandas.read_csv(bodies_csv)
    assert list(frame.columns) == list(expected.columns)
    assert len(frame) == len(expected)
    assert np.allclose(frame["y_m"].to_numpy(), expected["y_m"].to_numpy(), rtol=1e-8, atol=0)


def test_every_keeps_the_start_every_nth_step_and_the_last():
    scene = impulse.load("assets/scenes/bounce.toml")
    trace = scene.simulate(duration=1.0, every=7, progress=False)
    steps = round(1.0 / scene.time_step)
    assert trace.step[0] == 0 and trace.step[-1] == steps
    assert list(trace.step[1:-1]) == list(range(7, steps, 7))
    without = scene.simulate(duration=1.0, every=7, contacts=False, progress=False)
    assert len(trace.contacts) > 0 and len(without.contacts) == 0
    assert np.array_equal(without.position(0), trace.position(0))
    with pytest.raises(ValueError, match="every"):
        scene.simulate(every=0)
    with pytest.raises(KeyError, match="no body is named"):
        trace.position("no such body")


def test_momentum_is_kept_in_a_frictionless_hit_in_zero_gravity():
    tables = {
        "scene": {"duration": 1.0},
        "world": {"gravity": [0, 0, 0], "friction": False},
        "body": [
            {"name": "a", "shape": "sphere", "radius": 0.3, "mass": 1.0, "position": [-1, 0, 0], "velocity": [2, 0, 0],
             "restitution": 1.0},
            {"name": "b", "shape": "sphere", "radius": 0.3, "mass": 2.0, "position": [1, 0.1, 0], "restitution": 1.0},
        ],
    }
    trace = impulse.scene(tables).simulate(progress=False)
    assert len(trace.contacts) > 0
    assert np.allclose(trace.momentum, trace.momentum[0], atol=1e-9)
    assert abs(trace.kinetic_energy[-1] / trace.kinetic_energy[0] - 1) < 1e-3


def test_the_gil_is_released_while_simulating():
    # A thread that ticks every millisecond runs while the heap steps. Were the GIL held, it could
    # tick only when the progress check takes it back (ten times a second): ten times that is asked.
    scene = impulse.load("assets/scenes/ex2_many_bodies.toml")
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    thread = threading.Thread(target=count)
    thread.start()
    started = time.monotonic()
    scene.simulate(duration=2.0, every=60, progress=False)
    ended = time.monotonic()
    done.set()
    thread.join()
    during = [t for t in ticks if started < t < ended]
    assert len(during) > 10 * (ended - started) / 0.1, \
        "Python ran %d times in %.2f s while the world stepped" % (len(during), ended - started)
