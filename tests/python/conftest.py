"""The package under test is build/python's (IMPULSE_BUILD: the build directory; the tests run
from the repository's root, where the scene files are)."""

import os
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("IMPULSE_BUILD", os.path.join(ROOT, "build"))
sys.path.insert(0, os.path.join(BUILD, "python"))
sys.path.insert(0, os.path.join(ROOT, "assets", "workshop"))  # listing1_corrected.py


@pytest.fixture
def root():
    return ROOT


@pytest.fixture
def program():
    return os.path.join(BUILD, "demos", "impulse")


@pytest.fixture(autouse=True)
def at_root(monkeypatch):
    monkeypatch.chdir(ROOT)
