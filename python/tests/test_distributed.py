"""Zarr volumes: the command line's `--format zarr`, the Python writer and a Dask
LocalCluster of worker processes give byte-identical stores, which zarr-python reads as the
voxels csgpix.voxelize gives; a failed run leaves nothing behind."""

import filecmp
import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

import csgpix
import csgpix.distributed as cd
from conftest import SCENES, run_cli

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests" / "data"))
import read_zarr  # noqa: E402  (the downsample rule in numpy, shared with tests/zarr.rs)

zarr = pytest.importorskip("zarr", reason="zarr-python is not installed: pip install './python[test]'")
distributed = pytest.importorskip("distributed", reason="dask.distributed is not installed")


def files(root: Path):
    return sorted(str(p.relative_to(root)) for p in root.rglob("*") if p.is_file())


def assert_same_tree(a: Path, b: Path):
    assert files(a) == files(b)
    for f in files(a):
        assert filecmp.cmp(a / f, b / f, shallow=False), f


def cli_zarr(tmp: Path, scene: Path, *args: str) -> Path:
    out = tmp / "cli.zarr"
    r = run_cli("voxelize", str(scene), *args, "--format", "zarr", "-o", str(out))
    assert r.returncode == 0, r.stderr.decode()
    return out


@pytest.fixture(scope="module")
def client():
    from dask.distributed import Client, LocalCluster

    with LocalCluster(n_workers=3, threads_per_worker=1, processes=True, dashboard_address=None) as cl:
        with Client(cl) as c:
            yield c


@pytest.mark.parametrize(
    "scene,args,kw",
    [
        ("csg-logo.csg", ["--res", "48x40x50", "--chunk", "16x16x8"], dict(res=(48, 40, 50), chunk=(16, 16, 8))),
        ("figure-5.6.csg", ["--res", "40", "--grey", "--chunk", "7"], dict(res=40, grey=True, chunk=7)),
        # Sharded with a pyramid: each task writes its rows of every level.
        (
            "twelve.csg",
            ["--res", "44x40x36", "--chunk", "8x8x4", "--shard", "2", "--levels", "3"],
            dict(res=(44, 40, 36), chunk=(8, 8, 4), shard=2, levels=3),
        ),
        ("csg-logo.csg", ["--res", "30", "--chunk", "4", "--shard", "none", "--levels", "2"],
         dict(res=30, chunk=4, shard="none", levels=2)),
    ],
)
def test_dask_workers_write_the_command_lines_store(tmp_path, client, scene, args, kw):
    want = cli_zarr(tmp_path, SCENES / scene, *args)
    path = str(SCENES / scene)
    local = tmp_path / "local.zarr"
    rep = cd.voxelize_zarr(path, local, **kw)
    assert_same_tree(want, local)
    dist = tmp_path / "dask.zarr"
    rep2 = cd.voxelize_zarr(path, dist, client=client, **kw)
    # A task a brick: a chunk row of one XY tile (every tile at once off the run route).
    tiles = rep2["tiles"] if rep2["bricks"] else 1
    assert rep2["tasks"] == rep2["rows"] * tiles, rep2
    assert rep2["tasks"] > 3, "several tasks, on several workers"
    assert_same_tree(want, dist)
    assert rep2["filled"] == rep["filled"] > 0
    # zarr-python reads the voxels csgpix.voxelize gives, placed as the grid is.
    g = zarr.open_group(str(dist), mode="r")
    arr = g["0"]
    vol = csgpix.voxelize(path, kw["res"], grey=kw.get("grey", False))
    assert np.array_equal(arr[:], vol.data)
    ms = g.attrs["ome"]["multiscales"][0]
    tr = ms["datasets"][0]["coordinateTransformations"]
    scale = next(t["scale"] for t in tr if t["type"] == "scale")
    shift = next(t["translation"] for t in tr if t["type"] == "translation")
    assert np.allclose(scale, vol.spacing[::-1]) and np.allclose(shift, vol.origin[::-1])
    assert [a["name"] for a in ms["axes"]] == ["z", "y", "x"]
    # The pyramid: each level the rule's downsample of the one below (tests/data/read_zarr.py).
    assert rep2["levels"] == len(ms["datasets"]) == kw.get("levels", 1)
    level = vol.data
    for l in range(1, rep2["levels"]):
        level = read_zarr.downsample(level)
        assert np.array_equal(g[str(l)][:], level), f"level {l}"
    written = sum(1 for f in files(dist) if "/c/" in f)
    assert rep2["files_written"] == rep["files_written"] == written > 0


def test_rows_grouped_into_tasks_give_the_same_store(tmp_path, client):
    path = str(SCENES / "twelve.csg")
    a, b = tmp_path / "a.zarr", tmp_path / "b.zarr"
    cd.voxelize_zarr(path, a, 32, chunk=4, shard=2, levels=3)
    rep = cd.voxelize_zarr(path, b, 32, chunk=4, shard=2, levels=3, rows_per_task=3, client=client)
    # Tiles of 16 × 16 columns: level 2's shard is one 4 × 4 chunk, 16 × 16 of level 0.
    assert (rep["rows"], rep["tile"], rep["tiles"], rep["levels"]) == (8, [16, 16], 4, 3)
    assert rep["tasks"] == 3 * 4
    assert any(f.startswith("2/c/") for f in files(b)), "level 2 written by the tasks"
    assert_same_tree(a, b)


@pytest.mark.parametrize("rows_per_task,tiles_per_task,tasks", [(1, 1, 5 * 16), (3, 2, 2 * 8), (8, None, 1)])
def test_bricks_as_tasks_give_the_command_lines_store(tmp_path, client, rows_per_task, tiles_per_task, tasks):
    scene = SCENES / "csg-logo.csg"
    want = cli_zarr(tmp_path, scene, "--res", "60x52x40", "--chunk", "8x8x8", "--shard", "2", "--levels", "2")
    out = tmp_path / "bricks.zarr"
    rep = cd.voxelize_zarr(str(scene), out, (60, 52, 40), chunk=8, shard=2, levels=2, client=client,
                           rows_per_task=rows_per_task, tiles_per_task=tiles_per_task)
    # Tiles of 16 × 16 columns (a shard of 2 × 2 chunks at level 0, of 1 at level 1): 4 × 4.
    assert (rep["rows"], rep["tile"], rep["tiles"], rep["bricks"]) == (5, [16, 16], 16, True)
    assert rep["tasks"] == tasks
    assert_same_tree(want, out)


def test_a_failed_task_leaves_nothing(tmp_path, client):
    # Workers load the scene again from its file: gone, every task fails.
    scene_file = tmp_path / "gone.csg"
    shutil.copy(SCENES / "figure-5.2.csg", scene_file)
    scene = csgpix.load(scene_file)
    scene_file.unlink()
    out = tmp_path / "out.zarr"
    with pytest.raises(FileNotFoundError, match="gone.csg"):
        cd.voxelize_zarr(scene, out, 16, chunk=4, client=client)
    assert list(tmp_path.iterdir()) == [], "no output and no staging directory"


def test_an_existing_output_is_refused(tmp_path):
    out = tmp_path / "x.zarr"
    out.mkdir()
    with pytest.raises(csgpix.CsgpixError, match="exists"):
        cd.voxelize_zarr(str(SCENES / "figure-5.2.csg"), out, 8)
    assert list(out.iterdir()) == []


def test_a_task_over_the_memory_limit_fails_and_leaves_nothing(tmp_path):
    out = tmp_path / "big.zarr"
    with pytest.raises(csgpix.CsgpixError, match="over max_memory 8"):
        cd.voxelize_zarr(str(SCENES / "figure-5.2.csg"), out, 512, chunk=64, max_memory=8)
    assert list(tmp_path.iterdir()) == []


def test_tiles_outside_the_store_or_off_the_run_route_are_refused(tmp_path):
    from csgpix import _native

    scene = csgpix.load(SCENES / "csg-logo.csg")
    path = tmp_path / "t.zarr"
    meta = _native.zarr_create(scene, path, 32, chunk=8, shard=2)
    n = meta["tiles"]
    assert meta["bricks"] and n > 1, meta
    with pytest.raises(csgpix.CsgpixError, match=rf"^tiles \(0, {n + 1}\): the store has tiles 0\.\.{n}, "):
        _native.zarr_write_rows(scene, path, (0, 1), tiles=(0, n + 1))
    # The slab routes write whole chunk rows: every tile or none.
    with pytest.raises(csgpix.CsgpixError, match="only the run route voxelizes some of them"):
        _native.zarr_write_rows(scene, path, (0, 1), tiles=(0, 1), route="intervals")
    whole = _native.zarr_write_rows(scene, path, (0, meta["rows"]), tiles=(0, n), route="intervals")
    assert whole["filled"] > 0
