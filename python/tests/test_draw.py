"""compile/render against the command line and between the models; verify_select against
the command line's JSON."""

import json

import numpy as np
import pytest

import csgpix
from conftest import ROOT, SCENES, THESIS, run_cli


def cli_render_json(tmp, *args):
    r = run_cli("render", *args, "--json", "-o", str(tmp / "x.png"))
    assert r.returncode == 0, r.stderr.decode()
    return json.loads(r.stdout)


@pytest.mark.parametrize(
    "scene,size,kw,args",
    [
        ([THESIS / "cube.dl"], (96, 80), {}, []),
        ([THESIS / "box1.dl", THESIS / "box2.dl"], (256, 256), dict(clip="A.!B"), ["--clip", "A.!B"]),
        ([SCENES / "csg-logo.csg"], (96, 80), dict(view="iso"), ["--view", "iso"]),
    ],
)
def test_render_matches_the_command_line_and_the_models_agree(tmp, scene, size, kw, args):
    w, h = size
    prog = csgpix.compile([str(s) for s in scene], w, h, **kw)
    word = csgpix.render(prog, model="word")
    cycle = csgpix.render(prog, model="cycle")
    assert word.codes.shape == (h, w) and word.codes.dtype == np.uint8
    assert np.array_equal(word.codes, cycle.codes)
    assert word.cycles == cycle.cycles == prog.cycles()
    assert (word.codes > 0).any()
    rep = cli_render_json(tmp, *[str(s) for s in scene], "--size", f"{w}x{h}", *args)
    assert rep["cycles"] == word.cycles and rep["operations"] == len(prog)
    # The float reference differs from the array at most on a few edge pixels (§5.4).
    flt = csgpix.render(prog, model="float")
    assert np.mean(flt.codes != word.codes) < 0.02
    assert word.rgb().shape == (h, w, 3)
    assert np.array_equal(word.rgb()[word.codes == 0], np.tile(csgpix.palette()[0], ((word.codes == 0).sum(), 1)))


@pytest.mark.parametrize("equations", ["derived", "printed"])
def test_verify_select_reports_what_the_command_line_reports(equations):
    got = csgpix.verify_select(equations)
    r = run_cli("verify-select", "--equations", equations, "--json")
    assert r.returncode == (0 if equations == "derived" else 1)
    assert got == json.loads(r.stdout)
    bad = sum(len(s["mismatches"]) for s in got)
    assert (bad == 0) == (equations == "derived")


def test_compile_errors_point_into_the_display_list():
    bad = ROOT / "tests" / "data" / "identity" / "bad.dl"
    with pytest.raises(csgpix.CsgpixError) as e:
        csgpix.compile(str(bad))
    assert e.value.file == str(bad) and e.value.line == 3 and e.value.col == 5
    with pytest.raises(csgpix.CsgpixError, match="--clip"):
        csgpix.compile([str(THESIS / "box1.dl"), str(THESIS / "box2.dl")], clip="A.!")
