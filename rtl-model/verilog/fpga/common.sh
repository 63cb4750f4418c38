# Sourced by flow.sh and seeds.sh: a device's nextpnr flags, the panel's sources and its
# synthesis. Sets $pnr and $srcs from $dev and $here; `synth NX NY` writes panel.json and
# yosys.log in the current directory.
case $dev in
    hx8k) pnr="--hx8k --package ct256" ;;
    up5k) pnr="--up5k --package sg48" ;;
    *) echo "usage: sh $(basename "$0") hx8k|up5k ..." >&2; exit 2 ;;
esac
v=$here/..
srcs="$v/sgene_derived.v $v/comparator.v $v/depgen.v $v/pixel.v $v/pixel_array.v \
$v/controller.v $v/machine.v $v/panel.v"

synth() {
    yosys -q -l yosys.log -p "read_verilog $srcs; chparam -set NX $1 -set NY $2 panel; \
synth_ice40 -top panel -json panel.json; stat" >/dev/null
}
