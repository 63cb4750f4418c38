#!/bin/sh
# How the clock nextpnr reaches depends on its placement seed: one panel synthesized once
# (yosys synth_ice40, as flow.sh does), placed and routed with each seed, and
# report-seeds-DEVICE-NXxNY.json written beside this script (the clock per seed; min,
# median, max):
#   sh seeds.sh hx8k 4x6 1 2 3 4 5 6 7 8
# flow.sh and report.sh use seed 1; this says how far from the others that is.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
dev=$1 size=$2
shift 2
nx=${size%x*} ny=${size#*x}
. "$here/common.sh"
out=${FPGA_BUILD:-$here/build}/seeds-$dev-$size
mkdir -p "$out"
cp "$here/program.hex" "$out/program.hex"
cd "$out"
synth "$nx" "$ny"
lines=$(mktemp)
for seed in "$@"; do
    ok=true
    FREQ_MHZ=20 nextpnr-ice40 $pnr --pcf "$here/$dev.pcf" --pre-pack "$here/clocks.py" \
        --freq 20 --seed "$seed" --json panel.json --log "nextpnr-$seed.log" \
        >/dev/null 2>&1 || ok=false
    fmax=$(grep -E "Max frequency for clock" "nextpnr-$seed.log" | tail -1 \
        | sed -E 's/.*: ([0-9.]+) MHz.*/\1/')
    echo "{\"seed\":$seed,\"routed\":$ok,\"fmax_mhz\":${fmax:-0}}" >>"$lines"
done
python3 - "$dev" "$size" "$lines" "$here/report-seeds-$dev-$size.json" "$*" <<'PY'
import json, statistics, sys
dev, size, lines, out, seeds = sys.argv[1:]
runs = [json.loads(l) for l in open(lines) if l.strip()]
clocks = sorted(r["fmax_mhz"] for r in runs if r["routed"])
rep = {
    "device": dev,
    "panel": size,
    "command": f"sh rtl-model/verilog/fpga/seeds.sh {dev} {size} {seeds}",
    "target_mhz": 20,
    "min_mhz": clocks[0],
    "median_mhz": round(statistics.median(clocks), 3),
    "max_mhz": clocks[-1],
    "runs": runs,
}
json.dump(rep, open(out, "w"), indent=1)
open(out, "a").write("\n")
print(f"{out}: {len(clocks)} of {len(runs)} seeds routed, "
      f"{clocks[0]}-{clocks[-1]} MHz, median {rep['median_mhz']}")
PY
rm -f "$lines"
