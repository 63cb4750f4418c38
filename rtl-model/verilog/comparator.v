// Bit-serial comparator, seed 001 §2.3.2 and §2.4.2 (Figure 2.9 "compare").
// Words arrive LSB first; `first` is high with bit 0. Four flip-flops: lt (A < R on the
// bits seen; at the sign bit the order reverses), eq, ovf (an overflow bit of A was 1), sign.
module comparator #(parameter F = 10, I = 10, O = 11) (
    input wire clk, first, a, r,
    output wire N, J, T, M
);
    localparam W = F + I + O + 1, KW = $clog2(W);
    reg [KW-1:0] k;
    reg lt, eq, ovf, sign;
    wire [KW-1:0] bit_k = first ? {KW{1'b0}} : k;
    wire lt0 = first ? 1'b0 : lt;
    wire eq0 = first ? 1'b1 : eq;
    wire ovf0 = first ? 1'b0 : ovf;
    wire is_sign = bit_k == W - 1;
    wire is_ovf = bit_k >= F + I && bit_k < W - 1;
    wire diff = a ^ r;
    wire a_smaller = is_sign ? a : r;
    always @(posedge clk) begin
        k <= bit_k + 1'b1;
        lt <= diff ? a_smaller : lt0;
        eq <= eq0 & ~diff;
        ovf <= ovf0 | (is_ovf & a);
        if (is_sign) sign <= a;
    end
    assign N = sign;
    assign J = lt | eq;
    assign T = eq;
    assign M = ovf & ~sign;
endmodule
