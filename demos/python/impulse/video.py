"""A rendered video, shown inline in Jupyter: the MP4 with its poster and captions track."""

import base64
import os


def _data_url(path, mime):
    with open(path, "rb") as file:
        return f"data:{mime};base64,{base64.b64encode(file.read()).decode('ascii')}"


class Video:
    """An MP4 that ``Scene.render`` or ``impulse.compare`` wrote, and what sits beside it.

    path       the .mp4
    poster     its poster frame (.png), where something happens
    captions   its captions track (.vtt), None when the scene has none
    chapters   its chapters track (.vtt), None when it has none
    checks     each pane's [[check]]s: lists of dicts of check, passed, measured
    """

    def __init__(self, written):
        self.path = written["video"]
        self.poster = written["poster"]
        self.captions = written["captions"]
        self.chapters = written["chapters"]
        self.checks = [list(pane) for pane in written["checks"]]

    def __repr__(self):
        return f"<impulse.Video {self.path}>"

    def __fspath__(self):
        return self.path

    def _repr_html_(self):
        # Everything inline (data: URLs), so that the notebook shows it wherever it is opened.
        poster = f' poster="{_data_url(self.poster, "image/png")}"' if self.poster else ""
        tracks = ""
        if self.captions:
            tracks += (f'<track kind="captions" label="captions" srclang="en" default '
                       f'src="{_data_url(self.captions, "text/vtt")}">')
        if self.chapters:
            tracks += f'<track kind="chapters" srclang="en" src="{_data_url(self.chapters, "text/vtt")}">'
        name = os.path.basename(self.path)
        return (f'<video controls muted playsinline style="max-width: 100%"{poster} title="{name}">'
                f'<source src="{_data_url(self.path, "video/mp4")}" type="video/mp4">{tracks}</video>')
