// An NX×NY array of pixel processors (seed 001 Figure 2.8): one control word for all,
// and DEPGEN (§2.4): the x tree puts x*dx on column line x, the y tree c0 + y*dy on row
// line y, from the coefficient bits dg_c0, dg_dx, dg_dy (LSB first, dg_first with bit 0),
// LEVELS + 1 clocks after the controller presents them.
module pixel_array #(parameter NX = 16, NY = 16) (
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
    input wire dg_first, dg_c0, dg_dx, dg_dy,
    output wire [NX*NY*8-1:0] image
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
                    .win(win),
                    .col_en(col_en),
                    .first(first),
                    .is_sign(is_sign),
                    .cmp_en(cmp_en),
                    .lhs(lhs),
                    .rhs(rhs),
                    .st_en(st_en),
                    .d_en(d_en),
                    .d_bit(d_bit),
                    .tr_en(tr_en),
                    .tr_dst(tr_dst),
                    .tr_src(tr_src),
                    .tr_cpair(tr_cpair),
                    .tr_compose(tr_compose),
                    .int_bit(int_bit),
                    .dec_latch(dec_latch),
                    .dec_pos(dec_pos),
                    .ext(ext),
                    .dec_push(dec_push),
                    .stk_en(stk_en),
                    .stk_op(stk_op),
                    .sp(sp),
                    .rst(rst),
                    .col_bit(col[x]), .row_bit(row[y]),
                    // The observation port serves the one-pixel checks; the array
                    // reads its pixels through `image`.
                    /* verilator lint_off PINCONNECTEMPTY */
                    .image(image[(y * NX + x) * 8 +: 8]), .state()
                    /* verilator lint_on PINCONNECTEMPTY */);
            end
        end
    endgenerate
endmodule
