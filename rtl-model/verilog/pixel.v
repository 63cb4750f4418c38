// One pixel processor, seed 001 Figure 2.9: depth registers A F B C, colour registers
// D E G, the select code S_hi S_lo, the pixel's DEPGEN adder, compare, SGENE (derived),
// TRANSD/TRANSC and the clipping stack. Every control input is broadcast by the controller
// to the whole array each clock; only col_bit and row_bit (DEPGEN's lines) differ by pixel.
// Depth and colour registers circulate: bit k of the window sits at bit 0 in clock k.
module pixel #(parameter F = 10, I = 10, O = 11, CB = 8, SD = 8) (
    input wire clk,
    input wire win,
    input wire col_en,
    input wire first,
    input wire is_sign,
    input wire cmp_en,
    input wire [1:0] lhs,
    input wire [1:0] rhs,
    input wire st_en,
    input wire d_en,
    input wire d_bit,
    input wire tr_en,
    input wire [1:0] tr_dst,
    input wire [1:0] tr_src,
    input wire [1:0] tr_cpair,
    input wire tr_compose,
    input wire int_bit,
    input wire dec_latch,
    input wire [1:0] dec_pos,
    input wire [5:0] ext,
    input wire dec_push,
    input wire stk_en,
    input wire [1:0] stk_op,
    /* verilator lint_off UNUSEDSIGNAL */
    input wire [5:0] sp,
    /* verilator lint_on UNUSEDSIGNAL */
    input wire rst,
    input wire col_bit, row_bit,
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
    wire [3:0] cur = {rC[0], rB[0], rF[0], rA[0]};
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
    wire [3:0] nxt = {nC, nB, nF, nA};
    wire N, J, T, M, Nn, Jn, Tn, Mn;
    wire [$clog2(W)+3:0] cmp_regs;
    comparator #(.F(F), .I(I), .O(O)) cmp(.clk(clk), .rst(rst), .en(cmp_en), .first(first),
        .a(nxt[lhs]), .r(nxt[rhs]), .N(N), .J(J), .T(T), .M(M),
        .Nn(Nn), .Jn(Jn), .Tn(Tn), .Mn(Mn), .regs(cmp_regs));

    // SGENE on the flags after this clock; the stage selector picks the pair.
    wire front_S1, front_S2, back_S1, back_S2, close_S1, close_S2, clip_LL, second_S3, second_S4;
    sgene_derived sgene(.L(ext[0]), .S(ext[1]), .H(ext[2]), .Y(ext[3]), .X(ext[4]), .P(ext[5]),
        .N(Nn), .J(Jn), .T(Tn), .M(Mn),
        .front_S1(front_S1), .front_S2(front_S2), .back_S1(back_S1), .back_S2(back_S2),
        .close_S1(close_S1), .close_S2(close_S2), .clip_LL(clip_LL),
        .second_S3(second_S3), .second_S4(second_S4));
    wire [7:0] pairs = {second_S3, second_S4, close_S1, close_S2, back_S1, back_S2,
        front_S1, front_S2};
    wire [1:0] code = pairs[2 * dec_pos +: 2];

    // clipping stack: one bit per level, the stack pointer sp is the controller's; si is
    // sp as wide as an index into the stack (programs never leave 0..SD).
    localparam SW = SD > 1 ? $clog2(SD) : 1;
    wire [SW-1:0] si = sp[SW-1:0];
    wire top = stack[si - 1'b1];
    wire under = stack[si - 2'd2];

    always @(posedge clk) begin
        if (rst) begin
            rA <= {1'b0, {W-1{1'b1}}};
            rF <= {1'b0, {W-1{1'b1}}};
            rB <= {1'b0, {W-1{1'b1}}};
            rC <= {1'b0, {W-1{1'b1}}};
            rD <= {CB{1'b0}};
            rE <= {CB{1'b0}};
            rG <= {CB{1'b0}};
            {s_hi, s_lo} <= 2'b01;
            carry <= 1'b0;
            stack <= {SD{1'b0}};
        end else begin
            if (win) begin
                rA <= {nA, rA[W-1:1]};
                rF <= {nF, rF[W-1:1]};
                rB <= {nB, rB[W-1:1]};
                rC <= {nC, rC[W-1:1]};
            end
            if (win & col_en) begin
                rD <= {nD, rD[CB-1:1]};
                rE <= {nE, rE[CB-1:1]};
                rG <= {nG, rG[CB-1:1]};
            end
            if (st_en) carry <= col_bit & row_bit | cin & (col_bit ^ row_bit);
            if (dec_latch) {s_hi, s_lo} <= code;
            if (dec_push) stack[si] <= clip_LL;
            if (stk_en)
                case (stk_op)
                    2'd0: stack[si - 2'd2] <= under & top;
                    2'd1: stack[si - 2'd2] <= under | top;
                    2'd2: stack[si - 1'b1] <= ~top;
                    default: {s_hi, s_lo} <= {~top, 1'b1};
                endcase
        end
    end
    assign image = rG;
    // Observation: every register and the flags, {stack, carry, comparator {k, sign, ovf,
    // eq, lt}, M, T, J, N, S_lo, S_hi, G, E, D, C, B, F, A} (pixel.rs state_fields).
    assign state = {stack, carry, cmp_regs, M, T, J, N, s_lo, s_hi, rG, rE, rD, rC, rB, rF, rA};
endmodule
