"""Shared fixtures of the Python package tests: the cooperage command line
(to compare with), the source tree, and small journals written on the fly."""

import os
import subprocess
import textwrap

import pytest


@pytest.fixture(scope="session")
def cli():
    """Runs `cooperage ARGS...`; returns the CompletedProcess (text)."""
    path = os.environ.get("COOPERAGE_CLI")
    assert path and os.path.exists(path), "COOPERAGE_CLI must name the built cooperage command"

    def run(*args):
        return subprocess.run([path, *map(str, args)], capture_output=True, text=True, timeout=300)

    return run


@pytest.fixture(scope="session")
def source_dir():
    path = os.environ.get("COOPERAGE_SOURCE_DIR")
    assert path and os.path.isdir(path), "COOPERAGE_SOURCE_DIR must name the source tree"
    return path


@pytest.fixture
def journal(tmp_path):
    """Writes a journal whose <cooperage> element holds BODY; returns its path."""

    def write(body, name="job.xml"):
        path = tmp_path / name
        path.write_text('<cooperage version="1">\n' + textwrap.dedent(body) + "</cooperage>\n")
        return path

    return write


BRICK = """\
<geometry><brick name="b" origin="0 0 0" size="1 2 3"/></geometry>
<mesh size="0.5"/>
"""
