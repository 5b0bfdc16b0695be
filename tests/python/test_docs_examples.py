"""The Python examples of README.md and docs/python.md run as written, from a
copy of the repository's examples (so their outputs stay out of the tree)."""

import os
import re
import shutil
import subprocess
import sys

import pytest


def python_blocks(path):
    text = open(path).read()
    return re.findall(r"```python\n(.*?)```", text, re.S)


@pytest.fixture
def root_copy(tmp_path, source_dir):
    """A directory that looks like the repository root for the examples."""
    os.mkdir(tmp_path / "examples")
    for name in os.listdir(os.path.join(source_dir, "examples")):
        if name.endswith((".xml", ".step")):
            shutil.copy(os.path.join(source_dir, "examples", name), tmp_path / "examples")
    return tmp_path


def run_block(code, cwd):
    r = subprocess.run([sys.executable, "-c", code], cwd=cwd, capture_output=True, text=True,
                       timeout=300, env=dict(os.environ))
    assert r.returncode == 0, r.stdout + r.stderr
    return r.stdout


def test_readme_example(root_copy, source_dir):
    blocks = python_blocks(os.path.join(source_dir, "README.md"))
    assert len(blocks) == 1 and len(blocks[0].strip().splitlines()) == 3, blocks
    run_block(blocks[0], root_copy)
    assert (root_copy / "part.exo").stat().st_size > 0
    assert "<canvas" in (root_copy / "part.html").read_text()


def test_python_guide_worked_example(root_copy, source_dir):
    blocks = python_blocks(os.path.join(source_dir, "docs", "python.md"))
    assert len(blocks) == 1
    out = run_block(blocks[0], root_copy)
    assert "scaled Jacobian min" in out and "refused:" in out and "file not found" in out
    for name in ("part.exo", "part.html", "part_meshio.vtu", "examples/bracket.exo",
                 "examples/bracket.html"):
        assert (root_copy / name).exists(), name
