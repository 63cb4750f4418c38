#!/bin/sh
# Place and route one panel of the machine (controller + NX×NY pixels, panel.v) on an iCE40:
#   sh flow.sh hx8k|up5k NX NY [FREQ_MHZ]    (run from any directory; default 20 MHz)
# yosys synth_ice40 -> nextpnr-ice40 (--pcf, --pre-pack clocks.py, --freq) -> icepack, in
# build/DEVICE-NXxNY/ (under $FPGA_BUILD when set), and one JSON line on stdout: the device, the panel, logic cells,
# block RAMs, the max clock nextpnr reports, whether it meets FREQ_MHZ, the critical path's
# ends and its logic/routing delay. Exit 1 if it does not fit or route.
# program.hex is the thesis cube's 16x16 window at (56, 90) (csgpix export-verilog --scene);
# the memory image sits in block RAM, so the logic does not depend on it.
set -eu
dev=$1 nx=$2 ny=$3 freq=${4:-20}
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
out=${FPGA_BUILD:-$here/build}/$dev-${nx}x$ny
mkdir -p "$out"
cp "$here/program.hex" "$out/program.hex"
cd "$out"
t0=$(date +%s)
synth "$nx" "$ny"
t1=$(date +%s)
ok=1
FREQ_MHZ=$freq nextpnr-ice40 $pnr --pcf "$here/$dev.pcf" --pre-pack "$here/clocks.py" \
    --freq "$freq" --seed 1 --json panel.json --asc panel.asc --log nextpnr.log \
    >/dev/null 2>&1 || ok=0
t2=$(date +%s)
[ $ok = 1 ] && icepack panel.asc panel.bin
lc=$(grep -m1 -E 'ICESTORM_LC:' nextpnr.log | sed -E 's/.*LC: *([0-9]+)\/ *([0-9]+).*/\1 \2/')
ram=$(grep -m1 -E 'ICESTORM_RAM:' nextpnr.log | sed -E 's/.*RAM: *([0-9]+)\/ *([0-9]+).*/\1 \2/')
fmax=$(grep -E "Max frequency for clock" nextpnr.log | tail -1 | sed -E 's/.*: ([0-9.]+) MHz.*/\1/')
pass=$(grep -E "Max frequency for clock" nextpnr.log | tail -1 | grep -q PASS && echo true || echo false)
# The clock's critical path (the first report; the second is the pins'): its ends, delays.
crit=$(awk '/Critical path report for clock/ {p=1; next} p && /Critical path report/ {exit} p' nextpnr.log)
path=$(echo "$crit" | grep -m1 -E 'ns logic, .* ns routing' | sed -E 's/^Info: *//')
from=$(echo "$crit" | grep -m1 'Source' | sed -E 's/.*Source //')
to=$(echo "$crit" | grep 'Sink' | tail -1 | sed -E 's/.*Sink //')
latch=$(grep -c '^Latch inferred' yosys.log || true)
warn=$(grep -c -i 'warning' yosys.log || true)
set -- $lc
lcs=${1:-0} lcmax=${2:-0}
set -- $ram
printf '{"device":"%s","nx":%s,"ny":%s,"pixels":%s,"routed":%s,"lc":%s,"lc_max":%s,"ram":%s,"ram_max":%s,"fmax_mhz":%s,"target_mhz":%s,"meets":%s,"critical_path":"%s","from":"%s","to":"%s","latches":%s,"yosys_warnings":%s,"yosys_s":%s,"nextpnr_s":%s}\n' \
    "$dev" "$nx" "$ny" $((nx * ny)) $([ $ok = 1 ] && echo true || echo false) "$lcs" "$lcmax" \
    "${1:-0}" "${2:-0}" "${fmax:-0}" "$freq" "$pass" "$path" "$from" "$to" "$latch" "$warn" \
    $((t1 - t0)) $((t2 - t1))
[ $ok = 1 ]
