"""Type stubs of csgpix._native, the Rust library behind the csgpix package."""

from os import PathLike
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, PathLike[str]]
_Vec3 = Tuple[float, float, float]

class CsgpixError(ValueError):
    """One-line message; ``file``, ``line``, ``col``: where in an input, or None."""

    file: Optional[str]
    line: Optional[int]
    col: Optional[int]

# --- scenes and voxelization -------------------------------------------------------------

class Scene:
    name: str
    @property
    def primitives(self) -> int: ...
    @property
    def bounds(self) -> Tuple[_Vec3, _Vec3]: ...
    @property
    def warnings(self) -> List[str]: ...

def load(path: _Path, openscad_timeout: Optional[float] = 300.0, strict: bool = False) -> Scene: ...
def load_expr(
    expr: str, prims: Sequence[Tuple[str, Union[_Path, Tuple[_Path, float]]]]
) -> Scene: ...
def voxelize(
    scene: Scene,
    res: Union[int, Tuple[int, int, int], None] = None,
    *,
    voxel: Optional[float] = None,
    pad: int = 0,
    bounds: Optional[Tuple[_Vec3, _Vec3]] = None,
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
) -> Tuple[npt.NDArray[np.uint8], _Vec3, _Vec3, Tuple[int, int, int]]: ...
def mesh(
    data: npt.NDArray[np.uint8],
    origin: _Vec3,
    spacing: _Vec3,
    *,
    max_memory: Optional[int] = None,
) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.uint32]]: ...

# --- drawing on the array ----------------------------------------------------------------

class Program:
    @property
    def size(self) -> Tuple[int, int]: ...
    @property
    def stack_levels(self) -> int: ...
    def cycles(self, equations: str = "derived") -> int: ...
    def ops(self) -> List[str]: ...
    def __len__(self) -> int: ...

def compile(
    scene: Union[_Path, Sequence[_Path]],
    width: int = 250,
    height: int = 250,
    *,
    clip: Optional[str] = None,
    view: str = "iso",
    word: str = "10/10/11",
    openscad_timeout: Optional[float] = 300.0,
) -> Program: ...
def render(
    program: Program, model: str = "cycle", equations: str = "derived"
) -> Tuple[npt.NDArray[np.uint8], int]: ...
def palette() -> npt.NDArray[np.uint8]: ...
def verify_select(
    equations: str = "derived", vectors: Optional[_Path] = None
) -> List[Dict[str, Any]]: ...

# --- zarr volumes (csgpix.distributed) ---------------------------------------------------

def zarr_create(
    scene: Scene,
    path: _Path,
    res: Union[int, Tuple[int, int, int], None] = None,
    *,
    voxel: Optional[float] = None,
    pad: int = 0,
    bounds: Optional[Tuple[_Vec3, _Vec3]] = None,
    chunk: Union[int, Tuple[int, int, int], None] = None,
    sampling: str = "centre",
    model: str = "word",
    route: str = "runs",
    eval: str = "blist",
    grey: bool = False,
    blend: Optional[str] = None,
    word: str = "10/10/11",
) -> Dict[str, Any]: ...
def zarr_write_rows(
    scene: Scene,
    path: _Path,
    rows: Tuple[int, int],
    *,
    tiles: Optional[Tuple[int, int]] = None,
    sampling: str = "centre",
    model: str = "word",
    route: str = "runs",
    eval: str = "blist",
    grey: bool = False,
    blend: Optional[str] = None,
    word: str = "10/10/11",
    threads: Optional[int] = None,
    max_memory: Optional[int] = None,
    progress: Optional[Callable[[int, int], object]] = None,
) -> Dict[str, int]: ...

# --- array models (cocotb reference) -----------------------------------------------------

class ArrayModel:
    """A compiled program on the ``cycle`` or ``word`` model, stepped from Python; on the
    ``cycle`` model also clock by clock, as the Verilog ``pixel_array`` sees it."""

    def __init__(
        self,
        program: Program,
        model: str = "cycle",
        equations: str = "derived",
        *,
        origin: Tuple[int, int] = (0, 0),
    ) -> None: ...
    @property
    def model(self) -> str: ...
    @property
    def size(self) -> Tuple[int, int]: ...
    @property
    def position(self) -> int: ...
    @property
    def done(self) -> bool: ...
    @property
    def cycles(self) -> int: ...
    def __len__(self) -> int: ...
    def ops(self) -> List[str]: ...
    def step(self) -> int: ...
    def finish(self) -> int: ...
    def run(self) -> int: ...
    def image(self) -> npt.NDArray[np.uint8]: ...
    def registers(self, x: int, y: int) -> Dict[str, Any]: ...
    def step_clocks(self) -> List[List[int]]: ...
    def finish_clocks(self) -> List[List[int]]: ...
    def state_words(self) -> List[int]: ...
    def state_fields(self) -> List[Tuple[str, int]]: ...
    def control_words(self) -> Tuple[List[int], List[int]]: ...
    @staticmethod
    def control_fields() -> List[Tuple[str, int, int]]: ...
    @staticmethod
    def array_inputs() -> List[str]: ...

def verilog_files(program: Program) -> Dict[str, str]: ...
