"""Read a csgpix Zarr store with zarr-python and compare it with the NRRD volume of the same run.

    python3 tests/data/read_zarr.py OUT.zarr OUT.nrrd

Prints `equal: shape (nz, ny, nx), ...` and exits 0 when level 0 equals the NRRD samples
voxel for voxel, each coarser level of the multiscale pyramid equals the NRRD volume
downsampled by the rule of docs/zarr.md (written here again, in numpy), and the OME-Zarr
scale and translation are the NRRD header's space directions and origin (Z, Y, X), doubled
and moved to the centre of the coarser voxel per level; otherwise says what differs and exits
1. Called by tests/zarr.rs.
"""

import sys

import numpy as np
import zarr


def read_nrrd(path):
    """The samples of a csgpix NRRD (uint8, raw, X fastest) as a (nz, ny, nx) array, and the
    header's fields."""
    data = open(path, "rb").read()
    end = data.index(b"\n\n")
    fields = {}
    for line in data[:end].decode().splitlines()[1:]:
        if line.startswith("#") or ": " not in line:
            continue
        key, value = line.split(": ", 1)
        fields[key] = value
    assert fields["type"] == "uint8" and fields["encoding"] == "raw", fields
    nx, ny, nz = (int(w) for w in fields["sizes"].split())
    samples = np.frombuffer(data[end + 2 :], dtype=np.uint8).reshape(nz, ny, nx)
    return samples, fields


def downsample(a):
    """The next level: each axis halved rounding up, a voxel the most frequent non-zero value
    of its (up to) 8, ties to the smallest, 0 when all are 0. Padding with 0 changes nothing."""
    a = np.pad(a, [(0, n % 2) for n in a.shape])
    nz, ny, nx = (n // 2 for n in a.shape)
    blocks = a.reshape(nz, 2, ny, 2, nx, 2).transpose(0, 2, 4, 1, 3, 5).reshape(-1, 8)
    values = blocks.astype(np.int64)
    counts = (values[:, :, None] == values[:, None, :]).sum(axis=2)
    score = np.where(values != 0, counts * 256 + (255 - values), -1)
    best = values[np.arange(len(values)), score.argmax(axis=1)]
    best[score.max(axis=1) < 0] = 0
    return best.astype(np.uint8).reshape(nz, ny, nx)


def numbers(text):
    return [float(w) for w in text.replace("(", " ").replace(")", " ").replace(",", " ").split()]


def main():
    store, nrrd = sys.argv[1], sys.argv[2]
    group = zarr.open_group(store, mode="r")
    array = group["0"]
    want, fields = read_nrrd(nrrd)
    got = array[:]
    problems = []
    if got.shape != want.shape:
        problems.append(f"shape {got.shape}, NRRD {want.shape}")
    elif not np.array_equal(got, want):
        problems.append(f"{int(np.count_nonzero(got != want))} voxels differ")
    if array.dtype != np.uint8:
        problems.append(f"dtype {array.dtype}")
    ome = group.attrs["ome"]
    transforms = ome["multiscales"][0]["datasets"][0]["coordinateTransformations"]
    scale, translation = transforms[0]["scale"], transforms[1]["translation"]
    dirs = numbers(fields["space directions"])
    origin = numbers(fields["space origin"])
    if scale != [dirs[8], dirs[4], dirs[0]]:
        problems.append(f"scale {scale}, NRRD space directions {dirs}")
    if translation != origin[::-1]:
        problems.append(f"translation {translation}, NRRD space origin {origin}")
    datasets = ome["multiscales"][0]["datasets"]
    level = want
    for l, ds in enumerate(datasets[1:], start=1):
        level = downsample(level)
        got_l = group[ds["path"]][:]
        if ds["path"] != str(l):
            problems.append(f"dataset {l} has path {ds['path']}")
        elif got_l.shape != level.shape or not np.array_equal(got_l, level):
            problems.append(f"level {l} is not the downsample of level {l - 1}")
        t = ds["coordinateTransformations"]
        f = 2.0**l
        if not np.allclose(t[0]["scale"], np.array(scale) * f, rtol=1e-12, atol=0):
            problems.append(f"level {l} scale {t[0]['scale']}")
        centre = np.array(translation) + np.array(scale) * (f - 1) / 2
        if not np.allclose(t[1]["translation"], centre, rtol=1e-12, atol=1e-12):
            problems.append(f"level {l} translation {t[1]['translation']}, not {centre}")
    if problems:
        print("; ".join(problems))
        sys.exit(1)
    print(
        f"equal: shape {got.shape}, chunks {array.chunks}, shards {array.shards}, "
        f"{len(datasets)} levels, {int(np.count_nonzero(got))} filled, zarr-python {zarr.__version__}"
    )


if __name__ == "__main__":
    main()
