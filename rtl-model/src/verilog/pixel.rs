//! One pixel processor (Figure 2.9) and an n×m array of them as Verilog, driven by the control
//! word a controller broadcasts every clock, and the control stream of a program.
//!
//! * [`pixel_module`]: registers A F B C (depth, circulating shift registers, bit k at bit 0
//!   in clock k), D E G (colour), the latched code S_hi S_lo, the pixel's DEPGEN adder (one
//!   carry flip-flop), the comparator, SGENE (`derived`), TRANSD/TRANSC and the clipping stack.
//! * [`array_module`]: `pixel_array`, NX×NY pixels sharing the control word, and DEPGEN's
//!   two trees (`depgen`, [`super::depgen`], §2.4): the x tree puts `x·dx` on column
//!   line x, the y tree `c0 + y·dy` on row line y (modulo 2^N_D, LSB first), from the plane
//!   coefficients' bits in the control word; pixel (x, y) adds column x and row y.
//! * [`testbench`]: `tb_array` reads a control stream (`$readmemh`) and the expected state of
//!   every pixel after every clock (written from the `cycle` model by [`super::stimulus`]),
//!   clocks the stream into the array and compares every register of every pixel after every
//!   clock, naming the clock, the pixel and the register of each mismatch.
//! * [`control_stream`]: the stream of a program, one word per clock, from [`Window::of`] and
//!   the same sequencing as the models (pending transfer, stack pointer, DEPGEN fill).
//!
//! The pixel does what `cycle.rs` does in one clock: TRANSD/TRANSC write bit k of the register
//! the previous window's code targets, DEPGEN's sum goes into bit k of A (and MEM D's bit into
//! D), and the comparator takes bit k of both operands as just written.

use crate::array::Sequencer;
use crate::comparator::BitRole;
use crate::program::{stack_effect, CReg, Decide, Decode, Op, Reg, Transfer, Window};
use crate::select::EquationSet;
use crate::state::ArrayConfig;

/// Control word fields: (name, first bit, width). `dg_*` are DEPGEN's root inputs: bit k of
/// a plane's c0, dx and dy, [`ArrayConfig::depgen_latency`] clocks before the window's clock k
/// (`dg_first` with bit 0); the trees in `pixel_array` turn them into the line bits.
pub const FIELDS: [(&str, usize, usize); 30] = [
    ("last", 0, 1),
    ("op_end", 1, 1),
    ("win", 2, 1),
    ("col_en", 3, 1),
    ("first", 4, 1),
    ("is_sign", 5, 1),
    ("is_ovf", 6, 1),
    ("cmp_en", 7, 1),
    ("lhs", 8, 2),
    ("rhs", 10, 2),
    ("st_en", 12, 1),
    ("d_en", 13, 1),
    ("d_bit", 14, 1),
    ("tr_en", 15, 1),
    ("tr_dst", 16, 2),
    ("tr_src", 18, 2),
    ("tr_cpair", 20, 2),
    ("tr_compose", 22, 1),
    ("int_bit", 23, 1),
    ("dec_latch", 24, 1),
    ("dec_pos", 25, 2),
    ("ext", 27, 6),
    ("dec_push", 33, 1),
    ("stk_en", 34, 1),
    ("stk_op", 35, 2),
    ("sp", 37, 6),
    ("dg_first", 43, 1),
    ("dg_c0", 44, 1),
    ("dg_dx", 45, 1),
    ("dg_dy", 46, 1),
];

/// Bits of the control word.
pub const CW: usize = 48;

/// The testbenches hold at most 2^this control words (`MAXCLK`): longer streams are refused
/// before they are written.
pub const MAX_CLOCKS_LOG2: u32 = 20;

pub(crate) fn field(name: &str) -> (usize, usize) {
    let f = FIELDS.iter().find(|f| f.0 == name).expect("field");
    (f.1, f.2)
}

/// The Verilog slice of a field of control word `c`: `c[9:8]`.
fn slice(name: &str) -> String {
    let (lo, w) = field(name);
    if w == 1 {
        format!("c[{lo}]")
    } else {
        format!("c[{}:{lo}]", lo + w - 1)
    }
}

/// The broadcast control ports, in order, with their widths.
const PORTS: [(&str, usize); 24] = [
    ("win", 1),
    ("col_en", 1),
    ("first", 1),
    ("is_sign", 1),
    ("cmp_en", 1),
    ("lhs", 2),
    ("rhs", 2),
    ("st_en", 1),
    ("d_en", 1),
    ("d_bit", 1),
    ("tr_en", 1),
    ("tr_dst", 2),
    ("tr_src", 2),
    ("tr_cpair", 2),
    ("tr_compose", 1),
    ("int_bit", 1),
    ("dec_latch", 1),
    ("dec_pos", 2),
    ("ext", 6),
    ("dec_push", 1),
    ("stk_en", 1),
    ("stk_op", 2),
    ("sp", 6),
    ("rst", 1),
];

/// The control word's fields that are inputs of `pixel_array`, in [`FIELDS`] order: every
/// field but `last` and `op_end` (the testbench's bookkeeping) and `is_ovf` (the comparator's
/// bit counter gives each bit its role). `clk` and `rst` are its other inputs. A testbench
/// that drives `pixel_array` itself (rather than through `tb_array`) sets each of these
/// ports to its field of the clock's word.
pub fn array_inputs() -> Vec<&'static str> {
    FIELDS
        .iter()
        .map(|f| f.0)
        .filter(|n| PORTS.iter().any(|p| p.0 == *n) || n.starts_with("dg_"))
        .collect()
}

fn port_decls() -> String {
    PORTS
        .iter()
        .map(|(n, w)| match (*n, *w) {
            (_, 1) => format!("    input wire {n},\n"),
            // The controller's pointer serves any stack depth; a pixel reads the bits its
            // own stack needs (`si`).
            ("sp", _) => format!(
                "    /* verilator lint_off UNUSEDSIGNAL */\n    input wire [{}:0] {n},\n    \
                 /* verilator lint_on UNUSEDSIGNAL */\n",
                w - 1
            ),
            _ => format!("    input wire [{}:0] {n},\n", w - 1),
        })
        .collect()
}

fn port_conns(indent: &str) -> String {
    PORTS
        .iter()
        .map(|(n, _)| format!("{indent}.{n}({n}),\n"))
        .collect()
}

/// `pixel`: one pixel processor. Register codes on `lhs rhs tr_dst tr_src` are those of
/// [`Reg`] (A 0, F 1, B 2, C 3); `tr_cpair` 1 is E ← D, 2 is G ← E; `dec_pos` 0-3 picks
/// SGENE's front, back, close or second pair; `ext` is {P, X, Y, H, S, L}; `stk_op` 0 AND,
/// 1 OR, 2 NOT, 3 apply (pop LL' into the code).
pub fn pixel_module(cfg: &ArrayConfig, set: &EquationSet) -> String {
    let f = &cfg.fmt;
    format!(
        "// One pixel processor, seed 001 Figure 2.9: depth registers A F B C, colour registers
// D E G, the select code S_hi S_lo, the pixel's DEPGEN adder, compare, SGENE ({set}),
// TRANSD/TRANSC and the clipping stack. Every control input is broadcast by the controller
// to the whole array each clock; only col_bit and row_bit (DEPGEN's lines) differ by pixel.
// Depth and colour registers circulate: bit k of the window sits at bit 0 in clock k.
module pixel #(parameter F = {ff}, I = {ii}, O = {oo}, CB = {cb}, SD = {sd}) (
    input wire clk,
{ports}    input wire col_bit, row_bit,
    output wire [CB-1:0] image,
    output wire [4*(F+I+O+1)+3*CB+11+$clog2(F+I+O+1)+SD-1:0] state
);
    localparam W = F + I + O + 1;
    reg [W-1:0] rA, rF, rB, rC;
    reg [CB-1:0] rD, rE, rG;
    reg s_hi, s_lo, carry;
    reg [SD-1:0] stack;

    // TRANSD/TRANSC: the latched code decoded (Sel: 00 Put A, 10 Put 0, 01 Keep, 11 Put 1;
    // Compose: 00 Put 1, 01 Put F, 1- Keep C).
    wire put_src = tr_compose ? ~s_hi & s_lo : ~s_hi & ~s_lo;
    wire put0 = tr_compose ? 1'b0 : s_hi & ~s_lo;
    wire keep = tr_compose ? s_hi : ~s_hi & s_lo;
    wire put1 = tr_compose ? ~s_hi & ~s_lo : s_hi & s_lo;
    wire [3:0] cur = {{rC[0], rB[0], rF[0], rA[0]}};
    wire src = cur[tr_src];
    wire one = ~is_sign;  // the Put-1 word 011...1
    // A is never a transfer's destination: F, B, C are (tr_dst 1, 2, 3).
    wire hit_F = tr_en & tr_dst == 2'd1;
    wire hit_B = tr_en & tr_dst == 2'd2;
    wire hit_C = tr_en & tr_dst == 2'd3;
    wire nF = hit_F ? put_src & src | keep & rF[0] | put1 & one : rF[0];
    wire nB = hit_B ? put_src & src | keep & rB[0] | put1 & one : rB[0];
    wire nC = hit_C ? put_src & src | keep & rC[0] | put1 & one : rC[0];
    wire csrc = tr_cpair == 2'd1 ? rD[0] : rE[0];
    wire cen = tr_en & col_en;
    wire nE = cen && tr_cpair == 2'd1 ? put_src & csrc | keep & rE[0] | put0 & int_bit : rE[0];
    wire nG = cen && tr_cpair == 2'd2 ? put_src & csrc | keep & rG[0] | put0 & int_bit : rG[0];

    // DEPGEN: the pixel's one-bit serial adder of its column and row lines, into A; MEM D.
    wire cin = first ? 1'b0 : carry;
    wire sum = col_bit ^ row_bit ^ cin;
    wire nA = st_en ? sum : rA[0];
    wire nD = d_en ? d_bit : rD[0];

    // compare: the operands as written this clock.
    wire [3:0] nxt = {{nC, nB, nF, nA}};
    wire N, J, T, M, Nn, Jn, Tn, Mn;
    wire [$clog2(W)+3:0] cmp_regs;
    comparator #(.F(F), .I(I), .O(O)) cmp(.clk(clk), .rst(rst), .en(cmp_en), .first(first),
        .a(nxt[lhs]), .r(nxt[rhs]), .N(N), .J(J), .T(T), .M(M),
        .Nn(Nn), .Jn(Jn), .Tn(Tn), .Mn(Mn), .regs(cmp_regs));

    // SGENE on the flags after this clock; the stage selector picks the pair.
    wire front_S1, front_S2, back_S1, back_S2, close_S1, close_S2, clip_LL, second_S3, second_S4;
    sgene_{set} sgene(.L(ext[0]), .S(ext[1]), .H(ext[2]), .Y(ext[3]), .X(ext[4]), .P(ext[5]),
        .N(Nn), .J(Jn), .T(Tn), .M(Mn),
        .front_S1(front_S1), .front_S2(front_S2), .back_S1(back_S1), .back_S2(back_S2),
        .close_S1(close_S1), .close_S2(close_S2), .clip_LL(clip_LL),
        .second_S3(second_S3), .second_S4(second_S4));
    wire [7:0] pairs = {{second_S3, second_S4, close_S1, close_S2, back_S1, back_S2,
        front_S1, front_S2}};
    wire [1:0] code = pairs[2 * dec_pos +: 2];

    // clipping stack: one bit per level, the stack pointer sp is the controller's; si is
    // sp as wide as an index into the stack (programs never leave 0..SD).
    localparam SW = SD > 1 ? $clog2(SD) : 1;
    wire [SW-1:0] si = sp[SW-1:0];
    wire top = stack[si - 1'b1];
    wire under = stack[si - 2'd2];

    always @(posedge clk) begin
        if (rst) begin
            rA <= {{1'b0, {{W-1{{1'b1}}}}}};
            rF <= {{1'b0, {{W-1{{1'b1}}}}}};
            rB <= {{1'b0, {{W-1{{1'b1}}}}}};
            rC <= {{1'b0, {{W-1{{1'b1}}}}}};
            rD <= {{CB{{1'b0}}}};
            rE <= {{CB{{1'b0}}}};
            rG <= {{CB{{1'b0}}}};
            {{s_hi, s_lo}} <= 2'b01;
            carry <= 1'b0;
            stack <= {{SD{{1'b0}}}};
        end else begin
            if (win) begin
                rA <= {{nA, rA[W-1:1]}};
                rF <= {{nF, rF[W-1:1]}};
                rB <= {{nB, rB[W-1:1]}};
                rC <= {{nC, rC[W-1:1]}};
            end
            if (win & col_en) begin
                rD <= {{nD, rD[CB-1:1]}};
                rE <= {{nE, rE[CB-1:1]}};
                rG <= {{nG, rG[CB-1:1]}};
            end
            if (st_en) carry <= col_bit & row_bit | cin & (col_bit ^ row_bit);
            if (dec_latch) {{s_hi, s_lo}} <= code;
            if (dec_push) stack[si] <= clip_LL;
            if (stk_en)
                case (stk_op)
                    2'd0: stack[si - 2'd2] <= under & top;
                    2'd1: stack[si - 2'd2] <= under | top;
                    2'd2: stack[si - 1'b1] <= ~top;
                    default: {{s_hi, s_lo}} <= {{~top, 1'b1}};
                endcase
        end
    end
    assign image = rG;
    // Observation: every register and the flags, {{stack, carry, comparator {{k, sign, ovf,
    // eq, lt}}, M, T, J, N, S_lo, S_hi, G, E, D, C, B, F, A}} (pixel.rs state_fields).
    assign state = {{stack, carry, cmp_regs, M, T, J, N, s_lo, s_hi, rG, rE, rD, rC, rB, rF, rA}};
endmodule
",
        set = set.name,
        ff = f.frac,
        ii = f.int,
        oo = f.ovf,
        cb = cfg.colour_bits,
        sd = cfg.stack_depth,
        ports = port_decls(),
    )
}

/// `pixel_array`: NX×NY pixels on the broadcast control word and DEPGEN's two trees
/// (`depgen`, §2.4): the x tree puts `x·dx` on column line x, the y tree `c0 + y·dy` on
/// row line y, and pixel (x, y) adds the two. Both trees get the larger number of levels, so
/// a plane's bit k presented on `dg_*` reaches every pixel `LEVELS + 1` clocks later.
pub fn array_module(cfg: &ArrayConfig) -> String {
    format!(
        "// An NX×NY array of pixel processors (seed 001 Figure 2.8): one control word for all,
// and DEPGEN (§2.4): the x tree puts x*dx on column line x, the y tree c0 + y*dy on row
// line y, from the coefficient bits dg_c0, dg_dx, dg_dy (LSB first, dg_first with bit 0),
// LEVELS + 1 clocks after the controller presents them.
module pixel_array #(parameter NX = {nx}, NY = {ny}) (
    input wire clk,
{ports}    input wire dg_first, dg_c0, dg_dx, dg_dy,
    output wire [NX*NY*{cb}-1:0] image
);
    localparam LEVELS = $clog2(NX) > $clog2(NY) ? $clog2(NX) : $clog2(NY);
    wire [NX-1:0] col;
    wire [NY-1:0] row;
    depgen #(.N(NX), .LEVELS(LEVELS)) xtree(.clk(clk), .rst(rst), .first(dg_first),
        .root(1'b0), .d(dg_dx), .line(col));
    depgen #(.N(NY), .LEVELS(LEVELS)) ytree(.clk(clk), .rst(rst), .first(dg_first),
        .root(dg_c0), .d(dg_dy), .line(row));
    genvar x, y;
    generate
        for (y = 0; y < NY; y = y + 1) begin : gy
            for (x = 0; x < NX; x = x + 1) begin : gx
                pixel p(.clk(clk),
{conns}                    .col_bit(col[x]), .row_bit(row[y]),
                    // The observation port serves the one-pixel checks; the array
                    // reads its pixels through `image`.
                    /* verilator lint_off PINCONNECTEMPTY */
                    .image(image[(y * NX + x) * {cb} +: {cb}]), .state()
                    /* verilator lint_on PINCONNECTEMPTY */);
            end
        end
    endgenerate
endmodule
",
        nx = cfg.width,
        ny = cfg.height,
        cb = cfg.colour_bits,
        ports = port_decls(),
        conns = port_conns("                    "),
    )
}

/// The fields of a pixel's `state` port, LSB first: (name, bits). Every register of the
/// pixel (A F B C, D E G, S_hi S_lo, the comparator's lt eq ovf sign and bit counter k, the
/// DEPGEN adder's carry, the stack) and the flags N J T M the comparator derives.
pub fn state_fields(cfg: &ArrayConfig) -> Vec<(&'static str, usize)> {
    let (w, cb) = (cfg.fmt.bits() as usize, cfg.colour_bits as usize);
    let kw = (usize::BITS - (w - 1).leading_zeros()) as usize;
    vec![
        ("A", w),
        ("F", w),
        ("B", w),
        ("C", w),
        ("D", cb),
        ("E", cb),
        ("G", cb),
        ("S_hi", 1),
        ("S_lo", 1),
        ("N", 1),
        ("J", 1),
        ("T", 1),
        ("M", 1),
        ("lt", 1),
        ("eq", 1),
        ("ovf", 1),
        ("sign", 1),
        ("k", kw),
        ("carry", 1),
        ("stack", cfg.stack_depth),
    ]
}

/// Bits of a pixel's `state` port.
pub fn state_width(cfg: &ArrayConfig) -> usize {
    state_fields(cfg).iter().map(|f| f.1).sum()
}

/// The module header, the array and its control connections, shared by both testbenches.
fn tb_common(cfg: &ArrayConfig, name: &str) -> String {
    let conns: String = PORTS
        .iter()
        .map(|(n, _)| {
            if *n == "rst" {
                "        .rst(rst),\n".to_string()
            } else {
                format!("        .{n}({}),\n", slice(n))
            }
        })
        .chain(
            ["dg_first", "dg_c0", "dg_dx", "dg_dy"]
                .iter()
                .map(|n| format!("        .{n}({}),\n", slice(n))),
        )
        .collect();
    format!(
        "module {name};
    localparam NX = {nx}, NY = {ny}, CW = {CW}, MAXCLK = 1 << {MAX_CLOCKS_LOG2};
    localparam SW = {sw};
    reg clk = 0, rst = 1;
    reg [CW-1:0] mem [0:MAXCLK-1];
    reg [CW-1:0] c = {{CW{{1'b0}}}};
    reg [8*256-1:0] file;
    reg done = 0;
    integer t = 0, ops = 0;
    wire [NX*NY*{cb}-1:0] image;
    pixel_array #(.NX(NX), .NY(NY)) dut(.clk(clk),
{conns}        .image(image));
",
        nx = cfg.width,
        ny = cfg.height,
        cb = cfg.colour_bits,
        sw = state_width(cfg),
    )
}

/// A testbench's start: the control stream (`+ctl`, `control.hex` by default) into `mem`,
/// the expected states (`+exp`, `expected.hex`) opened or `CHECK off`, one clock in reset.
pub(crate) const OPEN_STREAMS: &str =
    "        if (!$value$plusargs(\"ctl=%s\", file)) file = \"control.hex\";
        if (!$value$plusargs(\"exp=%s\", efile)) efile = \"expected.hex\";
        $readmemh(file, mem);
        fd = $fopen(efile, \"r\");
        if (fd == 0) $display(\"CHECK off\");
        #1 clk = 1; #1 clk = 0; rst = 0;
";

/// `tb_array`: reads the control stream `+ctl=FILE` (default `control.hex`, one word per
/// clock until the word with `last`) and the expected states `+exp=FILE` (default
/// `expected.hex`): after every clock, one line per pixel (row-major), the pixel's `state` in
/// hex. After each clock it compares every field of every pixel's `state` with the expected
/// line and prints `MISMATCH clock x y field expected got` (it stops after the clock with the
/// 20th), then `CLOCKS n OPS m MISMATCHES b`. Without the expected file it only runs (`CHECK
/// off`).
pub fn testbench(cfg: &ArrayConfig) -> String {
    format!(
        "// Runs a control stream through pixel_array and compares every register of every pixel
// with the expected state after every clock; generated, do not edit. Control word fields:
// pixel.rs FIELDS; state fields: pixel.rs state_fields.
{common}{tasks}    initial begin
{open}        while (!done && bad < 20) begin
            c = mem[t];
            #1 clk = 1; #1 clk = 0;
            if (fd != 0) check_all;
            if (c[1]) ops = ops + 1;
            done = c[0];
            t = t + 1;
        end
        $display(\"CLOCKS %0d OPS %0d MISMATCHES %0d\", t, ops, bad);
        $finish;
    end
endmodule
",
        common = tb_common(cfg, "tb_array"),
        tasks = check_tasks(cfg, "dut"),
        open = OPEN_STREAMS,
    )
}

/// The expected-state check of a testbench (`tb_array`, `tb_machine`): the tasks `field`,
/// `check` and `check_all`, which read one line per pixel of `+exp` and compare it with the
/// pixel's `state` (reached as `{array}.gy[y].gx[x].p.state`), counting in `bad`.
pub(crate) fn check_tasks(cfg: &ArrayConfig, array: &str) -> String {
    let mut fields = String::new();
    let mut lo = 0;
    for (name, w) in state_fields(cfg) {
        fields += &format!("                field(\"{name}\", {lo}, {w}, x, y);\n");
        lo += w;
    }
    let mut all = String::new();
    for y in 0..cfg.height {
        for x in 0..cfg.width {
            all += &format!(
                "            st[{}] = {array}.gy[{y}].gx[{x}].p.state;\n",
                y * cfg.width + x
            );
        }
    }
    format!(
        "    reg [8*256-1:0] efile;
    reg [SW-1:0] s, e;
    reg [SW-1:0] st [0:NX*NY-1];
    integer fd, n, p, bad = 0;
    task field(input [8*8-1:0] name, input integer lo, input integer w, input integer x,
            input integer y);
        reg [SW-1:0] m;
        begin
            m = ({{SW{{1'b1}}}} >> (SW - w)) << lo;
            if ((s & m) !== (e & m)) begin
                bad = bad + 1;
                if (bad <= 20)
                    $display(\"MISMATCH %0d %0d %0d %0s %0h %0h\", t + 1, x, y, name,
                        (e & m) >> lo, (s & m) >> lo);
            end
        end
    endtask
    task check(input integer x, input integer y);
        begin
            n = $fscanf(fd, \"%h\\n\", e);
            if (n != 1) begin
                $display(\"EXPECTED ends before clock %0d\", t + 1);
                $finish;
            end
            if (s !== e) begin
{fields}            end
        end
    endtask
    task check_all;
        begin
{all}            for (p = 0; p < NX * NY; p = p + 1) begin
                s = st[p];
                check(p % NX, p / NX);
            end
        end
    endtask
"
    )
}

/// `tb_bench`: runs the control stream `+reps=R` times (default 1) through `pixel_array` with
/// no checks, for timing, then prints the image (G of every pixel, pixel (0, 0) in the low
/// byte, hex) as `IMAGE` lines, a row each, top row first, and `CLOCKS` with the clocks run. Not checked in: the speed test writes
/// it for each array size.
pub fn bench_testbench(cfg: &ArrayConfig) -> String {
    format!(
        "// Runs a control stream R times through pixel_array for timing; generated.
{common}    integer reps, r, clocks = 0;
    initial begin
        if (!$value$plusargs(\"ctl=%s\", file)) file = \"control.hex\";
        if (!$value$plusargs(\"reps=%d\", reps)) reps = 1;
        $readmemh(file, mem);
        #1 clk = 1; #1 clk = 0; rst = 0;
        for (r = 0; r < reps; r = r + 1) begin
            done = 0; t = 0;
            while (!done) begin
                c = mem[t];
                #1 clk = 1; #1 clk = 0;
                done = c[0];
                t = t + 1;
                clocks = clocks + 1;
            end
        end
        // A row a line ($display takes at most 8192 bits), the top row first.
        for (r = {ny} - 1; r >= 0; r = r - 1)
            $display(\"IMAGE %h\", image[r * {row} +: {row}]);
        $display(\"CLOCKS %0d\", clocks);
        $finish;
    end
endmodule
",
        common = tb_common(cfg, "tb_bench"),
        ny = cfg.height,
        row = cfg.width * cfg.colour_bits as usize,
    )
}

/// One clock's control word.
#[derive(Clone, Debug)]
struct Word(Vec<bool>);

impl Word {
    fn new() -> Word {
        Word(vec![false; CW])
    }

    fn set(&mut self, name: &str, v: u64) {
        let (lo, w) = field(name);
        assert!(w == 64 || v >> w == 0, "{name} = {v} does not fit {w} bits");
        for i in 0..w {
            self.0[lo + i] = v >> i & 1 == 1;
        }
    }

    fn hex(&self) -> String {
        let digits = self.0.len().div_ceil(4);
        (0..digits)
            .rev()
            .map(|d| {
                let v = (0..4)
                    .filter(|b| self.0.get(d * 4 + b) == Some(&true))
                    .fold(0, |a, b| a | 1 << b);
                char::from_digit(v, 16).unwrap()
            })
            .collect()
    }
}

fn reg_code(r: Reg) -> u64 {
    r as u64
}

/// The control stream of `ops` (checked with [`crate::array::check_program`] first): one hex
/// word per line, one line per clock, `op_end` on the last clock of every operation and of the
/// flush window, `last` on an idle clock after them. Clocks = the models' cycle count. DEPGEN's
/// root bits of a streamed plane (c0, dx, dy, LSB first) go [`ArrayConfig::depgen_latency`]
/// clocks ahead of the window that takes them into A: the fill the models count before the
/// first stream is the trees' pipeline, and later planes overlap the windows before them.
pub fn control_stream(cfg: &ArrayConfig, set: &EquationSet, ops: &[Op]) -> String {
    let nd = cfg.fmt.bits() as usize;
    let lat = cfg.depgen_latency() as usize;
    // (clock, coefficients, bit k): clock takes bit k of the plane into A.
    let mut roots: Vec<(usize, i64, i64, i64, usize)> = vec![];
    let mut seq = Sequencer::default();
    let mut words: Vec<Word> = vec![];
    let transfer = |w: &mut Word, t: &Transfer, k: usize| {
        w.set("tr_en", 1);
        w.set("tr_dst", reg_code(t.dst));
        w.set("tr_src", reg_code(t.src));
        w.set(
            "tr_cpair",
            match t.colour {
                None => 0,
                Some((CReg::E, CReg::D)) => 1,
                Some((CReg::G, CReg::E)) => 2,
                Some(other) => panic!("no colour path {other:?}"),
            },
        );
        w.set("tr_compose", (t.decode == Decode::Compose) as u64);
        w.set("int_bit", (t.interior as u64) >> k & 1);
    };
    let clock = |w: &mut Word, k: usize| {
        w.set("win", 1);
        w.set("col_en", (k < cfg.colour_bits as usize) as u64);
        w.set("first", (k == 0) as u64);
        w.set(
            "is_sign",
            (BitRole::of(&cfg.fmt, k as u32) == BitRole::Sign) as u64,
        );
        w.set(
            "is_ovf",
            (BitRole::of(&cfg.fmt, k as u32) == BitRole::Overflow) as u64,
        );
    };
    for op in ops {
        match Window::of(op, set) {
            Some(win) => {
                let clocks = seq.window_clocks(cfg, &win) as usize;
                for _ in nd..clocks {
                    words.push(Word::new());
                }
                let (l, s, h, y, x, p) = match *op {
                    Op::Plane { l, s, h, y, .. } => (l, s, h, y, false, false),
                    Op::Close { l } => (l, false, false, false, false, false),
                    Op::ClipPlane { h, y, x, .. } => (false, false, h, y, x, false),
                    Op::Compose { p } => (false, false, false, false, false, p),
                    _ => unreachable!(),
                };
                let ext = [l, s, h, y, x, p]
                    .iter()
                    .enumerate()
                    .fold(0, |a, (i, b)| a | (*b as u64) << i);
                for k in 0..nd {
                    let mut w = Word::new();
                    clock(&mut w, k);
                    w.set("cmp_en", 1);
                    w.set("lhs", reg_code(win.lhs));
                    w.set("rhs", reg_code(win.rhs));
                    w.set("ext", ext);
                    if let Some((c, colour)) = win.stream {
                        w.set("st_en", 1);
                        roots.push((words.len(), c.c0, c.dx, c.dy, k));
                        if let Some(col) = colour {
                            if k < cfg.colour_bits as usize {
                                w.set("d_en", 1);
                                w.set("d_bit", (col as u64) >> k & 1);
                            }
                        }
                    }
                    if let Some(t) = &seq.pending {
                        transfer(&mut w, t, k);
                    }
                    if k == nd - 1 {
                        w.set("op_end", 1);
                        w.set("sp", seq.sp as u64);
                        match win.decide {
                            Decide::Latch(..) => {
                                w.set("dec_latch", 1);
                                w.set("dec_pos", win.position as u64 - 1);
                            }
                            Decide::Push(_) => w.set("dec_push", 1),
                        }
                    }
                    words.push(w);
                }
                if matches!(win.decide, Decide::Push(_)) {
                    seq.sp += 1;
                }
                seq.pending = win.transfer;
            }
            None => {
                let mut w = Word::new();
                w.set("stk_en", 1);
                w.set("op_end", 1);
                w.set("sp", seq.sp as u64);
                w.set(
                    "stk_op",
                    match op {
                        Op::ClipAnd => 0,
                        Op::ClipOr => 1,
                        Op::ClipNot => 2,
                        _ => 3,
                    },
                );
                words.push(w);
                if matches!(op, Op::ClipApply) {
                    seq.pending = Some(Transfer::clip_apply());
                }
                let (pop, push) = stack_effect(op);
                seq.sp = seq.sp - pop + push;
            }
        }
    }
    if let Some(t) = seq.pending.take() {
        for k in 0..nd {
            let mut w = Word::new();
            clock(&mut w, k);
            transfer(&mut w, &t, k);
            w.set("op_end", (k == nd - 1) as u64);
            words.push(w);
        }
    }
    let mut end = Word::new();
    end.set("last", 1);
    words.push(end);
    for (at, c0, dx, dy, k) in roots {
        let w = &mut words[at
            .checked_sub(lat)
            .expect("DEPGEN's fill precedes every stream")];
        w.set("dg_first", (k == 0) as u64);
        w.set("dg_c0", (c0 >> k & 1) as u64);
        w.set("dg_dx", (dx >> k & 1) as u64);
        w.set("dg_dy", (dy >> k & 1) as u64);
    }
    words.iter().map(|w| w.hex() + "\n").collect()
}
