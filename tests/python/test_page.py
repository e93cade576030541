"""Scene.view and Trace.view: the page `impulse export` writes, the same bytes from Python, shown
inline in a notebook as a frame of its own; the run in it is the trace's."""

import html
import base64
import gzip
import json
import os
import re
import subprocess

import numpy as np

import impulse


def test_view_writes_the_page_the_program_exports_and_shows_it_inline(tmp_path, program):
    scene = impulse.load("assets/scenes/bounce.toml", set={"body[dropped ball].restitution": 0.5})
    page = scene.view(tmp_path / "bounce.html")
    assert page.path == str(tmp_path / "bounce.html") and os.fspath(page) == page.path
    subprocess.run([program, "-q", "export", "assets/scenes/bounce.toml", "--set", "body[dropped ball].restitution=0.5",
                    "-o", str(tmp_path / "exported.html")], check=True)
    with open(page.path, "rb") as mine, open(tmp_path / "exported.html", "rb") as exported:
        assert mine.read() == exported.read()
    shown = page._repr_html_()
    assert shown.startswith('<iframe title="bounce.html" sandbox="allow-scripts"')
    source = html.unescape(re.search(r'srcdoc="([^"]*)"', shown).group(1))
    with open(page.path, encoding="utf-8") as file:
        assert source == file.read()
    assert sorted(os.listdir(tmp_path)) == ["bounce.html", "exported.html"]


def test_a_comparisons_page_shows_its_panes_as_export_does(tmp_path, program):
    scene = impulse.load("assets/scenes/ex1_friction.toml")
    page = scene.view(tmp_path / "friction.html")
    subprocess.run([program, "-q", "export", "assets/scenes/ex1_friction.toml", "-o", str(tmp_path / "exported.html")], check=True)
    with open(page.path, "rb") as mine, open(tmp_path / "exported.html", "rb") as exported:
        assert mine.read() == exported.read()
    with open(page.path, encoding="utf-8") as file:
        run = page_run(file.read())
    assert [pane["label"] for pane in run["panes"]] == ["tangential impulses off", "on: friction \u03bc = 0.5"]


def page_run(text):
    """The run in a page: JSON, gzipped, in base64."""
    packed = re.search(r'<script id="impulse-run" type="application/gzip;base64">([^<]*)</script>', text)
    return json.loads(gzip.decompress(base64.b64decode(packed.group(1))))


def test_a_traces_page_holds_its_run(tmp_path):
    scene = impulse.load("assets/scenes/bounce.toml")
    trace = scene.simulate(progress=False)
    page = trace.view(tmp_path / "trace.html")
    with open(page.path, encoding="utf-8") as file:
        text = file.read()
    run = page_run(text)
    assert [body["name"] for body in run["bodies"]] == trace.bodies
    # The dropped ball at 1 s in the page (frame 30 of 30 fps) where the trace has it: the sum of
    # its listed changes, in 1e-5 m.
    ball = trace.bodies.index("dropped ball")
    frame = round(1.0 * run["fps"])
    units = np.zeros(3)
    for k in range(frame + 1):
        listed = run["frames"][k]
        for at in range(0, len(listed), 8):
            if listed[at] == ball:
                units += listed[at + 1:at + 4]
    pose = units / 1e5
    row = int(np.argmin(np.abs(trace.time - 1.0)))
    assert abs(trace.time[row] - 1.0) < 1e-9
    assert np.allclose(pose, trace.position(ball)[row], atol=2e-5)
