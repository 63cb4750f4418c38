//! The bit-serial comparator of a pixel (Figure 2.9 "compare", flags of §2.3.2, §2.4.2) as a
//! Verilog module, with the same four flip-flops as [`crate::comparator::Comparator`], and a
//! self-checking testbench whose expected flags are the arithmetic definitions of §2.3.2
//! (N: A < 0, J: A ≤ R, T: A = R, M: A ≥ maxdepth, A ≥ 0), computed on whole words.

use crate::depth_word::WordFormat;

/// `comparator`: one bit of A and of R per clock, LSB first; `first` marks bit 0 of a word.
/// N J T M are valid after the clock of the sign bit. Word fields are parameters (§2.4.1).
pub fn module(fmt: &WordFormat) -> String {
    format!(
        "// Bit-serial comparator, seed 001 §2.3.2 and §2.4.2 (Figure 2.9 \"compare\").
// Words arrive LSB first; `first` is high with bit 0. Four flip-flops: lt (A < R on the
// bits seen; at the sign bit the order reverses), eq, ovf (an overflow bit of A was 1), sign.
// `en` low holds every flip-flop (clocks with no comparison); `rst` gives \"equal\" (J = T = 1).
// Nn Jn Tn Mn are the flags as they will be after this clock: SGENE latches them with the
// sign bit, so its code is ready for TRANSD in the next clock (Figure 2.11).
module comparator #(parameter F = {f}, I = {i}, O = {o}) (
    input wire clk, rst, en, first, a, r,
    output wire N, J, T, M,
    output wire Nn, Jn, Tn, Mn,
    output wire [$clog2(F+I+O+1)+3:0] regs
);
    localparam W = F + I + O + 1, KW = $clog2(W);
    reg [KW-1:0] k;
    reg lt, eq, ovf, sign;
    wire [KW-1:0] bit_k = first ? {{KW{{1'b0}}}} : k;
    wire lt0 = first ? 1'b0 : lt;
    wire eq0 = first ? 1'b1 : eq;
    wire ovf0 = first ? 1'b0 : ovf;
    wire sign0 = first ? 1'b0 : sign;
    wire is_sign = bit_k == W - 1;
    wire is_ovf = bit_k >= F + I && bit_k < W - 1;
    wire diff = a ^ r;
    wire a_smaller = is_sign ? a : r;
    wire lt_n = diff ? a_smaller : lt0;
    wire eq_n = eq0 & ~diff;
    wire ovf_n = ovf0 | (is_ovf & a);
    wire sign_n = is_sign ? a : sign0;
    always @(posedge clk) begin
        if (rst) begin
            k <= {{KW{{1'b0}}}};
            lt <= 1'b0;
            eq <= 1'b1;
            ovf <= 1'b0;
            sign <= 1'b0;
        end else if (en) begin
            k <= bit_k + 1'b1;
            lt <= lt_n;
            eq <= eq_n;
            ovf <= ovf_n;
            sign <= sign_n;
        end
    end
    assign N = sign;
    assign J = lt | eq;
    assign T = eq;
    assign M = ovf & ~sign;
    assign Nn = sign_n;
    assign Jn = lt_n | eq_n;
    assign Tn = eq_n;
    assign Mn = ovf_n & ~sign_n;
    // Observation: every flip-flop, {{k, sign, ovf, eq, lt}}.
    assign regs = {{k, sign, ovf, eq, lt}};
endmodule
",
        f = fmt.frac,
        i = fmt.int,
        o = fmt.ovf
    )
}

/// Boundary words of the format (as unsigned W-bit values): 0, ±1, around maxdepth, the
/// extremes.
fn boundary(fmt: &WordFormat) -> Vec<u64> {
    let m = fmt.maxdepth();
    [
        0,
        1,
        -1,
        m - 1,
        m,
        m + 1,
        -m,
        fmt.max_word(),
        fmt.min_word(),
        1 << fmt.frac,
    ]
    .iter()
    .map(|w| (*w as u64) & fmt.mask())
    .collect()
}

/// `tb_comparator`: every pair of boundary words, then `random` pseudo-random pairs (fixed
/// seed, half of them with R = A), each streamed LSB first; the flags are checked against
/// signed whole-word arithmetic. Prints `COMPARATOR pairs P mismatches B`.
pub fn testbench(fmt: &WordFormat, random: u32) -> String {
    let w = fmt.bits();
    let words = boundary(fmt);
    let mut pairs = String::new();
    for a in &words {
        for r in &words {
            pairs += &format!("        run({w}'h{a:x}, {w}'h{r:x});\n");
        }
    }
    format!(
        "// Checks `comparator` against the definitions of N J T M (§2.3.2); generated, do not edit.
module tb_comparator;
    localparam F = {f}, I = {i}, O = {o}, W = {w};
    reg clk = 0, first = 0, a = 0, r = 0;
    wire N, J, T, M, Nn, Jn, Tn, Mn;
    integer pairs = 0, bad = 0, n, seed = 1;
    reg [W-1:0] x, y;
    comparator #(.F(F), .I(I), .O(O)) dut(.clk(clk), .rst(1'b0), .en(1'b1), .first(first),
        .a(a), .r(r), .N(N), .J(J), .T(T), .M(M), .Nn(Nn), .Jn(Jn), .Tn(Tn), .Mn(Mn));
    task run(input [W-1:0] A, input [W-1:0] R);
        integer b;
        reg [3:0] want;
        begin
            for (b = 0; b < W; b = b + 1) begin
                first = b == 0; a = A[b]; r = R[b];
                #1 clk = 1; #1 clk = 0;
            end
            want = {{A[W-1], $signed(A) <= $signed(R), A == R, ~A[W-1] & |A[W-2:F+I]}};
            pairs = pairs + 1;
            if ({{N, J, T, M}} !== want) begin
                bad = bad + 1;
                $display(\"MISMATCH A=%h R=%h NJTM=%b expected %b\", A, R, {{N, J, T, M}}, want);
            end
        end
    endtask
    initial begin
{pairs}        for (n = 0; n < {random}; n = n + 1) begin
            x = $random(seed); y = (n % 2) ? x : $random(seed);
            run(x, y);
        end
        $display(\"COMPARATOR pairs %0d mismatches %0d\", pairs, bad);
        $finish;
    end
endmodule
",
        f = fmt.frac,
        i = fmt.int,
        o = fmt.ovf,
    )
}
