"""Build ``pixel_array`` under Icarus Verilog and run the cocotb testbench
(``pixel_array_tb.py``) on it with cocotb's Python runner: no Makefile.

    python python/tests/cocotb/runner.py [BUILD_DIR]

writes the Verilog from :func:`csgpix.verilog_files` into BUILD_DIR/src (default
``python/tests/cocotb/sim_build``), builds, runs every test of the testbench, prints each
result and exits 0 only when all passed.
"""

from __future__ import annotations

import sys
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Dict, List, Optional, Tuple

HERE = Path(__file__).resolve().parent


def write_sources(
    build_dir: Path, patch: Optional[Dict[str, Tuple[str, str]]] = None
) -> List[Path]:
    """Write the synthesizable sources of pixel_array for the testbench's array into
    BUILD_DIR/src; returns them, leaves first. `patch` maps a file to (text, replacement):
    a deliberately faulty DUT, for the test that the testbench can fail."""
    import csgpix

    if str(HERE) not in sys.path:
        sys.path.insert(0, str(HERE))
    import pixel_array_tb as tb

    files = csgpix.verilog_files(tb.program("cube"))
    src = build_dir / "src"
    src.mkdir(parents=True, exist_ok=True)
    for name, (old, new) in (patch or {}).items():
        assert files[name].count(old) == 1, f"{name}: {old!r} is not in it once"
        files[name] = files[name].replace(old, new)
    for name, text in files.items():
        (src / name).write_text(text)
    return [src / n for n in files["pixel_array.f"].split()]


def run(
    build_dir: Path,
    testcase: Optional[str] = None,
    patch: Optional[Dict[str, Tuple[str, str]]] = None,
) -> Path:
    """Build and run the testbench's tests (or only `testcase`) on pixel_array (`patch`ed:
    see write_sources); returns the results XML (cocotb's xUnit file)."""
    from cocotb_tools.runner import get_runner

    build_dir = Path(build_dir).resolve()
    sources = write_sources(build_dir, patch)
    runner = get_runner("icarus")
    runner.build(
        sources=sources,
        hdl_toplevel="pixel_array",
        build_dir=build_dir,
        always=True,
        timescale=("1ns", "1ps"),
    )
    xml = build_dir / "results.xml"
    try:
        return runner.test(
            test_module="pixel_array_tb",
            hdl_toplevel="pixel_array",
            build_dir=build_dir,
            test_dir=build_dir,
            results_xml=str(xml),
            testcase=testcase,
        )
    except SystemExit:
        # Under pytest the runner exits on a failed test; the results file says which.
        return xml


def results(xml: Path) -> List[Tuple[str, str, str]]:
    """(test, "passed" | "failed" | "skipped", message) of every test in the results."""
    out = []
    for case in ET.parse(xml).getroot().iter("testcase"):
        bad = case.find("failure")
        if bad is None:
            bad = case.find("error")
        if bad is not None:
            out.append((case.get("name"), "failed", bad.get("message") or bad.text or ""))
        elif case.find("skipped") is not None:
            out.append((case.get("name"), "skipped", ""))
        else:
            out.append((case.get("name"), "passed", ""))
    return out


def main() -> int:
    build = Path(sys.argv[1]) if len(sys.argv) > 1 else HERE / "sim_build"
    xml = run(build)
    rs = results(xml)
    for name, status, msg in rs:
        print(f"{status.upper():7} {name}" + (f": {msg}" if msg else ""))
    return 0 if rs and all(s == "passed" for _, s, _ in rs) else 1


if __name__ == "__main__":
    sys.exit(main())
