"""The cocotb testbench (cocotb/pixel_array_tb.py): Icarus simulates the Verilog
pixel_array, driven clock by clock from Python, against csgpix.ArrayModel as the reference
model. Built and run by cocotb's Python runner (cocotb/runner.py), no Makefile."""

import os
import shutil
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "cocotb"))

import runner  # noqa: E402

_missing = shutil.which("iverilog") is None or shutil.which("vvp") is None
if _missing and os.environ.get("CSGPIX_RTL_TOOLS") == "require":
    # CI (.ci/run) installs Icarus: its absence there is a failure, not a skip.
    raise RuntimeError("CSGPIX_RTL_TOOLS=require but iverilog/vvp are not installed")
pytestmark = pytest.mark.skipif(
    _missing,
    reason="Icarus Verilog (iverilog, vvp) is not installed: apt-get install -y iverilog",
)


def test_pixel_array_equals_the_cycle_model_clock_by_clock(tmp_path):
    """Both scenes (the cube's window, the clipped boxes): every register of every pixel
    after every clock, and the image after every operation, equal the models'."""
    results = runner.results(runner.run(tmp_path / "sim"))
    assert [(n, s) for n, s, _ in results] == [
        ("cube", "passed"),
        ("clipped_boxes", "passed"),
    ], results


def test_the_testbench_fails_on_a_faulty_pixel(tmp_path):
    """Not vacuous: a pixel whose Put 1 also sets the sign bit (F gets 1111...1, not
    0111...1) fails the cube, naming the clock, the operation, the pixel and the register."""
    fault = {"pixel.v": ("wire one = ~is_sign;", "wire one = 1'b1;")}
    results = runner.results(runner.run(tmp_path / "sim", testcase="cube", patch=fault))
    assert [(n, s) for n, s, _ in results] == [("cube", "failed")], results
    msg = results[0][2]
    assert "mismatches between pixel_array and the cycle model" in msg, msg
    assert "register " in msg and "verilog " in msg, msg
