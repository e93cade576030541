"""Checks an executed demos/notebooks/workshop.ipynb (nbconvert --execute ran it in a real
kernel): every cell ran without an error, and its outputs are what the cells promise: the trace's
numbers, a matplotlib figure, videos and a scene's page shown inline, and listing 1 in Python passing
the grade.

    python3 tests/python/check_notebook.py EXECUTED.ipynb
"""

import base64
import gzip
import html
import json
import re
import sys

import nbformat


def main(path):
    notebook = nbformat.read(path, as_version=4)
    code = [cell for cell in notebook.cells if cell.cell_type == "code"]
    outputs = [output for cell in code for output in cell.get("outputs", [])]
    errors = [output for output in outputs if output.output_type == "error"]
    assert not errors, "a cell raised: %s" % errors[0].get("ename")
    assert all(cell.get("execution_count") for cell in code), "a cell did not run"

    data = [output.get("data", {}) for output in outputs]
    text = "".join(output.get("text", "") for output in outputs) + "".join(d.get("text/plain", "") for d in data)
    figures = [d["image/png"] for d in data if "image/png" in d]
    assert figures, "no figure: the speed plot is missing"
    videos = [d["text/html"] for d in data if d.get("text/html", "").startswith("<video")]
    assert len(videos) == 2, "expected the comparison and the student's bounce as videos, got %d" % len(videos)
    for video in videos:
        assert 'src="data:video/mp4;base64,' in video and 'poster="data:image/png;base64,' in video
    pages = [d["text/html"] for d in data if d.get("text/html", "").startswith("<iframe")]
    assert len(pages) == 1, "expected the friction scene's page inline, got %d" % len(pages)
    assert 'sandbox="allow-scripts"' in pages[0] and "impulse-run" in pages[0]
    packed = re.search(r'<script id="impulse-run" type="application/gzip;base64">([^<]*)</script>', html.unescape(pages[0]))
    run = json.loads(gzip.decompress(base64.b64decode(packed.group(1))))
    panes = run.get("panes", [run])  # the file's [compare]: its panes, as export shows them
    assert all("sliding box" in [body["name"] for body in pane["bodies"]] for pane in panes), "the page holds the scene's bodies"
    assert "<impulse.Trace of ex1_friction" in text
    match = re.search(r"after [\d.]+ s: ([\d.]+) m/s with friction, ([\d.]+) m/s without", text)
    assert match and float(match.group(1)) < float(match.group(2)), "friction must slow the box: " + str(match)
    match = re.search(r"impulse grade add_collision_impulse\(\): (\d+) of (\d+) cases pass", text)
    assert match and match.group(1) == match.group(2), "listing 1 in Python must pass every case: " + str(match)
    print("%s: %d cells ran; a figure, %d videos, a page, every grade case passed" % (path, len(code), len(videos)))


if __name__ == "__main__":
    main(sys.argv[1])
