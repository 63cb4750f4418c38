// Bit-serial comparator, seed 001 §2.3.2 and §2.4.2 (Figure 2.9 "compare").
// Words arrive LSB first; `first` is high with bit 0. Four flip-flops: lt (A < R on the
// bits seen; at the sign bit the order reverses), eq, ovf (an overflow bit of A was 1), sign.
// `en` low holds every flip-flop (clocks with no comparison); `rst` gives "equal" (J = T = 1).
// Nn Jn Tn Mn are the flags as they will be after this clock: SGENE latches them with the
// sign bit, so its code is ready for TRANSD in the next clock (Figure 2.11).
module comparator #(parameter F = 10, I = 10, O = 11) (
    input wire clk, rst, en, first, a, r,
    output wire N, J, T, M,
    output wire Nn, Jn, Tn, Mn,
    output wire [$clog2(F+I+O+1)+3:0] regs
);
    localparam W = F + I + O + 1, KW = $clog2(W);
    reg [KW-1:0] k;
    reg lt, eq, ovf, sign;
    wire [KW-1:0] bit_k = first ? {KW{1'b0}} : k;
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
            k <= {KW{1'b0}};
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
    // Observation: every flip-flop, {k, sign, ovf, eq, lt}.
    assign regs = {k, sign, ovf, eq, lt};
endmodule
