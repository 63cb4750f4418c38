"""The Manifold bench's summary of issue 41's target (python/bench/manifold_peer.py)."""

import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python" / "bench"))

from manifold_peer import ROOT, floor_s, scene_file, target_summary  # noqa: E402

from conftest import cli_binary  # noqa: E402


def row(design, mesh_s, csgpix_s, n=256):
    return {"design": design, "file": f"vectors/designs/meshes/{design}.csg", "mesh_s": mesh_s,
            "grids": {str(n): {"csgpix_s": csgpix_s, "ratio_mesh": mesh_s / csgpix_s}}}


def test_the_target_counts_only_designs_whose_mesh_takes_50_ms():
    rows = [
        row("a", 0.10, 0.05),   # 2×
        row("b", 0.06, 0.12),   # 0.5×
        row("c", 0.30, 0.03),   # 10×
        row("quick", 0.01, 0.10),  # mesh under 50 ms: not counted
        {"design": "s", "file": "vectors/scenes/twelve.csg", "mesh_s": 1.0,
         "grids": {"256": {"ratio_mesh": 0.1}}},  # not a design
    ]
    t = target_summary(rows, 256, 0.02)
    assert t["designs"] == 3
    assert t["median_mesh_over_csgpix"] == 2.0
    assert (t["below_1x"], t["below_2x"]) == (1, 1)
    assert [d for d, _ in t["lowest"]] == ["b", "a", "c"]
    # At a 20 ms floor: 5×, 3×, 15×; the median 5×, none below 2×.
    assert abs(t["median_mesh_over_floor"] - 5.0) < 1e-12
    assert t["below_2x_at_floor"] == 0


def test_designs_drawn_in_a_substitute_font_are_named():
    rows = [row("tag", 0.10, 0.05), row("plain", 0.10, 0.05)]
    rows[0]["grids"]["256"]["font_substituted"] = True
    assert target_summary(rows, 256, None)["font_substituted"] == ["tag"]
    del rows[0]["grids"]["256"]["font_substituted"]
    assert target_summary(rows, 256, None)["font_substituted"] == []


def test_no_design_over_50_ms_gives_no_summary():
    assert target_summary([row("quick", 0.01, 0.10)], 256, 0.02) is None


def test_the_floor_is_a_whole_process_writing_the_volume(tmp_path):
    f = floor_s(32, cli_binary(), tmp_path)
    assert f is not None and 0 < f < 30
    assert not (tmp_path / "floor.nrrd").exists()


def test_a_design_that_ships_its_font_is_read_beside_it(tmp_path):
    meshes = ROOT / "vectors/designs/meshes"
    plain = meshes / "allen-key-handle.csg"
    assert scene_file(plain, tmp_path) == plain
    heart = scene_file(meshes / "birthday-heart.csg.gz", tmp_path)
    assert heart == tmp_path / "birthday-heart" / "birthday-heart.csg"
    assert (heart.parent / "Magiera Script.ttf").is_file()
    assert "Magiera" in heart.read_text()
    # csgpix draws it in that font: no fontconfig substitute, no warning about the font.
    run = subprocess.run([str(cli_binary()), "voxelize", str(heart), "--res", "16",
                          "-o", str(tmp_path / "heart.nrrd")], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert "font" not in run.stderr, run.stderr
