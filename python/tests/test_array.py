"""csgpix.ArrayModel: the cycle and word models stepped from Python agree with render, with
each other register for register after every operation, and with the program's clock
count; the cycle model's per-clock state words and control stream are consistent."""

from pathlib import Path

import numpy as np
import pytest

import csgpix
from csgpix import ArrayModel, CsgpixError

ROOT = Path(__file__).resolve().parents[2]
THESIS = ROOT / "vectors" / "thesis"
SCENES = ROOT / "vectors" / "scenes"

CUBE = [str(THESIS / "cube.dl")]
BOXES = [str(THESIS / "box1.dl"), str(THESIS / "box2.dl")]

# (scene, width, height, clip): the thesis screen and a projected .csg.
RENDERED = [
    (CUBE, 250, 250, None),
    (BOXES, 250, 250, "A.!B"),
    ([str(SCENES / "cube-minus-cylinder.csg")], 48, 32, None),
]
# (scene, size, clip, origin): small windows where every pixel is compared after every op.
WINDOWS = [
    (CUBE, (16, 16), None, (56, 90)),
    (BOXES, (16, 16), "A.!B", (112, 148)),
    ([str(SCENES / "cube-minus-cylinder.csg")], (16, 12), None, (0, 0)),
]


def compile_(scene, w, h, clip):
    return csgpix.compile(scene, w, h, clip=clip)


@pytest.mark.parametrize("model", ["cycle", "word"])
@pytest.mark.parametrize("scene,w,h,clip", RENDERED)
def test_image_after_run_is_renders(scene, w, h, clip, model):
    prog = compile_(scene, w, h, clip)
    m = ArrayModel(prog, model)
    clocks = m.run()
    img = csgpix.render(prog, model=model)
    assert m.image().dtype == np.uint8 and m.image().shape == (h, w)
    assert np.array_equal(m.image(), img.codes)
    assert clocks == m.cycles == img.cycles == prog.cycles()
    assert m.done and m.position == len(m) == len(prog)
    assert len(np.unique(img.codes)) >= 3


def test_printed_equations_are_renders():
    prog = compile_(CUBE, 250, 250, None)
    m = ArrayModel(prog, "cycle", "printed")
    m.run()
    img = csgpix.render(prog, model="cycle", equations="printed")
    assert np.array_equal(m.image(), img.codes)
    assert m.cycles == prog.cycles("printed")


@pytest.mark.parametrize("scene,size,clip,origin", WINDOWS)
def test_cycle_and_word_agree_register_for_register_after_every_op(scene, size, clip, origin):
    prog = compile_(scene, *size, clip)
    cycle = ArrayModel(prog, "cycle", origin=origin)
    word = ArrayModel(prog, "word", origin=origin)
    w, h = size
    total = 0
    for i in range(len(prog)):
        assert cycle.position == word.position == i
        c, d = cycle.step(), word.step()
        assert c == d and c > 0
        total += c
        for y in range(h):
            for x in range(w):
                a, b = cycle.registers(x, y), word.registers(x, y)
                assert a == b, f"operation {i}, pixel ({x}, {y})"
    assert cycle.finish() == word.finish()
    assert cycle.image().tolist() == word.image().tolist()
    regs = cycle.registers(0, 0)
    assert sorted(regs) == sorted("A F B C D E G S N J T M stack".split())
    assert isinstance(regs["S"], tuple) and len(regs["S"]) == 2


@pytest.mark.parametrize("equations", ["derived", "printed"])
@pytest.mark.parametrize("model", ["cycle", "word"])
def test_clocks_of_every_step_sum_to_the_programs(model, equations):
    prog = compile_(BOXES, 32, 32, "A.!B")
    m = ArrayModel(prog, model, equations, origin=(112, 148))
    steps = [m.step() for _ in range(len(prog))]
    flush = m.finish()
    assert sum(steps) + flush == m.cycles == prog.cycles(equations)
    assert m.finish() == 0 and m.done
    # Stack operations take one clock, windows N_D (32), the first stream DEPGEN's fill too.
    assert set(steps[1:]) <= {1, 32} and 1 in steps


def test_step_clocks_and_state_words_follow_the_registers():
    prog = compile_(CUBE, 16, 8, None)
    clocked = ArrayModel(prog, "cycle", origin=(56, 90))
    plain = ArrayModel(prog, "cycle", origin=(56, 90))
    fields, lo = {}, 0
    for name, bits in clocked.state_fields():
        fields[name] = (lo, bits)
        lo += bits

    def field(word, name):
        lo, bits = fields[name]
        return word >> lo & ((1 << bits) - 1)

    reset = clocked.state_words()
    assert len(reset) == 16 * 8 and field(reset[0], "k") == 0
    words, ends = clocked.control_words()
    assert len(words) == prog.cycles() + 1
    t = 0
    for i in range(len(prog)):
        states = clocked.step_clocks()
        assert len(states) == plain.step()
        assert all(len(s) == 16 * 8 and all(isinstance(v, int) for v in s) for s in states)
        t += len(states)
        assert ends[i] == t == clocked.cycles
        # At an operation's end every register is aligned: the last clock's words are the
        # state now, and their fields are the registers.
        now = clocked.state_words()
        assert states[-1] == now
        img = clocked.image()
        for p, word in enumerate(now):
            x, y = p % 16, p // 16
            r = clocked.registers(x, y)
            assert field(word, "G") == r["G"] == img[y, x]
            assert field(word, "A") == r["A"] & 0xFFFFFFFF
            assert (field(word, "S_hi"), field(word, "S_lo")) == r["S"]
            assert field(word, "stack") == r["stack"]
    flush = clocked.finish_clocks()
    assert len(flush) == plain.finish() > 0
    assert ends[len(prog)] == t + len(flush) == len(words) - 1
    assert clocked.finish_clocks() == []
    # The last word is the idle clock carrying `last`; op_end marks every end.
    fields_cw = {n: (lo, w) for n, lo, w in ArrayModel.control_fields()}
    assert words[-1] >> fields_cw["last"][0] & 1
    op_end = fields_cw["op_end"][0]
    assert [t + 1 for t, w in enumerate(words) if w >> op_end & 1] == ends


def test_control_fields_and_verilog_files():
    fields = ArrayModel.control_fields()
    assert sum(w for _, _, w in fields) == 47 and fields[0] == ("last", 0, 1)
    inputs = ArrayModel.array_inputs()
    assert "last" not in inputs and "dg_c0" in inputs and len(inputs) == len(fields) - 3
    prog = compile_(CUBE, 16, 16, None)
    assert ArrayModel(prog).ops() == prog.ops()
    moved = ArrayModel(prog, origin=(56, 90)).ops()
    assert len(moved) == len(prog) and moved[0] != prog.ops()[0] and moved[-1] == prog.ops()[-1]
    files = csgpix.verilog_files(prog)
    assert list(files)[-1] == "pixel_array.f"
    assert files["pixel_array.f"].split() == [
        "sgene_derived.v", "comparator.v", "depgen.v", "pixel.v", "pixel_array.v"
    ]
    assert "module pixel_array #(parameter NX = 16, NY = 16)" in files["pixel_array.v"]
    for name in inputs:
        assert name in files["pixel_array.v"]
    other = csgpix.verilog_files(compile_(CUBE, 8, 4, None))
    assert "NX = 8, NY = 4" in other["pixel_array.v"]


def test_errors():
    prog = compile_(CUBE, 16, 16, None)
    with pytest.raises(CsgpixError, match="model \"float\": `cycle` or `word`") as e:
        ArrayModel(prog, "float")
    assert e.value.file is None
    with pytest.raises(CsgpixError, match="equations"):
        ArrayModel(prog, "cycle", "other")
    word = ArrayModel(prog, "word")
    for call in (word.step_clocks, word.finish_clocks, word.state_words):
        with pytest.raises(CsgpixError, match="the word model has no clocks"):
            call()
    with pytest.raises(CsgpixError, match="operations left"):
        word.finish()
    with pytest.raises(CsgpixError, match="outside the 16x16 array"):
        word.registers(16, 0)
    word.run()
    with pytest.raises(CsgpixError, match="finished"):
        word.step()
    # A window where a plane leaves the depth word (DEPGEN would wrap).
    with pytest.raises(CsgpixError, match="origin 0,5000000: operation 0's plane"):
        ArrayModel(prog, origin=(0, 5000000))
