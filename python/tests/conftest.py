"""Shared paths and the command-line binary the bindings are checked against."""

import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
SCENES = ROOT / "vectors" / "scenes"
THESIS = ROOT / "vectors" / "thesis"


def cli_binary() -> Path:
    """The `csgpix` binary of this checkout: $CSGPIX_BIN, or target/release/csgpix (built by
    the README's test command, which CI runs first)."""
    p = Path(os.environ.get("CSGPIX_BIN", ROOT / "target" / "release" / "csgpix"))
    if not p.exists():
        pytest.fail(f"{p}: build it first (cargo build --release) or set CSGPIX_BIN")
    return p


def run_cli(*args: str, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run([str(cli_binary()), *args], cwd=cwd, capture_output=True, text=False)


def read_nrrd(path: Path) -> np.ndarray:
    """The voxels of a csgpix NRRD (raw uint8, sizes NX NY NZ) as an array [k, j, i]."""
    raw = path.read_bytes()
    head, _, data = raw.partition(b"\n\n")
    fields = dict(
        line.split(": ", 1) for line in head.decode().splitlines()[1:] if ": " in line
    )
    assert fields["type"] == "uint8" and fields["encoding"] == "raw", fields
    nx, ny, nz = (int(s) for s in fields["sizes"].split())
    return np.frombuffer(data, dtype=np.uint8).reshape(nz, ny, nx)


@pytest.fixture
def tmp(tmp_path):
    return tmp_path


def have(program: str) -> bool:
    return shutil.which(program) is not None
