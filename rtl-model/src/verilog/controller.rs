//! The controller in Verilog (seed 001 §2.4: the sequencer that drives the stage selector,
//! TRANSD/TRANSC, MEM D and DEPGEN's roots): a program memory of one record per [`Op`]
//! ([`program_hex`]), read by a sequencer that expands each record into the control word of
//! every clock, the word [`super::pixel::control_stream`] writes in Rust.
//!
//! * [`module`]: `controller`. The record at `pc` is decoded as [`Window::of`] decodes the
//!   operation (stage position, operands, the transfer it leaves pending); a bit counter `k`
//!   gives each clock of a window its role (bit k of the word, colour bits, sign, overflow);
//!   the stack pointer and the pending transfer are its registers, as in [`Sequencer`]. The
//!   sequencer runs [`ArrayConfig::depgen_latency`] clocks ahead of the array: DEPGEN's roots
//!   take the plane bits it produces at once, the rest of the word goes through a delay line
//!   of that many stages, so each plane enters the trees while the window before it runs.
//! * [`machine_module`]: `machine`, the controller and `pixel_array` (§2.5: one panel).
//! * [`testbench`]: `tb_machine`, which compares the controller's word with the control
//!   stream every clock and every pixel's state with the `cycle` model's after every clock.
//!
//! [`Sequencer`]: crate::array::Sequencer
//! [`Window::of`]: crate::program::Window::of

use super::pixel::{array_inputs, check_tasks, field, state_width, CW};
use crate::program::Op;
use crate::state::ArrayConfig;

/// Record opcodes (bits 3:0 of a record): END closes the program.
const OPCODES: [(&str, u64); 9] = [
    ("END", 0),
    ("Plane", 1),
    ("Close", 2),
    ("ClipPlane", 3),
    ("ClipAnd", 4),
    ("ClipOr", 5),
    ("ClipNot", 6),
    ("ClipApply", 7),
    ("Compose", 8),
];

/// Address bits of the program memory of the checked-in machine: 256 records (255 operations
/// and END), eight 256×16 block RAMs of an iCE40 at the thesis word.
pub const ADDR_BITS: u32 = 8;

/// Bits of one program record: opcode 4, externals 6, colour and interior CB each, c0 dx dy
/// N_D each.
pub fn record_bits(cfg: &ArrayConfig) -> usize {
    10 + 2 * cfg.colour_bits as usize + 3 * cfg.fmt.bits() as usize
}

/// The address bits a program of `ops` operations needs (its END record included), at least
/// [`ADDR_BITS`].
pub fn addr_bits(ops: usize) -> u32 {
    (usize::BITS - ops.leading_zeros()).max(ADDR_BITS)
}

/// The opcode and the externals {P X Y H S L} (bit 0 L) of an operation: the same externals
/// `control_stream` broadcasts in its windows, 0 where the operation has none.
fn head(op: &Op) -> (u64, [bool; 6]) {
    let code = |n: &str| OPCODES.iter().find(|o| o.0 == n).unwrap().1;
    let f = false;
    match *op {
        Op::Plane { l, s, h, y, .. } => (code("Plane"), [l, s, h, y, f, f]),
        Op::Close { l } => (code("Close"), [l, f, f, f, f, f]),
        Op::ClipPlane { h, y, x, .. } => (code("ClipPlane"), [f, f, h, y, x, f]),
        Op::ClipAnd => (code("ClipAnd"), [f; 6]),
        Op::ClipOr => (code("ClipOr"), [f; 6]),
        Op::ClipNot => (code("ClipNot"), [f; 6]),
        Op::ClipApply => (code("ClipApply"), [f; 6]),
        Op::Compose { p } => (code("Compose"), [f, f, f, f, f, p]),
    }
}

/// Why an operation has no program record.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RecordError {
    /// Its colour or interior code does not fit the colour registers.
    ColourTooWide {
        /// The operation's colour code.
        colour: u64,
        /// The operation's interior colour code.
        interior: u64,
        /// The colour registers' bits.
        bits: u32,
    },
}

impl std::fmt::Display for RecordError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RecordError::ColourTooWide {
                colour,
                interior,
                bits,
            } => write!(
                f,
                "a colour code ({colour} or {interior}) does not fit the {bits} colour bits"
            ),
        }
    }
}

impl std::error::Error for RecordError {}

/// One record, LSB first: opcode, externals, colour, interior, c0, dx, dy.
fn record(cfg: &ArrayConfig, op: &Op) -> Result<Vec<bool>, RecordError> {
    let (nd, cb) = (cfg.fmt.bits() as usize, cfg.colour_bits as usize);
    let (code, ext) = head(op);
    let (colour, interior, c) = match *op {
        Op::Plane {
            coeffs,
            colour,
            interior,
            ..
        } => (colour as u64, interior as u64, Some(coeffs)),
        Op::ClipPlane { coeffs, .. } => (0, 0, Some(coeffs)),
        _ => (0, 0, None),
    };
    if colour >> cb != 0 || interior >> cb != 0 {
        let bits = cfg.colour_bits;
        return Err(RecordError::ColourTooWide {
            colour,
            interior,
            bits,
        });
    }
    let mut bits = vec![];
    let mut put = |v: u64, w: usize| bits.extend((0..w).map(|i| i < 64 && v >> i & 1 == 1));
    put(code, 4);
    put(ext.iter().rev().fold(0, |a, b| a << 1 | *b as u64), 6);
    put(colour, cb);
    put(interior, cb);
    let c = c.map_or([0; 3], |c| [c.c0, c.dx, c.dy]);
    for v in c {
        put(v as u64, nd);
    }
    Ok(bits)
}

/// `program.hex`: the program memory image `controller` reads with `$readmemh`, one record a
/// line in hex (most significant digit first, [`record_bits`] bits), one per operation and a
/// closing END record (all zero). Refuses a colour code wider than the colour registers.
pub fn program_hex(cfg: &ArrayConfig, ops: &[Op]) -> Result<String, RecordError> {
    let mut text = String::new();
    let end = vec![false; record_bits(cfg)];
    for bits in ops.iter().map(|op| record(cfg, op)).chain([Ok(end)]) {
        text += &super::hex(&bits?);
        text.push('\n');
    }
    Ok(text)
}

/// `controller`: the sequencer (§2.4). Parameters: the word (F I O), colour bits CB, the
/// trees' latency LAT ([`ArrayConfig::depgen_latency`]), address bits AW and the memory
/// image PROG. Outputs the control word `cw` ([`super::pixel::FIELDS`]), `go` (from the
/// clock after the delay line has filled: `cw` is the program's word of that clock) and
/// `done` (the word carrying `last` has been sent).
pub fn module(cfg: &ArrayConfig) -> String {
    let f = &cfg.fmt;
    format!(
        "// The controller, seed 001 §2.4: a sequencer that reads one record per operation from
// the program memory (program.hex, docs/verilog.md) and broadcasts the control word of every
// clock: the stage position, operands, TRANSD/TRANSC's transfer, MEM D's colour bits, the
// stack operations and DEPGEN's root bits. Generated by rtl-model/src/verilog/controller.rs;
// do not edit. The sequence is that of pixel.rs control_stream: a window of W clocks per
// streamed or compared operation (bit k in clock k), DEPGEN's fill of LAT clocks before the
// first plane, one clock per stack operation, the flush window of a transfer still pending
// after END, and one idle word with `last`. The sequencer runs LAT clocks ahead of the
// array: DEPGEN's roots take the plane bits at once, the rest of the word is delayed LAT
// clocks, so a plane enters the trees while the window before it runs.
module controller #(parameter F = {ff}, I = {ii}, O = {oo}, CB = {cb}, LAT = {lat}, AW = {aw},
        PROG = \"program.hex\") (
    input wire clk, rst,
    // The memory's write port (a panel loads its program through it; tie we to 0 to run
    // the image PROG).
    input wire we,
    input wire [AW-1:0] wa,
    input wire [10+2*CB+3*(F+I+O+1)-1:0] wd,
    output wire [{cwm}:0] cw,
    output wire go,
    output reg done
);
    localparam W = F + I + O + 1;
    localparam RW = 10 + 2 * CB + 3 * W;
    localparam KW = $clog2(W > LAT ? W : LAT);
    // The last bit of a window and of DEPGEN's fill, as wide as k.
    /* verilator lint_off WIDTH */
    localparam [KW-1:0] KL = W - 1, KF = LAT - 1;
    /* verilator lint_on WIDTH */
    // The program memory: read synchronously at the next pc (a block RAM).
    reg [RW-1:0] rom [0:(1 << AW) - 1];
    initial $readmemh(PROG, rom);
    reg [RW-1:0] rec;
    reg [AW-1:0] pc;
    reg [KW-1:0] k;
    reg [5:0] sp;
    reg streamed, fin;
    // The transfer the latched code carries out in the next window (Transfer).
    reg pv, p_comp;
    reg [1:0] p_dst, p_src, p_cpair;
    reg [CB-1:0] p_int;

    // The record: opcode, externals {{P X Y H S L}}, colour, interior, c0, dx, dy.
    wire [3:0] opc = rec[3:0];
    wire [5:0] ext = rec[9:4];
    wire [CB-1:0] colour = rec[10 +: CB];
    wire [CB-1:0] interior = rec[10 + CB +: CB];
    wire [W-1:0] c0 = rec[10 + 2 * CB +: W];
    wire [W-1:0] dx = rec[10 + 2 * CB + W +: W];
    wire [W-1:0] dy = rec[10 + 2 * CB + 2 * W +: W];

{decode}
{word}
{seq}
endmodule
",
        ff = f.frac,
        ii = f.int,
        oo = f.ovf,
        cb = cfg.colour_bits,
        lat = cfg.depgen_latency(),
        aw = ADDR_BITS,
        cwm = CW - 1,
        decode = DECODE,
        word = word_assigns(),
        seq = SEQUENCE,
    )
}

/// Window::of in gates: which operation, its stage position and operands, and the transfer
/// it leaves pending (Transfer::clip_apply for Close and ClipApply).
const DECODE: &str = "    // Window::of: the operation's window and the transfer it leaves pending.
    wire endr = opc == 4'd0, plane = opc == 4'd1, close = opc == 4'd2, clip = opc == 4'd3;
    wire apply = opc == 4'd7, compose = opc == 4'd8;
    wire stk = opc >= 4'd4 && opc <= 4'd7;
    wire front = plane & (ext[2] | ext[3]);
    wire back = plane & ~front;
    wire stream = plane | clip;
    wire window = stream | close | compose;
    wire fill = stream & ~streamed;
    wire flush = endr & pv;
    wire last_w = endr & ~pv & ~fin;
    wire [1:0] lhs = close ? 2'd2 : compose ? 2'd1 : 2'd0;
    wire [1:0] rhs = back ? 2'd2 : compose ? 2'd3 : 2'd1;
    wire [1:0] pos = compose ? 2'd3 : close ? 2'd2 : back ? 2'd1 : 2'd0;
    wire t_v = plane | close | compose | apply;
    wire [1:0] t_dst = compose ? 2'd3 : back ? 2'd2 : 2'd1;
    wire [1:0] t_src = compose ? 2'd1 : close | apply ? 2'd2 : 2'd0;
    wire [1:0] t_cp = compose ? 2'd2 : back ? 2'd0 : 2'd1;
    wire [CB-1:0] t_int = front ? interior : {CB{1'b0}};
";

/// The bookkeeping of the sequencer: bit counter, fill, pc, stack pointer, pending transfer,
/// and the delay line that puts the word LAT clocks behind DEPGEN's root bits.
const SEQUENCE: &str =
    "    // pc moves on at the end of an operation; the memory reads the next record.
    wire [AW-1:0] pc_next = rst ? {AW{1'b0}} : adv ? pc + 1'b1 : pc;
    always @(posedge clk) rec <= rom[pc_next];
    always @(posedge clk) if (we) rom[wa] <= wd;
    always @(posedge clk) begin
        if (rst) begin
            pc <= {AW{1'b0}};
            k <= {KW{1'b0}};
            sp <= 6'd0;
            {streamed, fin, pv, p_comp} <= 4'b0;
            {p_dst, p_src, p_cpair} <= 6'b0;
            p_int <= {CB{1'b0}};
        end else begin
            pc <= pc_next;
            if (fill) begin
                k <= k == KF ? {KW{1'b0}} : k + 1'b1;
                if (k == KF) streamed <= 1'b1;
            end else if (window | flush) begin
                k <= lastk ? {KW{1'b0}} : k + 1'b1;
                if (lastk) begin
                    {pv, p_comp, p_dst, p_src, p_cpair, p_int} <=
                        {t_v, compose, t_dst, t_src, t_cp, t_int};
                    if (clip) sp <= sp + 1'b1;
                end
            end else if (stk) begin
                // AND, OR and apply pop one more than they push; NOT pops and pushes one.
                if (opc != 4'd6) sp <= sp - 1'b1;
                if (apply) {pv, p_comp, p_dst, p_src, p_cpair, p_int} <=
                    {t_v, 1'b0, t_dst, t_src, t_cp, {CB{1'b0}}};
            end else if (last_w) fin <= 1'b1;
        end
    end
    // The delay line: the word but DEPGEN's bits, and a mark that the sequencer ran.
    localparam PW = 44;
    reg [PW*LAT-1:0] pipe;
    /* verilator lint_off WIDTH */
    always @(posedge clk) pipe <= rst ? {PW*LAT{1'b0}} : {pipe, 1'b1, word[42:0]};
    /* verilator lint_on WIDTH */
    wire [PW-1:0] out = pipe[PW*(LAT-1) +: PW];
    assign go = out[43];
    assign cw = {1'b0, word[46:43], out[42:0]};
    always @(posedge clk) done <= rst ? 1'b0 : done | go & out[0];";

/// The per-clock word of the sequencer's step, field by field (`pixel::FIELDS`).
fn word_assigns() -> String {
    let fields: [(&str, &str); 30] = [
        ("last", "last_w"),
        ("op_end", "lastk & (run | flush) | stk"),
        ("win", "wk"),
        ("col_en", "wk & k < CB"),
        ("first", "wk & k == 0"),
        ("is_sign", "wk & lastk"),
        ("is_ovf", "wk & k >= F + I & ~lastk"),
        ("cmp_en", "run"),
        ("lhs", "run ? lhs : 2'd0"),
        ("rhs", "run ? rhs : 2'd0"),
        ("st_en", "run & stream"),
        ("d_en", "run & front & k < CB"),
        ("d_bit", "run & front & k < CB & col_k[0]"),
        ("tr_en", "tr"),
        ("tr_dst", "tr ? p_dst : 2'd0"),
        ("tr_src", "tr ? p_src : 2'd0"),
        ("tr_cpair", "tr ? p_cpair : 2'd0"),
        ("tr_compose", "tr & p_comp"),
        ("int_bit", "tr & int_k[0]"),
        ("dec_latch", "decide & ~clip"),
        ("dec_pos", "decide & ~clip ? pos : 2'd0"),
        ("ext", "run ? ext : 6'd0"),
        ("dec_push", "decide & clip"),
        ("stk_en", "stk"),
        ("stk_op", "stk ? opc[1:0] : 2'd0"),
        ("sp", "decide | stk ? sp : 6'd0"),
        ("dg_first", "run & stream & k == 0"),
        ("dg_c0", "run & stream & c0_k[0]"),
        ("dg_dx", "run & stream & dx_k[0]"),
        ("dg_dy", "run & stream & dy_k[0]"),
    ];
    let mut v = String::from(
        "    // The step's word (pixel.rs FIELDS): run is a window clock of an operation, wk any
    // window clock (the flush's too), bit k of the word.
    wire lastk = k == KL;
    wire run = window & ~fill;
    wire wk = run | flush;
    wire tr = wk & pv;
    wire decide = run & lastk;
    wire adv = decide | stk;
    // Bit k of the colours and coefficients: bit 0 of each shift (the rest is not read).
    /* verilator lint_off UNUSEDSIGNAL */
    wire [CB-1:0] col_k = colour >> k, int_k = p_int >> k;
    wire [W-1:0] c0_k = c0 >> k, dx_k = dx >> k, dy_k = dy >> k;
    /* verilator lint_on UNUSEDSIGNAL */
    wire [46:0] word;
",
    );
    for (name, expr) in fields {
        let (lo, w) = field(name);
        let at = if w == 1 {
            format!("{lo}")
        } else {
            format!("{}:{lo}", lo + w - 1)
        };
        v += &format!("    assign word[{at}] = {expr};  // {name}\n");
    }
    v
}

/// `machine`: the controller and the NX×NY `pixel_array` on its word (§2.5, one panel). The
/// array is held in reset until the controller's delay line has filled (`go`).
pub fn machine_module(cfg: &ArrayConfig, aw: u32) -> String {
    let conns: String = array_inputs()
        .iter()
        .map(|n| {
            let (lo, w) = field(n);
            let s = if w == 1 {
                format!("cw[{lo}]")
            } else {
                format!("cw[{}:{lo}]", lo + w - 1)
            };
            format!("        .{n}({s}),\n")
        })
        .collect();
    format!(
        "// The machine, seed 001 §2.4-2.5: the controller and an NX×NY array of pixel processors
// with DEPGEN's trees on its control word. Generated by rtl-model/src/verilog/controller.rs.
module machine #(parameter NX = {nx}, NY = {ny}, AW = {aw}, PROG = \"program.hex\") (
    input wire clk, rst,
    // The program memory's write port (controller.v); 0 to run the image PROG.
    input wire we,
    input wire [AW-1:0] wa,
    input wire [{rwm}:0] wd,
    output wire [{cwm}:0] cw,
    output wire go, done,
    output wire [NX*NY*{cb}-1:0] image
);
    localparam LEVELS = $clog2(NX) > $clog2(NY) ? $clog2(NX) : $clog2(NY);
    controller #(.LAT(LEVELS + 1), .AW(AW), .PROG(PROG)) ctl(.clk(clk), .rst(rst), .we(we),
        .wa(wa), .wd(wd), .cw(cw), .go(go), .done(done));
    pixel_array #(.NX(NX), .NY(NY)) arr(.clk(clk), .rst(rst | ~go),
{conns}        .image(image));
endmodule
",
        nx = cfg.width,
        ny = cfg.height,
        cb = cfg.colour_bits,
        cwm = CW - 1,
        rwm = record_bits(cfg) - 1,
    )
}

/// `tb_machine`: resets the machine, waits for `go`, then each clock compares the controller's
/// word with the control stream `+ctl=FILE` (default `control.hex`) and prints `WORD t
/// expected E got G` for a difference, and after each clock checks every pixel's state
/// against `+exp=FILE` (default `expected.hex`; none there: `CHECK off`) as `tb_array` does.
/// Ends with `PREROLL p DONE d`, `WORDS n MISMATCHES w`, `CLOCKS n OPS m MISMATCHES b` and
/// the image (`IMAGE` rows, top first, pixel (0, 0) in the low byte). `aw`: the machine's
/// address bits (its write port is tied to 0).
pub fn testbench(cfg: &ArrayConfig, aw: u32) -> String {
    format!(
        "// Runs the machine (controller + pixel_array) on program.hex; compares the controller's
// word with the control stream and every pixel's state with the expected one after every
// clock. Generated by rtl-model/src/verilog/controller.rs; do not edit.
module tb_machine;
    localparam NX = {nx}, NY = {ny}, CW = {CW}, MAXCLK = 1 << 20;
    localparam SW = {sw};
    reg clk = 0, rst = 1;
    reg [CW-1:0] mem [0:MAXCLK-1];
    reg [CW-1:0] c = {{CW{{1'b0}}}};
    reg [8*256-1:0] file;
    reg done = 0;
    integer t = 0, ops = 0, wbad = 0, pre = 0, r;
    wire [CW-1:0] cw;
    wire go, fin;
    wire [NX*NY*{cb}-1:0] image;
    machine #(.NX(NX), .NY(NY)) dut(.clk(clk), .rst(rst), .we(1'b0), .wa({{{aw}{{1'b0}}}}),
        .wd({{{rw}{{1'b0}}}}), .cw(cw), .go(go), .done(fin), .image(image));
{tasks}    initial begin
{open}        while (!go && pre < 64) begin
            #1 clk = 1; #1 clk = 0;
            pre = pre + 1;
        end
        while (!done && bad < 20 && wbad < 20 && t < MAXCLK) begin
            c = cw;
            if (c !== mem[t]) begin
                wbad = wbad + 1;
                $display(\"WORD %0d expected %h got %h\", t, mem[t], c);
            end
            #1 clk = 1; #1 clk = 0;
            if (fd != 0) check_all;
            if (c[1]) ops = ops + 1;
            done = c[0];
            t = t + 1;
        end
        #1 clk = 1; #1 clk = 0;
        $display(\"PREROLL %0d DONE %0d\", pre, fin);
        $display(\"WORDS %0d MISMATCHES %0d\", t, wbad);
        $display(\"CLOCKS %0d OPS %0d MISMATCHES %0d\", t, ops, bad);
        // The image, G of every pixel (pixel (0, 0) in the low byte), a row a line, top first.
        for (r = NY - 1; r >= 0; r = r - 1)
            $display(\"IMAGE %h\", image[r * {row} +: {row}]);
        $finish;
    end
endmodule
",
        nx = cfg.width,
        ny = cfg.height,
        cb = cfg.colour_bits,
        sw = state_width(cfg),
        tasks = check_tasks(cfg, "dut.arr"),
        open = super::pixel::OPEN_STREAMS,
        row = cfg.width * cfg.colour_bits as usize,
        rw = record_bits(cfg),
    )
}

/// The machine's sources, leaves first: `pixel_array.f`'s files, the controller and
/// `machine.v` (`machine.f`).
pub fn filelist() -> String {
    super::filelist() + "controller.v\nmachine.v\n"
}

/// `tb_panel`: the panel's loader exercised. The program memory starts from `blank.hex`
/// (all END records), so the panel's first run after the power-on reset draws nothing; then,
/// under `ld_hold`, the first `+n=N` records of `program.hex` are shifted in a bit a clock
/// (most significant first) and written with `ld_we`; when the hold ends the machine runs
/// them. Prints `BEFORE fold done` after the first run and `AFTER fold done CLOCKS t` after
/// the second (`fold`: the XOR of every pixel's G). Inputs change on the falling edge.
pub fn panel_testbench(cfg: &ArrayConfig) -> String {
    format!(
        "// The panel's serial loader: a blank first run, then program.hex shifted in under
// ld_hold, written with ld_we, and run. Generated by rtl-model/src/verilog/controller.rs;
// do not edit.
module tb_panel #(parameter NX = 2, NY = 2) ();
    localparam RW = {rw}, AW = {aw}, MAXCLK = 1 << 22;
    reg clk = 0, ld_hold = 0, ld_bit = 0, ld_we = 0;
    wire [{cbm}:0] fold;
    wire done;
    reg [RW-1:0] recs [0:(1 << AW) - 1];
    integer n = 0, r, b, t;
    panel #(.NX(NX), .NY(NY), .AW(AW), .PROG(\"blank.hex\")) dut(.clk(clk), .ld_hold(ld_hold),
        .ld_bit(ld_bit), .ld_we(ld_we), .fold(fold), .done(done));
    always #5 clk = ~clk;
    task run_to_done;
        begin
            t = 0;
            while (done !== 1'b1 && t < MAXCLK) begin
                @(negedge clk);
                t = t + 1;
            end
            @(negedge clk);
        end
    endtask
    initial begin
        if (!$value$plusargs(\"n=%d\", n)) n = 0;
        if (n > 0) $readmemh(\"program.hex\", recs, 0, n - 1);
        run_to_done;
        $display(\"BEFORE %h %0d\", fold, done);
        @(negedge clk) ld_hold = 1;
        for (r = 0; r < n; r = r + 1) begin
            for (b = RW - 1; b >= 0; b = b - 1) begin
                @(negedge clk) ld_bit = recs[r][b];
            end
            @(negedge clk) ld_we = 1;
            @(negedge clk) ld_we = 0;
        end
        @(negedge clk) ld_hold = 0;
        run_to_done;
        $display(\"AFTER %h %0d CLOCKS %0d\", fold, done, t);
        $finish;
    end
endmodule
",
        rw = record_bits(cfg),
        aw = ADDR_BITS,
        cbm = cfg.colour_bits - 1,
    )
}

/// `panel`: the machine as an FPGA design (§2.5: one panel of the screen), for
/// `fpga/flow.sh`. A power-on reset (iCE40 flip-flops start at 0) holds the machine in reset
/// for 15 clocks. The program memory is loaded serially: while `ld_hold` holds the machine
/// in reset, `ld_bit` shifts a record in (most significant bit first) and `ld_we` writes it
/// at the next address, from 0; when `ld_hold` falls the machine runs the program from its
/// first record. So synthesis cannot fold a program's constants into the logic; the memory
/// starts from the image `program.hex`, which runs after configuration. The image leaves on CB
/// pins as the XOR of every pixel's G register (`fold`), so no pixel can be optimised away,
/// with `done`.
pub fn panel_module(cfg: &ArrayConfig) -> String {
    format!(
        "// A panel of the machine for an FPGA (seed 001 §2.5): the controller and an NX×NY array
// on one clock, a power-on reset, a serial loader for the program memory, and the image
// folded onto CB pins (the XOR of every pixel's G) so that synthesis keeps every pixel.
// Generated by rtl-model/src/verilog/controller.rs; do not edit.
module panel #(parameter NX = 2, NY = 2, AW = {aw}, PROG = \"program.hex\") (
    input wire clk,
    input wire ld_hold, ld_bit, ld_we,
    output reg [{cbm}:0] fold,
    output reg done
);
    localparam RW = {rw};
    reg [3:0] por = 4'd0;
    wire rst = ~&por;
    always @(posedge clk) if (rst) por <= por + 1'b1;
    // The loader: while ld_hold holds the machine, a record shifts in a bit a clock and
    // ld_we writes it and moves on; the addresses start again at 0 when the hold ends.
    reg [RW-1:0] ld;
    reg [AW-1:0] la = {{AW{{1'b0}}}};
    wire load = ld_hold & ld_we;
    always @(posedge clk) begin
        ld <= {{ld[RW-2:0], ld_bit}};
        if (!ld_hold) la <= {{AW{{1'b0}}}};
        else if (load) la <= la + 1'b1;
    end
    /* verilator lint_off UNUSEDSIGNAL */
    wire [{cwm}:0] cw;
    wire go;
    /* verilator lint_on UNUSEDSIGNAL */
    wire fin;
    wire [NX*NY*{cb}-1:0] image;
    machine #(.NX(NX), .NY(NY), .AW(AW), .PROG(PROG)) m(.clk(clk), .rst(rst | ld_hold),
        .we(load), .wa(la), .wd(ld), .cw(cw), .go(go), .done(fin), .image(image));
    integer i;
    reg [{cbm}:0] x;
    always @(*) begin
        x = {{{cb}{{1'b0}}}};
        for (i = 0; i < NX * NY; i = i + 1) x = x ^ image[i * {cb} +: {cb}];
    end
    always @(posedge clk) begin
        fold <= x;
        done <= fin;
    end
endmodule
",
        cb = cfg.colour_bits,
        cbm = cfg.colour_bits - 1,
        cwm = CW - 1,
        aw = ADDR_BITS,
        rw = record_bits(cfg),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::program;

    /// A record per operation and END; each line as wide as a record; END is all zero; a
    /// plane's c0 sits at bit 10 + 2·CB.
    #[test]
    fn program_hex_has_a_record_per_operation() {
        let cfg = ArrayConfig::new(4, 4);
        let ops = program();
        let text = program_hex(&cfg, &ops).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), ops.len() + 1);
        let digits = record_bits(&cfg).div_ceil(4);
        assert!(lines.iter().all(|l| l.len() == digits));
        assert!(lines.last().unwrap().chars().all(|c| c == '0'));
        let (i, c) = ops
            .iter()
            .enumerate()
            .find_map(|(i, o)| match o {
                Op::Plane { coeffs, .. } => Some((i, coeffs)),
                _ => None,
            })
            .unwrap();
        let v = u128::from_str_radix(lines[i], 16).unwrap();
        let nd = cfg.fmt.bits();
        assert_eq!(v & 15, 1, "opcode Plane");
        assert_eq!(
            (v >> 26) as u64 & cfg.fmt.mask(),
            c.c0 as u64 & cfg.fmt.mask()
        );
        assert_eq!(
            (v >> (26 + nd)) as u64 & cfg.fmt.mask(),
            c.dx as u64 & cfg.fmt.mask()
        );
    }

    /// A colour code wider than the colour registers is refused, not truncated.
    #[test]
    fn program_hex_refuses_a_colour_wider_than_the_registers() {
        let mut cfg = ArrayConfig::new(4, 4);
        cfg.colour_bits = 2;
        let ops = program();
        let e = program_hex(&cfg, &ops).unwrap_err();
        assert!(
            matches!(e, RecordError::ColourTooWide { bits: 2, .. }),
            "{e}"
        );
        assert!(e.to_string().contains("2 colour bits"), "{e}");
    }

    /// 256 records fill the checked-in memory; one more operation needs a bit more.
    #[test]
    fn addr_bits_grow_with_the_program() {
        assert_eq!(addr_bits(255), 8);
        assert_eq!(addr_bits(256), 9);
        assert_eq!(addr_bits(3), 8);
    }
}
