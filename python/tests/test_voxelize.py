"""csgpix.voxelize against the command line's NRRD, slab ranges against the whole volume,
the models against each other, and errors with their place."""

import json
import os

import numpy as np
import pytest

import csgpix
from conftest import ROOT, SCENES, have, read_nrrd, run_cli


def cli_volume(tmp, *args):
    out = tmp / "v.nrrd"
    r = run_cli("voxelize", *args, "-o", str(out))
    assert r.returncode == 0, r.stderr.decode()
    head = out.read_bytes().partition(b"\n\n")[0].decode()
    fields = dict(l.split(": ", 1) for l in head.splitlines() if ": " in l)
    return read_nrrd(out), fields


def floats(text):
    return [float(x) for x in text.replace("(", " ").replace(")", " ").replace(",", " ").split()]


@pytest.mark.parametrize(
    "scene,args,kw",
    [
        ("figure-5.2.csg", ["--res", "40"], dict(res=40)),
        ("csg-logo.csg", ["--res", "24x20x16", "--model", "cycle"], dict(res=(24, 20, 16), model="cycle")),
        ("hollow-cube.csg", ["--voxel", "0.5", "--pad", "2", "--sampling", "slab"],
         dict(voxel=0.5, pad=2, sampling="slab")),
        ("figure-5.6.csg", ["--res", "32", "--grey"], dict(res=32, grey=True)),
        ("twelve.csg", ["--res", "30", "--eval", "tree", "--model", "float"],
         dict(res=30, eval="tree", model="float")),
    ],
)
def test_voxelize_equals_the_command_lines_nrrd(tmp, scene, args, kw):
    want, fields = cli_volume(tmp, str(SCENES / scene), *args)
    vol = csgpix.voxelize(str(SCENES / scene), **kw)
    assert vol.data.dtype == np.uint8 and vol.data.shape == want.shape
    assert np.array_equal(vol.data, want)
    assert vol.dims == tuple(reversed(want.shape))
    assert np.allclose(vol.origin, floats(fields["space origin"]))
    d = floats(fields["space directions"])
    assert np.allclose(vol.spacing, (d[0], d[4], d[8]))
    assert (vol.data > 0).any(), "a scene with solids fills voxels"


@pytest.mark.parametrize("z", [(0, 1), (5, 17), (17, 40), (39, 40), (12, 12)])
def test_a_slab_range_is_those_slabs_of_the_whole_volume(z):
    scene = csgpix.load(SCENES / "csg-logo.csg")
    whole = csgpix.voxelize(scene, 40)
    part = csgpix.voxelize(scene, 40, z=z)
    assert part.z == z and part.dims == whole.dims
    assert part.origin == whole.origin and part.spacing == whole.spacing
    assert np.array_equal(part.data, whole.data[z[0]:z[1]])


def test_the_models_agree():
    scene = csgpix.load(SCENES / "figure-5.2.csg")
    word = csgpix.voxelize(scene, 24).data
    assert np.array_equal(csgpix.voxelize(scene, 24, model="cycle").data, word)
    assert np.array_equal(csgpix.voxelize(scene, 24, route="array").data, word)
    for ev in ("tree", "stack"):
        assert np.array_equal(csgpix.voxelize(scene, 24, eval=ev).data, word)


@pytest.mark.parametrize("route", ["runs", "intervals"])
def test_progress_counts_up_to_its_total(route):
    scene = csgpix.load(SCENES / "csg-logo.csg")
    calls = []
    vol = csgpix.voxelize(scene, 24, route=route, progress=lambda d, t: calls.append((d, t)))
    assert np.array_equal(vol.data, csgpix.voxelize(scene, 24, route=route).data)
    totals = {t for _, t in calls}
    assert len(totals) == 1 and totals.pop() > 0
    done = [d for d, _ in calls]
    assert done == sorted(done) and done[-1] == calls[-1][1]


def test_an_exception_in_progress_is_raised_after_the_run():
    def fail(done, total):
        raise ValueError(f"stop at {done}")

    with pytest.raises(ValueError, match="stop at"):
        csgpix.voxelize(csgpix.load(SCENES / "figure-5.2.csg"), 16, progress=fail)


def test_an_expression_over_files(tmp):
    # A dataset minus a box scene: the same as the command line's --expr run.
    prims = [("head", (str(SCENES / "phantom.nrrd"), 300.0)), ("box", str(SCENES / "figure-5.2.csg"))]
    scene = csgpix.load_expr("head - box", prims)
    vol = csgpix.voxelize(scene, 32)
    want, _ = cli_volume(
        tmp, "--expr", "head - box", "--prim", f"head={SCENES / 'phantom.nrrd'},threshold=300",
        "--prim", f"box={SCENES / 'figure-5.2.csg'}", "--res", "32",
    )
    assert np.array_equal(vol.data, want)
    assert scene.primitives == 5


def test_an_expression_with_a_mesh(tmp):
    # A closed mesh written by the command line (Marching Cubes of a voxelized scene), bound
    # by name: the same voxels as the command line's --prim.
    r = run_cli("voxelize", str(SCENES / "hollow-cube.csg"), "--res", "12", "--mesh",
                str(tmp / "part.stl"), "-o", str(tmp / "part.nrrd"))
    assert r.returncode == 0, r.stderr.decode()
    prims = [("box", str(SCENES / "figure-5.2.csg")), ("part", str(tmp / "part.stl"))]
    vol = csgpix.voxelize(csgpix.load_expr("box + part", prims), 24)
    want, _ = cli_volume(tmp, "--expr", "box + part", "--prim", f"box={SCENES / 'figure-5.2.csg'}",
                         "--prim", f"part={tmp / 'part.stl'}", "--res", "24")
    assert np.array_equal(vol.data, want) and (vol.data > 0).any()


def test_a_scad_file_goes_through_openscad(tmp):
    if not have("openscad"):
        if os.environ.get("CSGPIX_OPENSCAD") == "require":
            pytest.fail("CSGPIX_OPENSCAD=require but openscad is not installed")
        pytest.skip("openscad is not installed")
    scad = SCENES / "extrusions.scad"
    want, _ = cli_volume(tmp, str(scad), "--voxel", "0.5", "--pad", "1")
    vol = csgpix.voxelize(csgpix.load(scad), voxel=0.5, pad=1)
    assert np.array_equal(vol.data, want) and (vol.data > 0).any()


def test_openscad_is_stopped_at_openscad_timeout(tmp, monkeypatch):
    """A fake openscad first on PATH that sleeps: load and compile stop it at the limit
    (the command line's default unless given), in a one-line error naming the keyword."""
    fake = tmp / "bin" / "openscad"
    fake.parent.mkdir()
    fake.write_text("#!/bin/sh\nexec sleep 600\n")
    fake.chmod(0o755)
    monkeypatch.setenv("PATH", f"{fake.parent}:{os.environ['PATH']}")
    scad = tmp / "slow.scad"
    scad.write_text("cube(1);\n")
    for call in (lambda: csgpix.load(scad, openscad_timeout=0.5),
                 lambda: csgpix.compile(str(scad), openscad_timeout=0.5)):
        with pytest.raises(csgpix.CsgpixError) as e:
            call()
        assert str(e.value) == f"{scad}: openscad did not finish within 0.5 s (openscad_timeout=)"
    with pytest.raises(csgpix.CsgpixError, match="openscad_timeout=-1"):
        csgpix.load(scad, openscad_timeout=-1)


def test_errors_carry_file_line_and_column(tmp):
    bad = ROOT / "tests" / "data" / "identity" / "bad.csg"
    with pytest.raises(csgpix.CsgpixError) as e:
        csgpix.load(bad)
    err = e.value
    assert (err.file, err.line) == (str(bad), 3) and err.col > 0
    assert str(e.value).startswith(f"{bad}:3:{err.col}: ")
    # The same words as the command line (which adds nothing to a scene error).
    r = run_cli("voxelize", str(bad), "--res", "8", "-o", str(tmp / "x.nrrd"))
    assert r.returncode == 2 and r.stderr.decode().strip().endswith(str(e.value))
    assert not (tmp / "x.nrrd").exists()


def test_a_missing_file_is_file_not_found(tmp):
    missing = tmp / "missing.csg"
    with pytest.raises(FileNotFoundError) as e:
        csgpix.load(missing)
    assert str(e.value).startswith(f"{missing}: ") and "\n" not in str(e.value)
    with pytest.raises(FileNotFoundError):
        csgpix.load_expr("a", [("a", str(tmp / "missing.stl"))])
    with pytest.raises(IsADirectoryError):
        csgpix.load(tmp)
    # The same words as the command line.
    r = run_cli("voxelize", str(missing), "--res", "8", "-o", str(tmp / "x.nrrd"))
    assert r.returncode == 2 and r.stderr.decode().strip().endswith(str(e.value))


@pytest.mark.parametrize(
    "call,words",
    [
        (lambda s: csgpix.voxelize(s), "give res or voxel"),
        (lambda s: csgpix.voxelize(s, (8, 8, 8), z=(3, 9)), "z=(3, 9): the grid has slabs 0..8"),
        (lambda s: csgpix.voxelize(s, 8, model="quantum"), "quantum"),
        (lambda s: csgpix.voxelize(s, 8, sampling="corner"), "sampling \"corner\""),
        (lambda s: csgpix.voxelize(s, 8, word="3/3"), "FRACTION/INTEGER/OVERFLOW"),
        (lambda s: csgpix.voxelize(s, (0, 4, 4)), "every side needs at least one voxel"),
        (lambda s: csgpix.load_expr("a + b", [("a", str(SCENES / "figure-5.2.csg"))]), "`b`"),
    ],
)
def test_bad_arguments_are_one_line_errors(call, words):
    scene = csgpix.load(SCENES / "figure-5.2.csg")
    with pytest.raises(csgpix.CsgpixError) as e:
        call(scene)
    assert words in str(e.value) and "\n" not in str(e.value)
    assert e.value.line is None or e.value.file is not None


def test_the_volume_is_an_array():
    vol = csgpix.voxelize(str(SCENES / "figure-5.2.csg"), 16)
    assert np.asarray(vol) is vol.data
    # figure-5.2 is 30 × 30 × 16 units: 16 voxels along its longest sides, 9 along Z.
    assert vol.shape == vol.data.shape == (9, 16, 16) and vol.dtype == np.uint8
    assert vol.dims == (16, 16, 9)
    i, j, k = 3, 4, 5
    assert np.allclose(vol.centre(i, j, k), np.add(vol.origin, np.multiply((i, j, k), vol.spacing)))


def test_a_run_over_the_memory_limit_is_refused_before_it_allocates():
    scene = csgpix.load(SCENES / "figure-5.2.csg")
    with pytest.raises(csgpix.CsgpixError, match=r"needs about \d+ MiB, over max_memory 16"):
        csgpix.voxelize(scene, 1024, max_memory=16)
    # A slab range holds its slabs only: the same grid fits in a few slabs.
    part = csgpix.voxelize(scene, (64, 64, 4096), z=(0, 2), max_memory=64)
    assert part.data.shape == (2, 64, 64)


def test_to_mesh_is_the_command_lines_mesh(tmp):
    """``Volume.to_mesh()`` is ``--mesh``'s surface: the same triangles and vertices, closed."""
    scene = SCENES / "figure-5.2.csg"
    obj = tmp / "m.obj"
    r = run_cli("voxelize", str(scene), "--res", "24", "--mesh", str(obj), "--json",
                "-o", str(tmp / "v.nrrd"))
    assert r.returncode == 0, r.stderr
    report = json.loads(r.stdout)
    vertices, faces = csgpix.voxelize(str(scene), 24).to_mesh()
    assert vertices.dtype == np.float32 and faces.dtype == np.uint32
    assert faces.shape == (report["mesh_triangles"], 3)
    # Closed: every edge is in exactly two triangles, once each way.
    edges = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    directed = {tuple(e) for e in edges.tolist()}
    assert len(directed) == len(edges) and all((b, a) in directed for a, b in directed)
    lines = obj.read_text().splitlines()
    want = np.array([[float(x) for x in l.split()[1:4]] for l in lines if l.startswith("v ")])
    assert want.shape == vertices.shape
    assert np.allclose(np.sort(want, axis=0), np.sort(vertices, axis=0), atol=1e-4)
    # A slab range meshes the slabs it holds, in the same scene units.
    part = csgpix.voxelize(str(scene), 24, z=(0, 6)).to_mesh()[0]
    assert part[:, 2].max() < vertices[:, 2].max() and np.isclose(part[:, 2].min(), vertices[:, 2].min())


def test_warnings_are_python_warnings_and_strict_refuses(tmp_path):
    # A colour out of range: OpenSCAD warns and renders; so does csgpix (docs/volume-scenes.md).
    scene = ROOT / "vectors" / "openscad" / "lenient" / "colour.csg"
    with pytest.warns(UserWarning, match=r"colour\.csg:1:8: color\(\) expects") as caught:
        s = csgpix.load(str(scene))
    assert len(caught) == 4
    assert s.warnings == [str(w.message) for w in caught]
    # The same voxels as the command line, which prints the same lines.
    out = tmp_path / "c.nrrd"
    proc = run_cli("voxelize", str(scene), "--res", "16", "-o", str(out))
    assert proc.returncode == 0
    lines = proc.stderr.decode().splitlines()
    assert [l.removeprefix("csgpix: warning: ") for l in lines] == s.warnings
    vol = csgpix.voxelize(s, 16)
    np.testing.assert_array_equal(vol.data, read_nrrd(out))
    with pytest.raises(csgpix.CsgpixError, match=r"colour\.csg:1:8: color\(\) expects"):
        csgpix.load(str(scene), strict=True)
