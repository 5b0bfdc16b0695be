"""Errors are Python exceptions with the command line's one-line messages:
cooperage.InputError for its exit-code-2 cases, and no file is left behind."""

import os

import pytest

import cooperage
from conftest import BRICK


def cli_message(result):
    """The message of 'cooperage: error: <message>' on stderr."""
    line = [l for l in result.stderr.splitlines() if l.startswith("cooperage: error: ")]
    assert line, result.stderr
    return line[-1][len("cooperage: error: "):]


def test_exception_classes():
    assert issubclass(cooperage.InputError, cooperage.Error)
    assert issubclass(cooperage.MeshingError, cooperage.Error)
    assert not issubclass(cooperage.MeshingError, cooperage.InputError)
    assert issubclass(cooperage.Error, RuntimeError)


def test_missing_cad_file_has_the_cli_message(cli, tmp_path):
    missing = tmp_path / "missing.step"
    with pytest.raises(cooperage.InputError) as e:
        cooperage.mesh(missing, size=1)
    r = cli("mesh", missing, "--size", 1, "-o", tmp_path / "x.exo")
    assert r.returncode == 2
    assert str(e.value).startswith(cli_message(r))  # the CLI may put long details on a second line
    assert e.value.code == "file not found"
    assert "missing.step" in str(e.value)


def test_malformed_journal_has_the_cli_message_and_line(cli, journal):
    job = journal("<geometry>\n<brick name=\"b\" size=\"1 1 1\">\n</geometry>\n")
    with pytest.raises(cooperage.InputError) as e:
        cooperage.run(job)
    r = cli("run", job)
    assert r.returncode == 2
    assert str(e.value).startswith(cli_message(r))  # the CLI may put long details on a second line
    assert e.value.code == "parse error"
    assert "job.xml:" in str(e.value)


def test_bad_arguments_are_input_errors(source_dir, journal):
    part = os.path.join(source_dir, "examples", "part.step")
    with pytest.raises(cooperage.InputError, match="size must be positive"):
        cooperage.mesh(part, size=0)
    with pytest.raises(cooperage.InputError, match="elements must be"):
        cooperage.mesh(part, size=1, elements="tet")
    with pytest.raises(cooperage.InputError, match="dim must be"):
        cooperage.mesh(part, size=1, dim=1)
    with pytest.raises(cooperage.InputError, match="threads"):
        cooperage.mesh(part, size=1, threads=-1)
    with pytest.raises(cooperage.InputError, match="finer_retries must be 0 to 4, got 5"):
        cooperage.mesh(part, size=1, finer_retries=5)
    with pytest.raises(cooperage.InputError, match="min_scaled_jacobian must be from -1 to 1, got 2"):
        cooperage.mesh(part, size=1, min_scaled_jacobian=2)
    with pytest.raises(cooperage.InputError, match='decompose must be "auto" or "off"'):
        cooperage.mesh(part, size=1, decompose="yes")
    with pytest.raises(cooperage.InputError, match="cooperage.run"):
        cooperage.mesh(journal(BRICK), size=1)
    with pytest.raises(cooperage.InputError, match="no <mesh> element"):
        cooperage.run(journal('<geometry><brick name="b" size="1 1 1"/></geometry>\n'))
    with pytest.raises(cooperage.InputError, match="size must be positive"):
        cooperage.plan(part, size=-1)
    with pytest.raises(cooperage.InputError, match='size must be a positive number or "D/N"'):
        cooperage.mesh(part, size="D/0")
    with pytest.raises(cooperage.InputError, match='size must be a positive number or "D/N"'):
        cooperage.plan(part, size="2mm")
    with pytest.raises(TypeError):
        cooperage.mesh(part)  # size is required


def test_error_names_the_entity(journal, cli):
    job = journal("""\
        <geometry><cylinder name="c" radius="1" height="1"/></geometry>
        <mesh size="0.5"><volume id="1" scheme="map"/></mesh>
        """)
    with pytest.raises(cooperage.InputError) as e:
        cooperage.run(job)
    assert e.value.code == "not applicable"
    assert e.value.entity == (3, 1)
    assert str(e.value).startswith("volume 1: map pinned at ")
    r = cli("run", job)
    assert r.returncode == 2 and str(e.value).startswith(cli_message(r))


def test_failed_run_writes_no_file(journal, tmp_path):
    job = journal("""\
        <geometry><import name="p" file="nowhere.step"/></geometry>
        <mesh size="1"/>
        <export file="out.exo"/>
        <report file="out.html"/>
        """)
    with pytest.raises(cooperage.InputError):
        cooperage.run(job)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["job.xml"]


def test_unwritable_report_raises_and_leaves_nothing(journal, tmp_path):
    mesh = cooperage.run(journal(BRICK))
    with pytest.raises(cooperage.InputError) as e:
        mesh.report(tmp_path / "no" / "such" / "dir" / "r.html")
    assert e.value.code == "file not found"
    assert not (tmp_path / "no").exists()
