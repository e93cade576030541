"""A scene's interactive page (``impulse export``'s HTML), shown inline in Jupyter."""

import html
import os


class Page:
    """The one HTML file ``Scene.view`` wrote: the scene's run and its three.js viewer (play,
    scrub, orbit), which opens offline in any browser and shows inline in a notebook.

    path   the .html
    """

    def __init__(self, path):
        self.path = path

    def __repr__(self):
        return f"<impulse.Page {self.path}>"

    def __fspath__(self):
        return self.path

    def _repr_html_(self):
        # The page itself, inline (srcdoc), so that the notebook shows it wherever it is opened; in
        # a frame of its own that may run scripts and nothing else.
        with open(self.path, encoding="utf-8") as file:
            page = file.read()
        name = html.escape(os.path.basename(self.path))
        return (f'<iframe title="{name}" sandbox="allow-scripts" style="width: 100%; height: 540px; border: 0" '
                f'srcdoc="{html.escape(page, quote=True)}"></iframe>')
