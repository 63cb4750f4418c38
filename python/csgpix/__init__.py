"""csgpix from Python: the simulator of a 2D CSG pixel-processor array (seed 001).

Load a scene and voxelize it into a numpy array::

    import csgpix
    scene = csgpix.load("vectors/scenes/figure-5.2.csg")
    vol = csgpix.voxelize(scene, 64)            # Volume: .data[k, j, i], .origin, .spacing
    print(vol.data.shape, vol.origin, vol.spacing, int((vol.data > 0).sum()))

Compile a scene for the array and render it, or step the array's models::

    prog = csgpix.compile("vectors/thesis/cube.dl", 256, 256)
    img = csgpix.render(prog, model="cycle")    # Image: .codes[y, x], .rgb(), .cycles

Every error is a :class:`CsgpixError` (a ``ValueError``) whose message is the command line's
one line, with ``file``, ``line`` and ``col`` where the problem has a place in a file; a file
the system cannot read raises the matching :class:`OSError` instead (``FileNotFoundError``,
``PermissionError``, ``IsADirectoryError``) with the same message.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Optional, Sequence, Tuple, Union

import numpy as np

from . import _native
from ._native import CsgpixError, Program, Scene, compile, load, load_expr, verify_select
from ._native import ArrayModel, verilog_files

# Raised in a worker process and pickled back: found again as csgpix.CsgpixError, its file,
# line and col kept (they are the exception's __dict__, which pickling carries).
CsgpixError.__module__ = "csgpix"

__all__ = [
    "ArrayModel",
    "CsgpixError",
    "Image",
    "Program",
    "Scene",
    "Volume",
    "compile",
    "load",
    "load_expr",
    "palette",
    "render",
    "verify_select",
    "verilog_files",
    "voxelize",
]

Vec3 = Tuple[float, float, float]


@dataclass(frozen=True)
class Volume:
    """Voxels of a scene: ``data[k - z0, j, i]`` is voxel (i, j, k) of the grid (uint8 colour
    codes, 0 empty; grey values 16..255 with ``grey`` or ``blend``).

    ``origin`` is the centre of voxel (0, 0, 0) of the whole grid and ``spacing`` the voxel's
    size, both (x, y, z) in scene units: voxel (i, j, k) is centred on
    ``origin + (i, j, k) * spacing``. ``dims`` is the whole grid's (NX, NY, NZ) and ``z`` the
    slab range held, (z0, z1).
    """

    data: np.ndarray
    origin: Vec3
    spacing: Vec3
    dims: Tuple[int, int, int]
    z: Tuple[int, int]

    def __array__(self, dtype=None, copy=None):
        return self.data if dtype is None else self.data.astype(dtype)

    @property
    def shape(self) -> Tuple[int, int, int]:
        """The shape of ``data``: (slabs held, NY, NX)."""
        return self.data.shape

    @property
    def dtype(self) -> np.dtype:
        """``data``'s type: uint8."""
        return self.data.dtype

    def to_mesh(self, max_memory: Optional[int] = None) -> Tuple[np.ndarray, np.ndarray]:
        """The surface of the voxels held, as ``csgpix voxelize --mesh`` writes it (global
        Marching Cubes over the optimized octree, closed and wound outward, in scene units):
        ``(vertices, faces)``, float32 (V, 3) and uint32 (F, 3), welded; e.g.
        ``trimesh.Trimesh(*vol.to_mesh())`` is watertight. ``max_memory`` (MiB) as for
        :func:`voxelize`."""
        origin = self.centre(0, 0, self.z[0])
        return _native.mesh(self.data, origin, self.spacing, max_memory=max_memory)

    def centre(self, i: int, j: int, k: int) -> Vec3:
        """Centre of voxel (i, j, k) of the grid, in scene units."""
        return tuple(o + n * s for o, n, s in zip(self.origin, (i, j, k), self.spacing))


def voxelize(
    scene: Union[Scene, str],
    res: Union[int, Tuple[int, int, int], None] = None,
    *,
    voxel: Optional[float] = None,
    pad: int = 0,
    bounds: Optional[Tuple[Vec3, Vec3]] = None,
    sampling: str = "centre",
    model: str = "word",
    route: str = "runs",
    eval: str = "blist",
    grey: bool = False,
    blend: Optional[str] = None,
    word: str = "10/10/11",
    z: Optional[Tuple[int, int]] = None,
    max_memory: Optional[int] = None,
    progress: Optional[Callable[[int, int], object]] = None,
) -> Volume:
    """Voxelize ``scene`` (a :class:`Scene` or a ``.csg``/``.scad`` path) as
    ``csgpix voxelize`` does: ``res`` N (N cubic voxels along the longest side of the bounds,
    as ``--res N``) or (NX, NY, NZ) voxels per axis, or cubic voxels of side ``voxel``, ``pad`` empty voxels around, over ``bounds`` or the scene's box.

    ``z=(k0, k1)`` voxelizes slabs k0..k1 of that grid only: the same voxels as those slabs
    of the whole volume, computed without the others. ``model`` is ``cycle``, ``word`` or
    ``float``; ``route`` ``runs`` (word or float), ``intervals`` or ``array`` (word); ``eval`` ``blist``, ``tree`` or
    ``stack``; ``sampling`` ``centre`` or ``slab`` (docs/voxelization.md).

    A run whose memory estimate is over ``max_memory`` MiB (default: the memory available
    now) is refused before anything is allocated, as the command line's ``--max-memory``.

    ``progress``, if given, is called as ``progress(done, total)`` as the slices are computed
    (``total`` the slices, ``done`` those finished), from the voxelizer's threads with the GIL
    taken: ``lambda done, total: bar.update(done - bar.n)`` drives a tqdm bar. An exception
    it raises is raised once the run is over.
    """
    if not isinstance(scene, Scene):
        scene = load(scene)
    data, origin, spacing, dims = _native.voxelize(
        scene, res, voxel=voxel, pad=pad, bounds=bounds, sampling=sampling, model=model,
        route=route, eval=eval, grey=grey, blend=blend, word=word, z=z, max_memory=max_memory,
        progress=progress,
    )
    k0, k1 = z if z is not None else (0, dims[2])
    return Volume(data, tuple(origin), tuple(spacing), tuple(dims), (k0, k1))


@dataclass(frozen=True)
class Image:
    """A rendered frame: ``codes[y, x]`` the colour code (G) of every pixel (uint8, 0
    background), ``cycles`` the array's clocks (0 for the ``float`` reference)."""

    codes: np.ndarray
    cycles: int

    def __array__(self, dtype=None, copy=None):
        return self.codes if dtype is None else self.codes.astype(dtype)

    def rgb(self) -> np.ndarray:
        """The picture the command line writes: shape (height, width, 3), uint8."""
        return palette()[self.codes]


def render(
    program: Union[Program, str, Sequence[str]],
    width: int = 250,
    height: int = 250,
    *,
    model: str = "cycle",
    equations: str = "derived",
    clip: Optional[str] = None,
    view: str = "iso",
) -> Image:
    """Render a compiled :class:`Program`, or compile the scene path(s) first (display lists
    ``.dl``, clipped by ``clip`` over A, B, ...; or one ``.csg``/``.scad`` along ``view``),
    on the ``cycle`` or ``word`` model of the array or the ``float`` reference. The defaults
    are the command line's: a 250×250 array (the thesis's window), the ``cycle`` model."""
    if not isinstance(program, Program):
        program = compile(program, width, height, clip=clip, view=view)
    codes, cycles = _native.render(program, model, equations)
    return Image(codes, cycles)


def palette() -> np.ndarray:
    """RGB of every colour code: shape (256, 3), uint8."""
    return _native.palette()
