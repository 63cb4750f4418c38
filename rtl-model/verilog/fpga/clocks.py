# nextpnr-ice40 --pre-pack clocks.py: the clock constraint. FREQ_MHZ is set by flow.sh
# (default 20); --freq gives nextpnr the same target.
import os
ctx.addClock("clk", float(os.environ.get("FREQ_MHZ", "20")))
