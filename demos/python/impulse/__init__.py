"""impulse from Python: scenes, traces as numpy arrays, videos shown inline, listing 1 graded.

    import impulse
    scene = impulse.load("assets/scenes/bounce.toml", set={"world.friction": False})
    trace = scene.simulate()                 # numpy arrays: trace.time, trace.position("ball"), ...
    video = scene.render("out/bounce.mp4")   # shows itself in Jupyter
    impulse.grade(my_add_collision_impulse)  # listing 1 in Python, held to the laws

The same libraries as the ``impulse`` program: the same checks, messages and numbers. The GIL is
released while a scene simulates or renders; Ctrl-C stops it and leaves no file behind.
"""

import os
import sys


def _import_error(missing):
    """What to do when numpy or the compiled module cannot be imported: which Python the package
    was built for (it has numpy: CMake requires it), and how to give this one numpy."""
    try:
        from ._built import PYTHON as built, VERSION as built_version
    except ImportError:
        built, built_version = "/usr/bin/python3", "Debian's"
    this = f"{sys.executable} ({sys.version_info.major}.{sys.version_info.minor})"
    other = os.path.realpath(sys.executable) != os.path.realpath(built)
    package = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # build/python, or the prefix's
    run_built = (f" The package was built for {built} ({built_version}), which has numpy: run that one, e.g. "
                 f"PYTHONPATH={package} {built}." if other else "")
    if missing == "numpy":
        return (f"impulse needs numpy, which this Python lacks: {this}.{run_built} {'Or i' if other else 'I'}nstall "
                f"numpy for this one: sudo apt-get install python3-numpy (Debian's python3), or {sys.executable} -m "
                f"pip install numpy (a venv's or a pyenv's).")
    return (f"impulse's compiled module does not load in this Python, {this}.{run_built or ' Build it again.'} "
            f"(To build for another Python: cmake -B build -DPython_EXECUTABLE=/path/to/python3, which needs numpy "
            f"and its headers.)")


try:
    import numpy  # noqa: F401  (every array the package gives is numpy's)
except ImportError as error:
    raise ImportError(_import_error("numpy")) from error
# Installed (cmake --install, the .deb): the sandbox's child and the workshop header, from here.
try:
    from ._installed import RESPONDER as _responder, INCLUDE as _include
    _here = os.path.dirname(os.path.abspath(__file__))
    os.environ.setdefault("IMPULSE_RESPOND", os.path.normpath(os.path.join(_here, _responder)))
    os.environ.setdefault("IMPULSE_WORKSHOP_INCLUDE", os.path.normpath(os.path.join(_here, _include)))
except ImportError:
    pass
try:
    from . import _impulse
except ImportError as error:
    raise ImportError(_import_error("_impulse")) from error
from ._toml import settings as _settings
from .trace import Trace, Contacts
from .page import Page
from .video import Video
from .workshop import Grade, RigidBody, case_names, time_step

__all__ = ["load", "scene", "Scene", "Trace", "Contacts", "Video", "Page", "compare", "grade", "Grade", "RigidBody",
           "time_step", "case_names", "SceneError", "OutputError", "ResponseError"]

SceneError = _impulse.SceneError        # ValueError: .file, .line, .table, .field, .setting
OutputError = _impulse.OutputError      # OSError: an output that cannot be written (nothing was replaced)
ResponseError = _impulse.ResponseError  # RuntimeError: a response that raised or made a NaN


def _progress(progress, description, unit):
    """A progress(done, total) for the C++ side: tqdm's bar when progress is True (the default)
    and tqdm is installed, a function of yours, or None. In Jupyter the bar is tqdm's widget where
    ipywidgets is installed, else its text bar."""
    if callable(progress):
        return progress
    if not progress:
        return None
    try:
        from tqdm.std import tqdm
    except ImportError:
        return None
    try:
        import ipywidgets  # noqa: F401  (tqdm's notebook bar needs it; without, it warns and draws nothing)
        from tqdm.auto import tqdm
    except ImportError:
        pass
    bar = None

    def update(done, total):
        nonlocal bar
        if bar is None:
            bar = tqdm(total=total, desc=description, unit=unit)
        bar.total = total
        bar.update(done - bar.n)
        if done >= total:
            bar.close()
    return update


class Scene:
    """A scene file read, with settings over it: what ``impulse render`` and ``simulate`` take.

    path, name, title, duration (s), time_step (s), bodies (names), settings (KEY=VALUE),
    compare (the file's [compare], or None), response (a Python listing 1, or None)
    """

    def __init__(self, core):
        self._core = core

    path = property(lambda self: self._core.path)
    title = property(lambda self: self._core.title)
    duration = property(lambda self: self._core.duration)
    time_step = property(lambda self: self._core.time_step)
    bodies = property(lambda self: list(self._core.bodies))
    settings = property(lambda self: list(self._core.settings))
    compare_spec = property(lambda self: self._core.compare)
    response = property(lambda self: self._core.response)

    @property
    def name(self):
        return os.path.splitext(os.path.basename(self.path))[0]

    def __repr__(self):
        changed = f" with {', '.join(self.settings)}" if self.settings else ""
        return f"<impulse.Scene {self.path}{changed}: {len(self.bodies)} bodies, {self.duration:g} s>"

    def with_settings(self, set=None, response=None):
        """The same scene with more settings over it (and a response, if given)."""
        return Scene(self._core.with_settings(_settings(set), response))

    def simulate(self, duration=None, every=1, contacts=True, progress=True):
        """Steps the world to ``duration`` (s; None: the scene's) and returns a Trace of the start
        and every ``every``th step (and the last). ``contacts=False`` keeps none of the contacts
        (a resting heap of 1000 boxes has 4000 a step: 320 MB over 12 s)."""
        arrays = _impulse.simulate(self._core, -1.0 if duration is None else float(duration), int(every),
                                   bool(contacts), _progress(progress, f"simulate {self.name}", "step"))
        return Trace(self, arrays)

    def render(self, path=None, quality="low", progress=True):
        """Renders the scene (its [compare]'s panes, if it has one) into ``path`` (None:
        out/NAME.mp4) at quality "low" (854x480, 15 fps), "medium" or "high" (None: the
        scene's), with its poster and captions beside it; returns the Video."""
        path = os.fspath(path) if path is not None else os.path.join("out", self.name + ".mp4")
        written = _impulse.render(self._core, path, quality or "", _progress(progress, f"render {self.name}", "frame"))
        return Video(written)

    def view(self, path=None):
        """Writes the scene's interactive page into ``path`` (None: out/NAME.html), as ``impulse
        export`` does: one HTML file of the run and a three.js viewer to play, scrub and orbit,
        offline. Returns the Page, which a notebook shows inline."""
        path = os.fspath(path) if path is not None else os.path.join("out", self.name + ".html")
        return Page(_impulse.page(self._core, path))

    def frames(self, times, quality="low", progress=False):
        """The pictures at simulated times ``times`` (s), as render() shows them: a numpy array
        (len(times), height, width, 3) of uint8 RGB, (k, 480, 854, 3) at quality "low" (the
        default, as for render), 720 x 1280 at "medium", 1080 x 1920 at "high" (None: the
        scene's). One time, not a list: one picture (height, width, 3)."""
        single = not hasattr(times, "__len__")
        times = [float(times)] if single else [float(t) for t in times]
        pictures = _impulse.frames(self._core, times, quality or "", _progress(progress, f"render {self.name}", "frame"))
        return pictures[0] if single else pictures


def load(path, set=None, response=None):
    """Reads a scene file (TOML) with ``set`` over it: ``{"world.friction": False,
    "body[ball].restitution": 0.9}`` (the keys are --set's). ``response``: listing 1 as a Python
    function, run in place of the workshop method's page. Raises SceneError naming file, line and
    field."""
    return Scene(_impulse.load(os.fspath(path), _settings(set), response))


def scene(tables, set=None, response=None, name="<tables>"):
    """A scene from the scene file's tables as dicts: ``{"world": {...}, "body": [{...}, ...]}``
    (a list of dicts is a list of tables, [[body]]). Checked as a file is; messages name ``name``."""
    return Scene(_impulse.from_tables(tables, name, _settings(set), response))


def compare(*scenes, vary=None, path=None, quality="low", progress=True):
    """Two to four panes side by side in one video: one scene and ``vary={KEY: [V1, V2, ...]}``,
    or two to four scenes. Returns the Video (``path`` None: out/NAME_KEY.mp4 or out/A_vs_B.mp4)."""
    if not scenes:
        raise TypeError("compare needs a scene")
    cores = [s._core for s in scenes]
    vary_text = ""
    if vary:
        if len(scenes) != 1:
            raise ValueError("vary= takes one scene; to compare scenes, give two to four and no vary")
        if len(vary) != 1:
            raise ValueError(f"vary= varies one field, got {len(vary)}: {', '.join(vary)}")
        (key, values), = vary.items()
        from ._toml import toml_value
        vary_text = f"{key}=" + ",".join(toml_value(v) for v in values)
    if path is None:
        stem = scenes[0].name
        if vary:
            stem += "_" + "".join(c if c.isalnum() else "_" for c in key)
        else:
            stem += "".join("_vs_" + s.name for s in scenes[1:])
        path = os.path.join("out", stem + ".mp4")
    written = _impulse.compare(cores, vary_text, os.fspath(path), quality or "",
                               _progress(progress, f"render {scenes[0].name}", "frame"))
    return Video(written)


def grade(function=None, only=None, progress=True):
    """Holds listing 1 written in Python (``function(c0, c1, hit_point, normal, penetration)``)
    to the laws, case by case, as ``impulse grade`` does; None grades the engine's reference.
    Returns a Grade (print it for the table)."""
    name = "reference" if function is None else getattr(function, "__name__", "response") + "()"
    cases = _impulse.grade(function, only or "", _progress(progress, "grade", "case"))
    return Grade(name, function, list(cases))
