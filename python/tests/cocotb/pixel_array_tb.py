"""A cocotb testbench of the Verilog ``pixel_array`` with :class:`csgpix.ArrayModel` as its
reference model (docs/verilog.md, "A cocotb testbench from Python").

Icarus simulates ``pixel_array`` built from :func:`csgpix.verilog_files` (the toplevel: no
Verilog testbench). Python is the controller: every clock it sets ``pixel_array``'s control
inputs to the fields of that clock's control word (:meth:`ArrayModel.control_words`, the
stream ``tb_array`` reads from ``control.hex``). It steps the cycle model operation by
operation (:meth:`ArrayModel.step_clocks`) and, after every clock, compares every field of
every pixel's ``state`` (read through the hierarchy, ``gy[y].gx[x].p.state``) with the
model's; at the end of every operation it also compares the ``image`` output with the cycle
model's and the word model's images. Any difference fails the test, naming the clock, the
operation, the pixel, the register and both values.

Run by ``python/tests/cocotb/runner.py`` (or ``pytest python/tests/test_cocotb.py``).
"""

from __future__ import annotations

from pathlib import Path
from typing import List, Optional

import cocotb
import numpy as np
from cocotb.triggers import Timer

import csgpix
from csgpix import ArrayModel

ROOT = Path(__file__).resolve().parents[3]
THESIS = ROOT / "vectors" / "thesis"

# The array the runner builds the Verilog for, and the scenes run on it: the windows of the
# 250x250 thesis screen the Rust co-simulation tests use (tests/verilog.rs).
SIZE = (16, 16)
SCENES = {
    "cube": dict(paths=[THESIS / "cube.dl"], clip=None, origin=(56, 90)),
    "clipped_boxes": dict(
        paths=[THESIS / "box1.dl", THESIS / "box2.dl"], clip="A.!B", origin=(112, 148)
    ),
}
# Mismatches reported before a test stops.
REPORT = 10


def program(name: str) -> csgpix.Program:
    s = SCENES[name]
    return csgpix.compile([str(p) for p in s["paths"]], *SIZE, clip=s["clip"])


class Bench:
    """pixel_array driven from Python, its pixels' ``state`` words read every clock."""

    def __init__(self, dut, model: ArrayModel, ops: List[str]):
        self.dut = dut
        self.model = model
        self.ops = ops
        fields = {n: (lo, w) for n, lo, w in ArrayModel.control_fields()}
        self.inputs = [
            (getattr(dut, n), fields[n][0], (1 << fields[n][1]) - 1)
            for n in ArrayModel.array_inputs()
        ]
        self.last_bit = fields["last"][0]
        self.width, self.height = model.size
        self.states = [
            dut.gy[y].gx[x].p.state for y in range(self.height) for x in range(self.width)
        ]
        self.fields = []
        lo = 0
        for name, w in model.state_fields():
            self.fields.append((name, lo, w))
            lo += w
        self.colour_bits = dict(model.state_fields())["G"]
        self.t = 0  # clocks driven since reset
        self.bad: List[str] = []

    def drive(self, word: int) -> None:
        for handle, lo, mask in self.inputs:
            handle.value = (word >> lo) & mask

    async def clock(self, word: int, rst: int = 0) -> None:
        """Present `word` (and rst), then one rising edge of clk."""
        self.dut.clk.value = 0
        self.dut.rst.value = rst
        self.drive(word)
        await Timer(1, "ns")
        self.dut.clk.value = 1
        await Timer(1, "ns")

    async def reset(self) -> None:
        await self.clock(0, rst=1)
        self.t = 0

    def read(self, handle) -> Optional[int]:
        """The value of `handle`, None if a bit is X or Z (parsed from the bits' string:
        LogicArray's own checks look at every bit as an object, 30 times slower)."""
        try:
            return int(str(handle.value), 2)
        except ValueError:
            return None

    def compare(self, want: List[int], where: str) -> None:
        """Every pixel's state against the model's `want` (row-major)."""
        for i, (h, w) in enumerate(zip(self.states, want)):
            got = self.read(h)
            if got == w:
                continue
            x, y = i % self.width, i // self.width
            if got is None:
                self.bad.append(f"{where}: pixel ({x}, {y}) state {h.value} is not 0/1")
                continue
            for name, lo, bits in self.fields:
                m, g = (w >> lo) & ((1 << bits) - 1), (got >> lo) & ((1 << bits) - 1)
                if m != g:
                    self.bad.append(
                        f"{where}: pixel ({x}, {y}) register {name}: model {m:x}, verilog {g:x}"
                    )

    def image(self) -> np.ndarray:
        v = self.read(self.dut.image)
        assert v is not None, f"image {self.dut.image.value} is not 0/1"
        cb = self.colour_bits
        codes = [(v >> (i * cb)) & ((1 << cb) - 1) for i in range(self.width * self.height)]
        return np.array(codes, dtype=np.uint8).reshape(self.height, self.width)

    def check(self) -> None:
        assert not self.bad, (
            f"{len(self.bad)} mismatches between pixel_array and the cycle model, first "
            f"{min(len(self.bad), REPORT)}:\n" + "\n".join(self.bad[:REPORT])
        )


async def cosimulate(dut, name: str) -> None:
    prog = program(name)
    origin = SCENES[name]["origin"]
    cycle = ArrayModel(prog, "cycle", origin=origin)
    word = ArrayModel(prog, "word", origin=origin)
    words, ends = cycle.control_words()
    ops = cycle.ops()
    bench = Bench(dut, cycle, ops)
    assert (len(dut.image) // bench.colour_bits) == SIZE[0] * SIZE[1], "DUT of another size"

    await bench.reset()
    bench.compare(cycle.state_words(), "after reset")
    bench.check()

    def run_clocks(states: List[List[int]], what: str, end: int):
        assert bench.t + len(states) == end, f"{what}: the stream ends it at clock {end}"
        return states

    for i in range(len(cycle)):
        what = f"operation {i} ({ops[i]})"
        states = run_clocks(cycle.step_clocks(), what, ends[i])
        word.step()
        for want in states:
            await bench.clock(words[bench.t])
            bench.compare(want, f"clock {bench.t + 1}, in {what}")
            bench.t += 1
        bench.check()
        img = bench.image()
        assert np.array_equal(img, cycle.image()), f"image after {what}:\n{img}\n{cycle.image()}"
        assert np.array_equal(img, word.image()), f"image after {what} (word model)"

    flush = cycle.finish_clocks()
    word.finish()
    if flush:
        run_clocks(flush, "the flush window", ends[len(cycle)])
    for want in flush:
        await bench.clock(words[bench.t])
        bench.compare(want, f"clock {bench.t + 1}, in the flush window")
        bench.t += 1
    bench.check()
    # The idle clock that carries `last` changes nothing.
    assert bench.t == cycle.cycles == len(words) - 1
    assert words[bench.t] >> bench.last_bit & 1
    await bench.clock(words[bench.t])
    bench.compare(cycle.state_words(), f"clock {bench.t + 1}, the idle clock with `last`")
    bench.check()

    img = bench.image()
    assert np.array_equal(img, cycle.image()) and np.array_equal(img, word.image())
    colours = len(np.unique(img))
    dut._log.info(
        "%s: %d operations, %d clocks + 1 idle, %d pixels compared every clock, image of %d "
        "colours equal to the cycle and word models",
        name, len(cycle), cycle.cycles, SIZE[0] * SIZE[1], colours,
    )
    assert colours >= 3, f"{name}: the window shows {colours} colours"


@cocotb.test()
async def cube(dut):
    """The thesis cube's 16x16 window at (56, 90)."""
    await cosimulate(dut, "cube")


@cocotb.test()
async def clipped_boxes(dut):
    """box1 clipped by box2 (A.!B): the stack's push, NOT, AND and apply."""
    await cosimulate(dut, "clipped_boxes")
