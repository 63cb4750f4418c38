"""Voxelizing past one machine: one volume's bricks as Dask tasks (docs/scale-out.md).

A volume is a Zarr v3 array (``csgpix voxelize -o OUT.zarr``, docs/zarr.md) whose chunks
are ``chunk`` slabs deep: a *chunk row* is every chunk of those slabs, and a *brick* is a
chunk row's columns of one XY *tile* (the least square of columns that holds whole shard
files at every level of the pyramid: a shard's side, 4096 voxels by default). The driver
writes the array's metadata into a staging directory beside ``out``; each task loads the
scene (a :class:`csgpix.Scene` pickles as its source, so workers need the same files at the
same paths) and voxelizes its bricks: on the run route (the default) only its tiles'
columns, so a task's memory is a brick's, whatever the grid's width; on a slab route its
rows' whole slices (``voxelize_slabs``, the masks of its first slab built from their source).
When every task has succeeded the staging directory is renamed to ``out``. The files are
byte-identical to the command line's, whatever the workers and the order they finish in: a
file is written by one task only, and its bytes depend on its voxels alone.

::

    from dask.distributed import Client, LocalCluster
    import csgpix, csgpix.distributed as cd

    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        report = cd.voxelize_zarr("vectors/scenes/csg-logo.csg", "logo.zarr", 256, client=client)
"""

from __future__ import annotations

import os
import shutil
import tempfile
import time
from pathlib import Path
from typing import Any, Dict, List, Optional, Tuple, Union

from . import _native
from ._native import CsgpixError, Scene

__all__ = ["voxelize_zarr", "write_rows"]


def write_rows(
    scene: Any,
    path: str,
    rows: Tuple[int, int],
    options: Dict[str, Any],
    tiles: Optional[Tuple[int, int]] = None,
) -> Dict[str, int]:
    """One task: voxelize the bricks of chunk rows ``rows`` (r0, r1) and tiles ``tiles``
    (t0, t1; default every tile) of the array at ``path`` and store them. ``scene`` is a
    :class:`Scene` or its source as ``Scene.__reduce__`` gives it (a loader and its
    arguments: what the tasks carry, so the scheduler, which unpickles the task graph, never
    loads a scene). Returns the bricks' work (filled voxels, frames, ...)."""
    if os.path.exists(os.path.join(path, STOP)):
        return {}
    t0 = time.perf_counter()
    if not isinstance(scene, Scene):
        loader, args = scene
        scene = loader(*args)
    work = _native.zarr_write_rows(scene, path, rows, tiles=tiles, **options)
    # Microseconds in the task (the scene loaded, the rows voxelized and stored): summed over
    # tasks, what the run cost besides scheduling.
    work["task_microseconds"] = round((time.perf_counter() - t0) * 1e6)
    return work


# Written into the staging directory when a task has failed: tasks that start later return at
# once, since the run is lost and its directory about to be removed.
STOP = ".csgpix-stop"


def voxelize_zarr(
    scene: Union[Scene, str],
    out: Union[str, os.PathLike],
    res: Union[int, Tuple[int, int, int], None] = None,
    *,
    client: Any = None,
    chunk: Union[int, Tuple[int, int, int]] = 64,
    shard: Union[int, str] = 64,
    levels: Optional[int] = None,
    rows_per_task: int = 1,
    tiles_per_task: Optional[int] = 1,
    voxel: Optional[float] = None,
    pad: int = 0,
    bounds: Optional[Tuple[Tuple[float, float, float], Tuple[float, float, float]]] = None,
    sampling: str = "centre",
    model: str = "word",
    route: str = "runs",
    eval: str = "blist",
    grey: bool = False,
    blend: Optional[str] = None,
    word: str = "10/10/11",
    threads: Optional[int] = None,
    max_memory: Optional[int] = None,
) -> Dict[str, Any]:
    """Voxelize ``scene`` into the Zarr volume ``out`` (a new directory), chunk rows as
    tasks of the Dask ``client`` (``dask.distributed.Client``), or in this process when
    ``client`` is None (one call over every row). Grid and run options are those of :func:`csgpix.voxelize`; ``chunk``
    is N or (X, Y, Z) voxels (as ``res``); ``shard`` chunks a shard side (``"none"`` or 1: one file a
    chunk); ``levels`` the multiscale pyramid's (default: the command line's, until the
    largest side is at most 256); each task writes its bricks at every level, since a brick
    of level 0 makes the same scene's brick of each coarser level (docs/zarr.md). A task is
    ``rows_per_task`` chunk rows × ``tiles_per_task`` tiles (None: every tile; tiles are
    split only on the run route, which computes a tile's columns alone). ``threads`` is each
    task's voxelizer threads (default: the worker's cores); ``max_memory`` (MiB, default: the
    memory available where the task runs) bounds each task's estimate, checked in the task
    before it allocates. Returns the run's figures: ``dims``, ``chunk``, ``shard``,
    ``levels``, ``rows``, ``tile``, ``tiles``, ``tasks`` and the work summed over the tasks
    (with ``files_written``, the shard or chunk files of every level).

    Nothing is left behind on failure: the staging directory is removed and ``out`` is not
    created. ``out`` must not exist.
    """
    if not isinstance(scene, Scene):
        scene = _native.load(scene)
    out = Path(out)
    if out.exists() or out.is_symlink():
        raise CsgpixError(f"{out}: exists; choose a new path or remove it")
    parent = out.absolute().parent
    if not parent.is_dir():
        raise CsgpixError(f"{out}: no such directory {parent}")
    options = dict(sampling=sampling, model=model, route=route, eval=eval, grey=grey,
                   blend=blend, word=word, threads=threads, max_memory=max_memory)
    staging = Path(tempfile.mkdtemp(prefix=f".{out.name}.", suffix=".csgpix-tmp", dir=parent))
    try:
        meta = _native.zarr_create(
            scene, str(staging), res, voxel=voxel, pad=pad, bounds=bounds, chunk=chunk,
            shard=shard, levels=levels, sampling=sampling, model=model, route=route, eval=eval, grey=grey, blend=blend,
            word=word,
        )
        rows, tiles = meta["rows"], meta["tiles"]
        step = max(1, int(rows_per_task))
        across = tiles if tiles_per_task is None or not meta["bricks"] else max(1, int(tiles_per_task))
        ranges = [
            ((r, min(r + step, rows)), (t, min(t + across, tiles)))
            for r in range(0, rows, step)
            for t in range(0, tiles, across)
        ]
        works = _run(client, scene, str(staging), ranges, options)
        os.rename(staging, out)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    total: Dict[str, int] = {}
    for w in works:
        for k, v in w.items():
            total[k] = total.get(k, 0) + v
    return dict(meta, tasks=len(ranges), **total)


Bricks = Tuple[Tuple[int, int], Tuple[int, int]]


def _run(client: Any, scene: Scene, path: str, ranges: List[Bricks], options: Dict[str, Any]):
    if client is None:
        # One call over every brick: the scene's set-up (slab ranges, meshes' crossings) is
        # done once.
        return [write_rows(scene, path, (ranges[0][0][0], ranges[-1][0][1]), options)] if ranges else []
    from dask.distributed import as_completed

    source = scene.__reduce__()
    run = f"{os.getpid()}-{id(ranges)}"
    futures = [
        client.submit(
            write_rows, source, path, r, options, t, pure=False,
            key=f"csgpix-bricks-{r[0]}-{r[1]}-{t[0]}-{t[1]}-{run}",
        )
        for r, t in ranges
    ]
    # Every task is waited for, failed run or not: a task still running could otherwise write
    # into the staging directory after it has been removed. After a failure the tasks not yet
    # started find STOP and return at once.
    failed = None
    for f in as_completed(futures):
        if f.status == "error" and failed is None:
            failed = f
            Path(path, STOP).touch()
    if failed is not None:
        failed.result()  # raises the task's exception, as it was raised in the worker
    return [f.result() for f in futures]
