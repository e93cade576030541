"""Scene.render, impulse.compare and Scene.frames: real frames from OSMesa, a real MP4 from
libavcodec, decoded back by ffprobe; Ctrl-C stops a render and leaves nothing behind."""

import json
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import impulse


def probe(path):
    """The first video stream's width, height and frame count, decoded by ffprobe."""
    out = subprocess.run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-count_frames", "-show_entries",
                          "stream=width,height,codec_name,nb_read_frames", "-of", "json", path],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)["streams"][0]


def test_render_writes_a_video_its_poster_and_captions_and_shows_them_inline(tmp_path):
    video = impulse.load("assets/scenes/bounce.toml").render(tmp_path / "bounce.mp4", progress=False)
    assert video.path == str(tmp_path / "bounce.mp4")
    stream = probe(video.path)
    assert (stream["codec_name"], stream["width"], stream["height"]) == ("h264", 854, 480)  # quality "low"
    assert int(stream["nb_read_frames"]) > 6 * 15
    assert video.poster.endswith("bounce.png") and os.path.getsize(video.poster) > 0
    assert video.captions.endswith("bounce.vtt") and open(video.captions).read().startswith("WEBVTT")
    assert all(check["passed"] for check in video.checks[0]) and len(video.checks[0]) > 0
    html = video._repr_html_()
    assert html.startswith("<video") and 'src="data:video/mp4;base64,' in html
    assert 'poster="data:image/png;base64,' in html and 'kind="captions"' in html
    assert sorted(os.listdir(tmp_path)) == sorted(
        os.path.basename(p) for p in [video.path, video.poster, video.captions] + ([video.chapters] if video.chapters else []))


def test_compare_shows_two_panes_of_one_field(tmp_path):
    scene = impulse.load("assets/scenes/ex1_friction.toml")
    video = impulse.compare(scene, vary={"world.friction": [True, False]}, path=tmp_path / "f.mp4", progress=False)
    stream = probe(video.path)
    assert (stream["width"], stream["height"]) == (854, 480)
    assert len(video.checks) == 2
    with pytest.raises(ValueError, match="one field"):
        impulse.compare(scene, vary={"world.friction": [True, False], "world.method": ["impulse", "penalty"]})
    with pytest.raises(impulse.SceneError, match="value 2"):
        impulse.compare(scene, vary={"body[0].restitution": [0.5, 7]}, path=tmp_path / "g.mp4", progress=False)
    assert not os.path.exists(tmp_path / "g.mp4")


def test_frames_are_the_pictures_at_the_times_asked(tmp_path):
    scene = impulse.load("assets/scenes/bounce.toml")
    frames = scene.frames([1.0, 0.0, 1.0], quality="low")
    assert frames.shape == (3, 480, 854, 3) and frames.dtype == np.uint8
    assert np.array_equal(frames[0], frames[2])  # the same moment twice
    # The dropped ball (orange, #e69f00) is lower at 1 s, after its bounce, than at 0 s; the
    # scene's left part only (the kinetic energy's curve, at the right, is orange too).
    def orange(frame):
        frame = frame[:, :600]
        mask = (np.abs(frame[..., 0].astype(int) - 0xe6) < 40) & (np.abs(frame[..., 1].astype(int) - 0x9f) < 40) & \
               (frame[..., 2] < 60)
        ys, xs = np.nonzero(mask)
        assert len(ys) > 200, "no orange ball in the frame"
        return ys.mean(), xs.mean()
    (y0, x0), (y1, x1) = orange(frames[1]), orange(frames[0])
    assert y1 - y0 > 40 and abs(x1 - x0) < 10  # it fell, straight down
    with pytest.raises(ValueError, match="within"):
        scene.frames([scene.duration + 1])


def test_frames_are_the_readmes_shape_by_default_and_the_quality_asked_for():
    # ex1_friction's video is "medium" (1280x720); frames, as render, are "low" unless asked.
    scene = impulse.load("assets/scenes/ex1_friction.toml")
    assert scene.frames([0.5, 1.0]).shape == (2, 480, 854, 3)
    assert scene.frames(0.5, quality="medium").shape == (720, 1280, 3)
    assert scene.frames([0.5], quality=None).shape == (1, 720, 1280, 3)  # the scene's own


def test_an_unwritable_output_is_an_output_error(tmp_path):
    (tmp_path / "dir.mp4").mkdir()
    with pytest.raises(impulse.OutputError):
        impulse.load("assets/scenes/bounce.toml").render(tmp_path / "dir.mp4", progress=False)


CTRL_C_SCRIPT = r"""
import sys, impulse
sys.stdout.write("started\n"); sys.stdout.flush()
seen = []
def progress(done, total):
    if not seen:
        seen.append(done)
        sys.stdout.write("drawing\n"); sys.stdout.flush()
try:
    impulse.load("assets/scenes/bounce.toml").render(sys.argv[1], quality="medium", progress=progress)
except KeyboardInterrupt:
    sys.stdout.write("interrupted\n"); sys.stdout.flush()
    sys.exit(7)
sys.stdout.write("finished\n")
"""


def test_ctrl_c_stops_a_render_and_leaves_nothing_behind(tmp_path, root):
    out = tmp_path / "out"
    out.mkdir()
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    child = subprocess.Popen([sys.executable, "-c", CTRL_C_SCRIPT, str(out / "bounce.mp4")], cwd=root, env=env,
                             stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline() == "started\n"
    assert child.stdout.readline() == "drawing\n"  # frames are being drawn and encoded
    time.sleep(0.3)
    child.send_signal(signal.SIGINT)
    rest = child.stdout.read()
    assert child.wait(timeout=60) == 7, rest
    assert rest == "interrupted\n"
    assert os.listdir(out) == []  # no video, no .part file, no poster


def test_interrupting_the_kernel_stops_a_render_in_a_notebook(tmp_path, root):
    # Jupyter's "interrupt" on a real kernel (jupyter_client, as the notebook's page does it).
    jupyter_client = pytest.importorskip("jupyter_client")
    out = tmp_path / "out"
    out.mkdir()
    manager = jupyter_client.KernelManager(kernel_name="python3")
    manager.start_kernel(cwd=root, env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    client = manager.client()
    client.start_channels()
    try:
        client.wait_for_ready(timeout=60)
        code = ("import impulse\n"
                "seen = []\n"
                "def progress(done, total):\n"
                "    if not seen: seen.append(done); print('drawing', flush=True)\n"
                f"impulse.load('assets/scenes/bounce.toml').render({str(out / 'bounce.mp4')!r}, quality='medium', "
                "progress=progress)\n")
        request = client.execute(code)
        while True:  # until the frames are being drawn
            message = client.get_iopub_msg(timeout=120)
            if message["msg_type"] == "stream" and "drawing" in message["content"]["text"]:
                break
        time.sleep(0.3)
        manager.interrupt_kernel()
        reply = client.get_shell_msg(timeout=60)
        while reply["parent_header"].get("msg_id") != request:
            reply = client.get_shell_msg(timeout=60)
        assert reply["content"]["status"] == "error"
        assert reply["content"]["ename"] == "KeyboardInterrupt"
        assert os.listdir(out) == []
    finally:
        client.stop_channels()
        manager.shutdown_kernel(now=True)
