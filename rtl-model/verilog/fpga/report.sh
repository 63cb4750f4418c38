#!/bin/sh
# The iCE40 report: place and route panels of several sizes (flow.sh) and write
# report-DEVICE.json beside this script:
#   sh report.sh hx8k 2x2 4x4 4x5 4x6 5x5     (the sizes docs/verilog.md lists)
#   sh report.sh up5k 2x2 3x4 4x4 4x5
# Logic cells per pixel are the slope between the smallest and the largest panel that
# routed, the controller's (and pads') share the intercept; the largest panel is the one
# with the most pixels that routed. Each run's JSON line is kept under "runs".
set -eu
here=$(cd "$(dirname "$0")" && pwd)
dev=$1
shift
lines=$(mktemp)
for s in "$@"; do
    sh "$here/flow.sh" "$dev" "${s%x*}" "${s#*x}" >>"$lines" || true
done
python3 - "$dev" "$lines" "$here/report-$dev.json" "$*" <<'PY'
import json, sys
dev, lines, out, sizes = sys.argv[1:]
runs = [json.loads(l) for l in open(lines) if l.strip()]
ok = sorted((r for r in runs if r["routed"]), key=lambda r: r["pixels"])
lo, hi = ok[0], ok[-1]
per = (hi["lc"] - lo["lc"]) / (hi["pixels"] - lo["pixels"])
rep = {
    "device": dev,
    "command": f"sh rtl-model/verilog/fpga/report.sh {dev} {sizes}",
    "lc_max": hi["lc_max"],
    "target_mhz": hi["target_mhz"],
    "lc_per_pixel": round(per, 1),
    "lc_shared": round(lo["lc"] - per * lo["pixels"]),
    "largest_panel": hi,
    "pixels": hi["pixels"],
    "clock_mhz": hi["fmax_mhz"],
    "runs": runs,
}
json.dump(rep, open(out, "w"), indent=1)
open(out, "a").write("\n")
print(f"{out}: {hi['nx']}x{hi['ny']} = {hi['pixels']} pixels, {hi['lc']}/{hi['lc_max']} LCs, "
      f"{per:.1f} LCs/pixel, Fmax {hi['fmax_mhz']} MHz")
PY
rm -f "$lines"
