"""cooperage.mesh() / run() / plan() and the Mesh arrays, checked against
geometry and against the command line (the C++ result)."""

import gc
import json
import os
import re
import threading
import time

import numpy
import pytest

import cooperage
from conftest import BRICK
from mesh_volume import HEX_TETS, WEDGE_TETS, total_volume


def cli_totals(stdout):
    """The 'nodes N, hexes H, wedges W, quads Q, triangles T' line of a run."""
    m = re.search(r"nodes (\d+), hexes (\d+), wedges (\d+), quads (\d+), triangles (\d+)", stdout)
    assert m, stdout
    return tuple(int(g) for g in m.groups())


def test_brick_counts_volume_and_quality_match_geometry_and_the_cli(journal, cli):
    job = journal(BRICK)
    mesh = cooperage.run(job)
    # 1 x 2 x 3 at size 0.5: 2 x 4 x 6 cubes on 3 x 5 x 7 nodes.
    assert mesh.points.shape == (105, 3)
    assert mesh.points.dtype == numpy.float64
    hexes = mesh.cells["hexahedron"]
    assert hexes.shape == (48, 8) and hexes.dtype == numpy.int64
    assert total_volume(mesh.points, hexes, HEX_TETS) == pytest.approx(6.0, rel=1e-12)
    assert numpy.allclose(mesh.quality()["hexahedron"], 1.0)
    # Every node inside the box, every corner of it a node.
    assert mesh.points.min(axis=0) == pytest.approx([0, 0, 0])
    assert mesh.points.max(axis=0) == pytest.approx([1, 2, 3])
    # The six sides: 2*(2*4 + 2*6 + 4*6) = 88 boundary quads.
    assert mesh.cells["quad"].shape == (88, 4)
    r = cli("run", job, "-q")
    assert r.returncode == 0, r.stderr
    assert cli_totals(r.stdout) == (105, 48, 0, 88, 0)


def test_mesh_of_a_cad_file_equals_the_cli_mesh(cli, source_dir, tmp_path):
    meshio = pytest.importorskip("meshio")
    part = os.path.join(source_dir, "examples", "part.step")
    mesh = cooperage.mesh(part, size=2)
    out = tmp_path / "cli.vtu"
    r = cli("mesh", part, "--size", 2, "-o", out, "-q")
    assert r.returncode == 0, r.stderr
    nodes, hexes, wedges, quads, tris = cli_totals(r.stdout)
    assert len(mesh.points) == nodes
    assert len(mesh.cells["hexahedron"]) == hexes
    assert "wedge" not in mesh.cells and wedges == 0
    assert len(mesh.cells["quad"]) == quads
    # The same nodes and hexes, read from the command line's file by meshio.
    theirs = meshio.read(out)
    assert numpy.array_equal(theirs.points, mesh.points)
    assert numpy.array_equal(theirs.cells_dict["hexahedron"], mesh.cells["hexahedron"])
    # The hexes fill the solid: the CAD volume from `cooperage info`.
    info = json.loads(cli("info", part, "--json").stdout)
    cad = sum(v["volume"] for v in info["volumes"])
    assert total_volume(mesh.points, mesh.cells["hexahedron"], HEX_TETS) == pytest.approx(cad, rel=5e-3)
    assert (mesh.quality()["hexahedron"] > 0).all()


def test_size_as_the_diagonal_over_n(cli, source_dir):
    """size="D/N" is the bounding-box diagonal (from `cooperage info`) over N."""
    part = os.path.join(source_dir, "examples", "part.step")
    info = json.loads(cli("info", part, "--json").stdout)
    lo = numpy.min([v["box_min"] for v in info["volumes"]], axis=0)
    hi = numpy.max([v["box_max"] for v in info["volumes"]], axis=0)
    diagonal = float(numpy.linalg.norm(hi - lo))
    relative = cooperage.mesh(part, "D/20")
    absolute = cooperage.mesh(part, size=diagonal / 20)
    assert relative.points.shape == absolute.points.shape
    assert numpy.allclose(relative.points, absolute.points, rtol=0, atol=1e-9 * diagonal)
    assert numpy.array_equal(relative.cells["hexahedron"], absolute.cells["hexahedron"])
    plan = cooperage.plan(part, size="D/20")
    assert plan[0]["entity"] == "volume 1" and plan[0]["scheme"] != "none"


def test_arrays_survive_the_mesh_and_points_are_a_read_only_view(journal):
    mesh = cooperage.run(journal(BRICK))
    points, hexes = mesh.points, mesh.cells["hexahedron"]
    again = mesh.points
    assert numpy.shares_memory(points, again), "points view the mesh's own nodes"
    copies = points.copy(), hexes.copy()
    with pytest.raises(ValueError):
        points[0, 0] = 1.0
    with pytest.raises(ValueError):
        hexes[0, 0] = 1
    del mesh, again
    gc.collect()
    junk = [numpy.full(10000, 7.0) for _ in range(50)]  # reuse freed memory, if any
    assert numpy.array_equal(points, copies[0])
    assert numpy.array_equal(hexes, copies[1])
    del junk


def test_cell_sets_cover_every_cell_once(journal):
    mesh = cooperage.run(journal("""\
        <geometry>
          <brick name="a" origin="0 0 0" size="1 1 1"/>
          <brick name="b" origin="1 0 0" size="1 1 1"/>
        </geometry>
        <mesh size="0.5"/>
        """))
    sets = mesh.cell_sets
    assert set(k for k in sets if k.startswith("volume")) == {"volume 1", "volume 2"}
    for kind, cells in mesh.cells.items():
        indices = numpy.concatenate([s[kind] for s in sets.values() if kind in s])
        assert numpy.array_equal(numpy.sort(indices), numpy.arange(len(cells))), kind
    # Conformal: the two cubes share the 9 nodes of their common face.
    a = set(mesh.cells["hexahedron"][sets["volume 1"]["hexahedron"]].ravel())
    b = set(mesh.cells["hexahedron"][sets["volume 2"]["hexahedron"]].ravel())
    assert len(a & b) == 9


def test_quality_per_cell_type(journal):
    mesh = cooperage.run(journal("""\
        <geometry><brick name="b" size="2 1 1"/></geometry>
        <mesh size="0.25"><volume id="1" elements="wedge"/></mesh>
        """))
    sj = mesh.quality("scaled_jacobian")
    assert set(sj) == set(mesh.cells)
    for kind, values in sj.items():
        assert len(values) == len(mesh.cells[kind])
        assert (values > 0).all() and (values <= 1 + 1e-12).all()
    assert "wedge" not in mesh.quality("skew"), "skew is not defined for wedges"
    assert total_volume(mesh.points, mesh.cells["wedge"], WEDGE_TETS) == pytest.approx(2.0, rel=1e-9)
    with pytest.raises(cooperage.InputError, match="unknown quality metric \"nope\""):
        mesh.quality("nope")


def test_write_every_format_and_the_report(journal, tmp_path):
    mesh = cooperage.run(journal(BRICK))
    for ext in ("exo", "msh", "vtu", "inp", "obj", "off", "stl", "ply"):
        path = tmp_path / f"brick.{ext}"
        mesh.write(path)
        assert path.stat().st_size > 0
    mesh.report(tmp_path / "brick.html")
    html = (tmp_path / "brick.html").read_text()
    assert "<canvas class=\"mesh\"" in html and "<b>48</b> hexes" in html
    with pytest.raises(cooperage.InputError):
        mesh.write(tmp_path / "brick.step")
    assert not (tmp_path / "brick.step").exists()
    assert sorted(p.name for p in tmp_path.iterdir() if ".tmp-" in p.name) == []


def test_write_keeps_the_journals_blocks_and_sets(journal, tmp_path):
    meshio = pytest.importorskip("meshio")
    mesh = cooperage.run(journal(BRICK + '<block id="7" name="steel" volumes="1"/>\n'
                                 '<nodeset id="3" name="base" vertices="1"/>\n'))
    mesh.write(tmp_path / "b.inp")
    m = meshio.read(tmp_path / "b.inp")
    assert sum(len(c) for c in m.cell_sets["steel"]) == len(mesh.cells["hexahedron"]) == 48
    assert list(m.point_sets) == ["base"] and len(m.point_sets["base"]) == 1


def test_run_result_plan_stages_and_written_files(journal, tmp_path):
    job = journal(BRICK + '<export file="b.vtu"/>\n<report file="b.html"/>\n')
    mesh = cooperage.run(job)
    assert mesh.written == [str(tmp_path / "b.vtu"), str(tmp_path / "b.html")]
    assert all(os.path.exists(f) for f in mesh.written)
    assert mesh.warnings == []
    assert list(mesh.stages)[:2] == ["geometry", "plan"] and "exports" in mesh.stages
    assert all(t >= 0 for t in mesh.stages.values())
    volumes = [p for p in mesh.plan if p["dim"] == 3]
    assert volumes == [{"entity": "volume 1", "dim": 3, "id": 1, "scheme": "map",
                        "reason": volumes[0]["reason"], "details": volumes[0]["details"]}]
    assert any(d.startswith("+ map") for d in volumes[0]["details"])
    assert mesh.source == str(job)
    assert "48 hexahedra" in repr(mesh)


def test_plan_dim_two_plans_the_surfaces_as_plan_dim_two(cli, source_dir):
    part = os.path.join(source_dir, "examples", "part.step")
    plan = cooperage.plan(part, size=2, dim=2)
    ours = json.loads(cli("plan", part, "--json", "--size", 2, "--dim", 2).stdout)
    assert [r["dim"] for r in plan] == [2] * len(ours["surfaces"]) and ours["volumes"] == []
    assert [(r["id"], r["scheme"], r["reason"]) for r in plan] == \
        [(c["id"], c["scheme"], c["reason"]) for c in ours["surfaces"]]
    assert all(r["scheme"] != "(volume)" for r in plan), "no volume meshes a surface in 2D"
    with pytest.raises(cooperage.InputError):
        cooperage.plan(part, size=2, dim=1)


def test_plan_refuses_the_sizes_mesh_refuses(cli, source_dir):
    # A size in the wrong unit: refused before planning, as mesh() refuses it.
    part = os.path.join(source_dir, "examples", "part.step")
    with pytest.raises(cooperage.InputError) as e:
        cooperage.plan(part, size=1e-7)
    assert "the mesh would have about" in str(e.value)
    refused = cli("plan", part, "--size", 1e-7)
    assert refused.returncode == 2 and str(e.value) in refused.stderr


def test_plan_matches_plan_json(journal, cli, source_dir):
    part = os.path.join(source_dir, "examples", "part.step")
    # fig3a_auto needs a cut: plan() decomposes as `cooperage plan` does.
    fig3a = os.path.join(source_dir, "examples", "fig3a_auto.xml")
    plans = {}
    for model, size in ((journal(BRICK), None), (fig3a, None), (part, 2)):
        plan = plans[model] = cooperage.plan(model, size=size)
        args = ["plan", model, "--json"] + (["--size", size] if size else [])
        ours = json.loads(cli(*args).stdout)
        theirs = [("volume", c) for c in ours["volumes"]] + [("surface", c) for c in ours["surfaces"]]
        assert len(plan) == len(theirs)
        for row, (kind, c) in zip(plan, theirs):
            assert row["entity"] == f"{kind} {c['id']}"
            assert row["dim"] == (3 if kind == "volume" else 2) and row["id"] == c["id"]
            assert (row["scheme"], row["reason"], row["pinned"]) == (c["scheme"], c["reason"], c["pinned"])
            assert [(k["scheme"], k["ok"], k["why"]) for k in row["candidates"]] == \
                [(k["scheme"], k["ok"], k["why"]) for k in c["candidates"]]
            chosen = [k["score"] for k in c["candidates"] if k["scheme"] == c["scheme"]]
            assert row["score"] == (chosen[0] if chosen else None)
    assert len([r for r in plans[fig3a] if r["dim"] == 3]) >= 2, "fig3a is planned as its pieces"
    plan = plans[part]
    assert len(plan) == 2 + 10 and [r["scheme"] for r in plan[:2]] == ["cooper", "cooper"]
    assert any(r["scheme"] == "(volume)" and r["score"] is None for r in plan), \
        "a surface its volume meshes has no score of its own"


def test_mesh_dim_2_is_a_surface_mesh(source_dir):
    mesh = cooperage.mesh(os.path.join(source_dir, "examples", "part.step"), size=4, dim=2)
    assert set(mesh.cells) <= {"quad", "triangle"} and "quad" in mesh.cells
    assert (mesh.quality()["quad"] > 0).all()


def test_the_gil_is_released_while_meshing(journal):
    # The run must be long enough to tell a stall from scheduling noise; a
    # fast machine needs a finer size, so refine until it is.
    for divisions in (50, 80, 100, 125):
        job = journal(f"""\
            <geometry><brick name="b" size="1 1 1"/></geometry>
            <mesh size="{1.0 / divisions}"/>
            """)
        done = threading.Event()
        box = {}

        def work():
            start = time.perf_counter()
            box["mesh"] = cooperage.run(job, threads=1)
            box["seconds"] = time.perf_counter() - start
            done.set()

        thread = threading.Thread(target=work)
        thread.start()
        last, longest = time.perf_counter(), 0.0
        while not done.is_set():
            now = time.perf_counter()
            longest, last = max(longest, now - last), now
            time.sleep(0.001)
        thread.join()
        assert len(box["mesh"].cells["hexahedron"]) == divisions ** 3
        if box["seconds"] > 0.3:
            break
    assert box["seconds"] > 0.3, "even the finest run is too short to tell"
    # Holding the GIL would stall this loop for the whole run.
    assert longest < 0.5 * box["seconds"], (longest, box["seconds"])


def fig3a_step(path):
    """The paper's Fig. 3a part as STEP (Gmsh's OpenCASCADE kernel): a 4 x 4 x 2
    block with a boss on top of its front half and one on the +x face of its
    back half; no single sweep takes it (volume 34)."""
    gmsh = pytest.importorskip("gmsh")
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        occ = gmsh.model.occ
        block = occ.addBox(0, 0, 0, 4, 4, 2)
        up = occ.addBox(1, 0.5, 2, 1, 1, 1)
        out = occ.addBox(4, 2.5, 0.5, 1, 1, 1)
        occ.fuse([(3, block)], [(3, up), (3, out)])
        occ.synchronize()
        gmsh.write(str(path))
    finally:
        gmsh.finalize()
    return path


def test_decompose_cuts_a_part_no_scheme_takes_whole(tmp_path):
    step = fig3a_step(tmp_path / "fig3a.step")
    mesh = cooperage.mesh(step, size=0.25)
    assert mesh.decomposition, "not cut"
    assert any("cut into volumes" in line for line in mesh.decomposition)
    hexes = mesh.cells["hexahedron"]
    assert len(hexes) > 0
    # The pieces fill the part: their hexes sum to its volume.
    assert total_volume(mesh.points, hexes, HEX_TETS) == pytest.approx(34, rel=1e-9)
    with pytest.raises(cooperage.Error, match="volume 1: no hex scheme applies"):
        cooperage.mesh(step, size=0.25, decompose="off")


def test_min_scaled_jacobian_is_a_failing_check(source_dir):
    part = os.path.join(source_dir, "examples", "part.step")
    kept = cooperage.mesh(part, size=2, min_scaled_jacobian=0.0)
    [check] = kept.checks
    assert (check["metric"], check["min"], check["action"]) == ("scaled_jacobian", 0.0, "fail")
    assert not check["failed"] and check["violations"] == 0
    strict = cooperage.mesh(part, size=2, min_scaled_jacobian=0.9999, finer_retries=0)
    [check] = strict.checks
    assert check["failed"] and check["violations"] > 0


def test_plan_takes_the_options_of_mesh(journal, cli, source_dir):
    part = os.path.join(source_dir, "examples", "part.step")
    for kwargs, flags in (({"imprint": False}, ["--no-imprint"]),
                          ({"elements": "wedge"}, ["--elements", "wedge"]),
                          ({"decompose": "off"}, ["--decompose", "off"])):
        plan = cooperage.plan(part, size=2, **kwargs)
        ours = json.loads(cli("plan", part, "--json", "--size", 2, *flags).stdout)
        theirs = [("volume", c) for c in ours["volumes"]] + [("surface", c) for c in ours["surfaces"]]
        assert [(r["entity"], r["scheme"], r["reason"]) for r in plan] == \
            [(f"{kind} {c['id']}", c["scheme"], c["reason"]) for kind, c in theirs], kwargs
    wedges = cooperage.plan(part, size=2, elements="wedge")
    assert all(k["scheme"] != "map" for r in wedges if r["dim"] == 3 for k in r["candidates"])
    with pytest.raises(cooperage.InputError):
        cooperage.plan(part, size=2, elements="tet")
    with pytest.raises(cooperage.InputError):
        cooperage.plan(part, size=2, decompose="yes")
    with pytest.raises(cooperage.InputError, match="imprint is for a CAD file"):
        cooperage.plan(journal(BRICK), imprint=False)
    with pytest.raises(cooperage.InputError):
        cooperage.mesh(part, 2, decompose="yes")


def test_wedges_asked_of_a_surface_mesh_are_an_input_error(source_dir):
    part = os.path.join(source_dir, "examples", "part.step")
    for kind in ("wedge", "mixed"):
        with pytest.raises(cooperage.InputError, match="asks for volume elements"):
            cooperage.mesh(part, 2, dim=2, elements=kind)
        with pytest.raises(cooperage.InputError, match="asks for volume elements"):
            cooperage.plan(part, size=2, dim=2, elements=kind)
