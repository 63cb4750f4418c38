"""Read a csgpix Zarr store with zarr-python and compare it with the NRRD volume of the same run.

    python3 tests/data/read_zarr.py OUT.zarr OUT.nrrd

Prints `equal: shape (nz, ny, nx), ...` and exits 0 when the array equals the NRRD samples
voxel for voxel and the OME-Zarr scale and translation are the NRRD header's space directions
and origin (Z, Y, X); otherwise says what differs and exits 1. Called by tests/zarr.rs.
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
    if problems:
        print("; ".join(problems))
        sys.exit(1)
    print(
        f"equal: shape {got.shape}, chunks {array.chunks}, {int(np.count_nonzero(got))} filled, "
        f"zarr-python {zarr.__version__}"
    )


if __name__ == "__main__":
    main()
