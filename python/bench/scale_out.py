"""Speed-up of a distributed voxelization with Dask workers on this machine
(docs/scale-out.md): one volume, written as a Zarr volume by 1..N worker processes of a
`distributed.LocalCluster` (one thread each, one voxelizer thread per task), against the
baseline measured in the same run: the same volume written in this process by one voxelizer thread (its chunks compressed and
written by the store's writer threads beside it, as in every run), and by all cores.

    python python/bench/scale_out.py --scene vectors/scenes/csg-logo.csg --res 512 --workers 1 2 --json

Every run's files are compared with the baseline's, byte for byte.
"""

import argparse
import filecmp
import json
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

import csgpix
import csgpix.distributed as cd


def tree_equal(a: Path, b: Path) -> bool:
    fa = sorted(p.relative_to(a) for p in a.rglob("*") if p.is_file())
    fb = sorted(p.relative_to(b) for p in b.rglob("*") if p.is_file())
    return fa == fb and all(filecmp.cmp(a / f, b / f, shallow=False) for f in fa)


def _peak_kib() -> int:
    """This process's peak resident memory (VmHWM), KiB."""
    with open("/proc/self/status") as f:
        return next(int(line.split()[1]) for line in f if line.startswith("VmHWM:"))


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scene", default="vectors/scenes/csg-logo.csg")
    ap.add_argument("--res", type=int, default=512)
    ap.add_argument("--chunk", type=int, default=32)
    ap.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--tasks-per-worker", type=int, default=2,
                    help="chunk rows are grouped into this many tasks per worker (each task "
                         "sets up the scene once)")
    ap.add_argument("--shard", type=int, default=64,
                    help="chunks a shard side: a brick's tile is a shard's columns (docs/zarr.md)")
    ap.add_argument("--tiles-per-task", type=int, default=None,
                    help="XY tiles a task takes (default: all; the run route's bricks)")
    ap.add_argument("--rows-per-task", type=int, default=None,
                    help="chunk rows a task takes (default: from --tasks-per-worker); with "
                         "--tiles-per-task 1 and every row, a task is a tile's whole depth, "
                         "its columns' runs computed once")
    ap.add_argument("--route", default="runs")
    ap.add_argument("--json", action="store_true", help="print the figures as JSON")
    a = ap.parse_args()
    from dask.distributed import Client, LocalCluster

    scene = csgpix.load(a.scene)
    work = Path(tempfile.mkdtemp(prefix="csgpix-scale-out."))
    rows = []
    try:
        t = time.perf_counter()
        opts = dict(chunk=a.chunk, shard=a.shard, route=a.route)
        base = cd.voxelize_zarr(scene, work / "base.zarr", a.res, threads=1, **opts)
        t_base = time.perf_counter() - t
        rows.append(dict(run="this process, 1 thread", workers=0, seconds=t_base, speedup=1.0, identical=True,
                         task_seconds=base["task_microseconds"] / 1e6))
        t = time.perf_counter()
        both = cd.voxelize_zarr(scene, work / "threads.zarr", a.res, **opts)
        s = time.perf_counter() - t
        rows.append(dict(run=f"this process, {os.cpu_count()} threads", workers=0, seconds=s,
                         speedup=t_base / s, task_seconds=both["task_microseconds"] / 1e6,
                         identical=tree_equal(work / "base.zarr", work / "threads.zarr")))
        shutil.rmtree(work / "threads.zarr")
        for n in a.workers:
            with LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None) as cl, Client(cl) as client:
                client.run(lambda: None)  # workers up before the clock starts
                out = work / f"w{n}.zarr"
                t = time.perf_counter()
                per = a.rows_per_task or -(-base["rows"] // (n * a.tasks_per_worker))
                rep = cd.voxelize_zarr(scene, out, a.res, threads=1, client=client, rows_per_task=per,
                                       tiles_per_task=a.tiles_per_task, **opts)
                s = time.perf_counter() - t
                # Each worker's peak resident memory: VmHWM, which a new program starts
                # afresh (ru_maxrss keeps the parent's high-water mark across fork and exec).
                peaks = client.run(_peak_kib)
            rows.append(dict(run=f"LocalCluster, {n} worker process(es)", workers=n, seconds=s,
                             tasks=rep["tasks"], worker_peak_mib=sorted(round(k / 1024) for k in peaks.values()),
                             task_seconds=rep["task_microseconds"] / 1e6,
                             speedup=t_base / s, identical=tree_equal(work / "base.zarr", out)))
            shutil.rmtree(out)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    fig = dict(scene=a.scene, res=a.res, chunk=a.chunk, shard=a.shard, route=a.route, tile=base["tile"],
               tiles=base["tiles"], rows_of_chunks=base["rows"], filled=base["filled"], cores=os.cpu_count(),
               driver_peak_mib=round(_peak_kib() / 1024), runs=rows)
    if a.json:
        print(json.dumps(fig, indent=2))
    else:
        for r in rows:
            peaks = f"  worker peaks {r['worker_peak_mib']} MiB" if "worker_peak_mib" in r else ""
            print(f"{r['run']:<40} {r['seconds']:8.2f} s  x{r['speedup']:.2f}  "
                  f"in tasks {r['task_seconds']:.2f} s{peaks}  identical={r['identical']}")
    return 0 if all(r["identical"] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
