#!/bin/sh
# Synthesis only (no place and route) of panels for ECP5 and Xilinx 7-series: yosys
# synth_ecp5 / synth_xilinx on panel.v at 2x2 and 4x4, LUTs and flip-flops per pixel (the
# slope between the two) and shared (the controller, DEPGEN's trees, the pads' logic), and
# the pixels that fit the devices named below (LUTs and flip-flops, no routing). Writes report-synth.json:
#   sh synth_other.sh
set -eu
here=$(cd "$(dirname "$0")" && pwd)
v=$here/..
out=$here/build/synth
mkdir -p "$out"
cp "$here/program.hex" "$out/program.hex"
cd "$out"
srcs="$v/sgene_derived.v $v/comparator.v $v/depgen.v $v/pixel.v $v/pixel_array.v \
$v/controller.v $v/machine.v $v/panel.v"
for fam in ecp5 xilinx; do
    for n in 2 4; do
        yosys -q -l "$fam-$n.log" -p "read_verilog $srcs; chparam -set NX $n -set NY $n panel; \
synth_$fam -flatten -top panel; tee -o $fam-$n.stat stat" >/dev/null
    done
done
python3 - "$here/report-synth.json" <<'PY'
import json, re, sys
def cells(path):
    c = {}
    for l in open(path):
        m = re.match(r"\s+(\S+)\s+(\d+)$", l)
        if m and not m.group(1).startswith("Number"):
            c[m.group(1)] = int(m.group(2))
    return c
def count(c, fam):
    if fam == "ecp5":
        luts = c.get("LUT4", 0)
        ffs = sum(v for k, v in c.items() if k.startswith("TRELLIS_FF"))
    else:
        luts = sum(v for k, v in c.items() if re.fullmatch(r"LUT[1-6]", k))
        ffs = sum(v for k, v in c.items() if re.fullmatch(r"FD[CPRS]E?", k))
    return luts, ffs
# (LUTs, flip-flops) of the devices: ECP5 LFE5U-25F/45F/85F (LUT4, one flip-flop each),
# Artix-7 XC7A35T/100T/200T (LUT6, two flip-flops each), from the vendors' data sheets.
devices = {"ecp5": {"LFE5U-25F": (24288, 24288), "LFE5U-45F": (43848, 43848),
                    "LFE5U-85F": (83640, 83640)},
           "xilinx": {"XC7A35T": (20800, 41600), "XC7A100T": (63400, 126800),
                      "XC7A200T": (133800, 267600)}}
rep = {"command": "sh rtl-model/verilog/fpga/synth_other.sh"}
for fam in ["ecp5", "xilinx"]:
    (l2, f2), (l4, f4) = count(cells(f"{fam}-2.stat"), fam), count(cells(f"{fam}-4.stat"), fam)
    lp, fp = (l4 - l2) / 12, (f4 - f2) / 12
    ls, fs = l2 - 4 * lp, f2 - 4 * fp
    fit = {d: int(min((n - ls) // lp, (f - fs) // fp)) for d, (n, f) in devices[fam].items()}
    rep[fam] = {"flow": f"synth_{fam}", "luts_2x2": l2, "ffs_2x2": f2, "luts_4x4": l4,
                "ffs_4x4": f4, "luts_per_pixel": round(lp, 1), "ffs_per_pixel": round(fp, 1),
                "luts_shared": round(ls), "ffs_shared": round(fs),
                "device_luts_ffs": devices[fam], "pixels_fit": fit}
    print(fam, rep[fam])
json.dump(rep, open(sys.argv[1], "w"), indent=1)
open(sys.argv[1], "a").write("\n")
PY
