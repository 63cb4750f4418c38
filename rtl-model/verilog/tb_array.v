// Runs a control stream through pixel_array and prints every register of every pixel
// after each operation; generated, do not edit. Control word fields: see pixel.rs FIELDS.
module tb_array;
    localparam NX = 16, NY = 16, CW = 80, MAXCLK = 1 << 20;
    reg clk = 0, rst = 1;
    reg [CW-1:0] mem [0:MAXCLK-1];
    reg [CW-1:0] c = {CW{1'b0}};
    reg [8*256-1:0] file;
    reg done = 0;
    integer t = 0, ops = 0;
    localparam W = 32, CB = 8, SD = 8, SW = 166;
    wire [NX*NY*CB-1:0] image;
    reg [SW-1:0] s;
    pixel_array #(.NX(NX), .NY(NY)) dut(.clk(clk),
        .win(c[2]),
        .col_en(c[3]),
        .first(c[4]),
        .is_sign(c[5]),
        .cmp_en(c[7]),
        .lhs(c[9:8]),
        .rhs(c[11:10]),
        .st_en(c[12]),
        .d_en(c[13]),
        .d_bit(c[14]),
        .tr_en(c[15]),
        .tr_dst(c[17:16]),
        .tr_src(c[19:18]),
        .tr_cpair(c[21:20]),
        .tr_compose(c[22]),
        .int_bit(c[23]),
        .dec_latch(c[24]),
        .dec_pos(c[26:25]),
        .ext(c[32:27]),
        .dec_push(c[33]),
        .stk_en(c[34]),
        .stk_op(c[36:35]),
        .sp(c[42:37]),
        .rst(rst),
        .col(c[48+NX-1:48]), .row(c[48+NX+NY-1:48+NX]),
        .image(image));
    task show(input integer x, input integer y);
        begin
            $display("P %0d %0d %0d %h %h %h %h %h %h %h %b %b %b %b %b %b %h", ops, x, y,
                s[W-1:0], s[2*W-1:W], s[3*W-1:2*W], s[4*W-1:3*W],
                s[4*W+CB-1:4*W], s[4*W+2*CB-1:4*W+CB], s[4*W+3*CB-1:4*W+2*CB],
                s[4*W+3*CB], s[4*W+3*CB+1], s[4*W+3*CB+2], s[4*W+3*CB+3], s[4*W+3*CB+4],
                s[4*W+3*CB+5], s[SW-1:4*W+3*CB+6]);
        end
    endtask
    task dump;
        begin
            s = dut.gy[0].gx[0].p.state; show(0, 0);
            s = dut.gy[0].gx[1].p.state; show(1, 0);
            s = dut.gy[0].gx[2].p.state; show(2, 0);
            s = dut.gy[0].gx[3].p.state; show(3, 0);
            s = dut.gy[0].gx[4].p.state; show(4, 0);
            s = dut.gy[0].gx[5].p.state; show(5, 0);
            s = dut.gy[0].gx[6].p.state; show(6, 0);
            s = dut.gy[0].gx[7].p.state; show(7, 0);
            s = dut.gy[0].gx[8].p.state; show(8, 0);
            s = dut.gy[0].gx[9].p.state; show(9, 0);
            s = dut.gy[0].gx[10].p.state; show(10, 0);
            s = dut.gy[0].gx[11].p.state; show(11, 0);
            s = dut.gy[0].gx[12].p.state; show(12, 0);
            s = dut.gy[0].gx[13].p.state; show(13, 0);
            s = dut.gy[0].gx[14].p.state; show(14, 0);
            s = dut.gy[0].gx[15].p.state; show(15, 0);
            s = dut.gy[1].gx[0].p.state; show(0, 1);
            s = dut.gy[1].gx[1].p.state; show(1, 1);
            s = dut.gy[1].gx[2].p.state; show(2, 1);
            s = dut.gy[1].gx[3].p.state; show(3, 1);
            s = dut.gy[1].gx[4].p.state; show(4, 1);
            s = dut.gy[1].gx[5].p.state; show(5, 1);
            s = dut.gy[1].gx[6].p.state; show(6, 1);
            s = dut.gy[1].gx[7].p.state; show(7, 1);
            s = dut.gy[1].gx[8].p.state; show(8, 1);
            s = dut.gy[1].gx[9].p.state; show(9, 1);
            s = dut.gy[1].gx[10].p.state; show(10, 1);
            s = dut.gy[1].gx[11].p.state; show(11, 1);
            s = dut.gy[1].gx[12].p.state; show(12, 1);
            s = dut.gy[1].gx[13].p.state; show(13, 1);
            s = dut.gy[1].gx[14].p.state; show(14, 1);
            s = dut.gy[1].gx[15].p.state; show(15, 1);
            s = dut.gy[2].gx[0].p.state; show(0, 2);
            s = dut.gy[2].gx[1].p.state; show(1, 2);
            s = dut.gy[2].gx[2].p.state; show(2, 2);
            s = dut.gy[2].gx[3].p.state; show(3, 2);
            s = dut.gy[2].gx[4].p.state; show(4, 2);
            s = dut.gy[2].gx[5].p.state; show(5, 2);
            s = dut.gy[2].gx[6].p.state; show(6, 2);
            s = dut.gy[2].gx[7].p.state; show(7, 2);
            s = dut.gy[2].gx[8].p.state; show(8, 2);
            s = dut.gy[2].gx[9].p.state; show(9, 2);
            s = dut.gy[2].gx[10].p.state; show(10, 2);
            s = dut.gy[2].gx[11].p.state; show(11, 2);
            s = dut.gy[2].gx[12].p.state; show(12, 2);
            s = dut.gy[2].gx[13].p.state; show(13, 2);
            s = dut.gy[2].gx[14].p.state; show(14, 2);
            s = dut.gy[2].gx[15].p.state; show(15, 2);
            s = dut.gy[3].gx[0].p.state; show(0, 3);
            s = dut.gy[3].gx[1].p.state; show(1, 3);
            s = dut.gy[3].gx[2].p.state; show(2, 3);
            s = dut.gy[3].gx[3].p.state; show(3, 3);
            s = dut.gy[3].gx[4].p.state; show(4, 3);
            s = dut.gy[3].gx[5].p.state; show(5, 3);
            s = dut.gy[3].gx[6].p.state; show(6, 3);
            s = dut.gy[3].gx[7].p.state; show(7, 3);
            s = dut.gy[3].gx[8].p.state; show(8, 3);
            s = dut.gy[3].gx[9].p.state; show(9, 3);
            s = dut.gy[3].gx[10].p.state; show(10, 3);
            s = dut.gy[3].gx[11].p.state; show(11, 3);
            s = dut.gy[3].gx[12].p.state; show(12, 3);
            s = dut.gy[3].gx[13].p.state; show(13, 3);
            s = dut.gy[3].gx[14].p.state; show(14, 3);
            s = dut.gy[3].gx[15].p.state; show(15, 3);
            s = dut.gy[4].gx[0].p.state; show(0, 4);
            s = dut.gy[4].gx[1].p.state; show(1, 4);
            s = dut.gy[4].gx[2].p.state; show(2, 4);
            s = dut.gy[4].gx[3].p.state; show(3, 4);
            s = dut.gy[4].gx[4].p.state; show(4, 4);
            s = dut.gy[4].gx[5].p.state; show(5, 4);
            s = dut.gy[4].gx[6].p.state; show(6, 4);
            s = dut.gy[4].gx[7].p.state; show(7, 4);
            s = dut.gy[4].gx[8].p.state; show(8, 4);
            s = dut.gy[4].gx[9].p.state; show(9, 4);
            s = dut.gy[4].gx[10].p.state; show(10, 4);
            s = dut.gy[4].gx[11].p.state; show(11, 4);
            s = dut.gy[4].gx[12].p.state; show(12, 4);
            s = dut.gy[4].gx[13].p.state; show(13, 4);
            s = dut.gy[4].gx[14].p.state; show(14, 4);
            s = dut.gy[4].gx[15].p.state; show(15, 4);
            s = dut.gy[5].gx[0].p.state; show(0, 5);
            s = dut.gy[5].gx[1].p.state; show(1, 5);
            s = dut.gy[5].gx[2].p.state; show(2, 5);
            s = dut.gy[5].gx[3].p.state; show(3, 5);
            s = dut.gy[5].gx[4].p.state; show(4, 5);
            s = dut.gy[5].gx[5].p.state; show(5, 5);
            s = dut.gy[5].gx[6].p.state; show(6, 5);
            s = dut.gy[5].gx[7].p.state; show(7, 5);
            s = dut.gy[5].gx[8].p.state; show(8, 5);
            s = dut.gy[5].gx[9].p.state; show(9, 5);
            s = dut.gy[5].gx[10].p.state; show(10, 5);
            s = dut.gy[5].gx[11].p.state; show(11, 5);
            s = dut.gy[5].gx[12].p.state; show(12, 5);
            s = dut.gy[5].gx[13].p.state; show(13, 5);
            s = dut.gy[5].gx[14].p.state; show(14, 5);
            s = dut.gy[5].gx[15].p.state; show(15, 5);
            s = dut.gy[6].gx[0].p.state; show(0, 6);
            s = dut.gy[6].gx[1].p.state; show(1, 6);
            s = dut.gy[6].gx[2].p.state; show(2, 6);
            s = dut.gy[6].gx[3].p.state; show(3, 6);
            s = dut.gy[6].gx[4].p.state; show(4, 6);
            s = dut.gy[6].gx[5].p.state; show(5, 6);
            s = dut.gy[6].gx[6].p.state; show(6, 6);
            s = dut.gy[6].gx[7].p.state; show(7, 6);
            s = dut.gy[6].gx[8].p.state; show(8, 6);
            s = dut.gy[6].gx[9].p.state; show(9, 6);
            s = dut.gy[6].gx[10].p.state; show(10, 6);
            s = dut.gy[6].gx[11].p.state; show(11, 6);
            s = dut.gy[6].gx[12].p.state; show(12, 6);
            s = dut.gy[6].gx[13].p.state; show(13, 6);
            s = dut.gy[6].gx[14].p.state; show(14, 6);
            s = dut.gy[6].gx[15].p.state; show(15, 6);
            s = dut.gy[7].gx[0].p.state; show(0, 7);
            s = dut.gy[7].gx[1].p.state; show(1, 7);
            s = dut.gy[7].gx[2].p.state; show(2, 7);
            s = dut.gy[7].gx[3].p.state; show(3, 7);
            s = dut.gy[7].gx[4].p.state; show(4, 7);
            s = dut.gy[7].gx[5].p.state; show(5, 7);
            s = dut.gy[7].gx[6].p.state; show(6, 7);
            s = dut.gy[7].gx[7].p.state; show(7, 7);
            s = dut.gy[7].gx[8].p.state; show(8, 7);
            s = dut.gy[7].gx[9].p.state; show(9, 7);
            s = dut.gy[7].gx[10].p.state; show(10, 7);
            s = dut.gy[7].gx[11].p.state; show(11, 7);
            s = dut.gy[7].gx[12].p.state; show(12, 7);
            s = dut.gy[7].gx[13].p.state; show(13, 7);
            s = dut.gy[7].gx[14].p.state; show(14, 7);
            s = dut.gy[7].gx[15].p.state; show(15, 7);
            s = dut.gy[8].gx[0].p.state; show(0, 8);
            s = dut.gy[8].gx[1].p.state; show(1, 8);
            s = dut.gy[8].gx[2].p.state; show(2, 8);
            s = dut.gy[8].gx[3].p.state; show(3, 8);
            s = dut.gy[8].gx[4].p.state; show(4, 8);
            s = dut.gy[8].gx[5].p.state; show(5, 8);
            s = dut.gy[8].gx[6].p.state; show(6, 8);
            s = dut.gy[8].gx[7].p.state; show(7, 8);
            s = dut.gy[8].gx[8].p.state; show(8, 8);
            s = dut.gy[8].gx[9].p.state; show(9, 8);
            s = dut.gy[8].gx[10].p.state; show(10, 8);
            s = dut.gy[8].gx[11].p.state; show(11, 8);
            s = dut.gy[8].gx[12].p.state; show(12, 8);
            s = dut.gy[8].gx[13].p.state; show(13, 8);
            s = dut.gy[8].gx[14].p.state; show(14, 8);
            s = dut.gy[8].gx[15].p.state; show(15, 8);
            s = dut.gy[9].gx[0].p.state; show(0, 9);
            s = dut.gy[9].gx[1].p.state; show(1, 9);
            s = dut.gy[9].gx[2].p.state; show(2, 9);
            s = dut.gy[9].gx[3].p.state; show(3, 9);
            s = dut.gy[9].gx[4].p.state; show(4, 9);
            s = dut.gy[9].gx[5].p.state; show(5, 9);
            s = dut.gy[9].gx[6].p.state; show(6, 9);
            s = dut.gy[9].gx[7].p.state; show(7, 9);
            s = dut.gy[9].gx[8].p.state; show(8, 9);
            s = dut.gy[9].gx[9].p.state; show(9, 9);
            s = dut.gy[9].gx[10].p.state; show(10, 9);
            s = dut.gy[9].gx[11].p.state; show(11, 9);
            s = dut.gy[9].gx[12].p.state; show(12, 9);
            s = dut.gy[9].gx[13].p.state; show(13, 9);
            s = dut.gy[9].gx[14].p.state; show(14, 9);
            s = dut.gy[9].gx[15].p.state; show(15, 9);
            s = dut.gy[10].gx[0].p.state; show(0, 10);
            s = dut.gy[10].gx[1].p.state; show(1, 10);
            s = dut.gy[10].gx[2].p.state; show(2, 10);
            s = dut.gy[10].gx[3].p.state; show(3, 10);
            s = dut.gy[10].gx[4].p.state; show(4, 10);
            s = dut.gy[10].gx[5].p.state; show(5, 10);
            s = dut.gy[10].gx[6].p.state; show(6, 10);
            s = dut.gy[10].gx[7].p.state; show(7, 10);
            s = dut.gy[10].gx[8].p.state; show(8, 10);
            s = dut.gy[10].gx[9].p.state; show(9, 10);
            s = dut.gy[10].gx[10].p.state; show(10, 10);
            s = dut.gy[10].gx[11].p.state; show(11, 10);
            s = dut.gy[10].gx[12].p.state; show(12, 10);
            s = dut.gy[10].gx[13].p.state; show(13, 10);
            s = dut.gy[10].gx[14].p.state; show(14, 10);
            s = dut.gy[10].gx[15].p.state; show(15, 10);
            s = dut.gy[11].gx[0].p.state; show(0, 11);
            s = dut.gy[11].gx[1].p.state; show(1, 11);
            s = dut.gy[11].gx[2].p.state; show(2, 11);
            s = dut.gy[11].gx[3].p.state; show(3, 11);
            s = dut.gy[11].gx[4].p.state; show(4, 11);
            s = dut.gy[11].gx[5].p.state; show(5, 11);
            s = dut.gy[11].gx[6].p.state; show(6, 11);
            s = dut.gy[11].gx[7].p.state; show(7, 11);
            s = dut.gy[11].gx[8].p.state; show(8, 11);
            s = dut.gy[11].gx[9].p.state; show(9, 11);
            s = dut.gy[11].gx[10].p.state; show(10, 11);
            s = dut.gy[11].gx[11].p.state; show(11, 11);
            s = dut.gy[11].gx[12].p.state; show(12, 11);
            s = dut.gy[11].gx[13].p.state; show(13, 11);
            s = dut.gy[11].gx[14].p.state; show(14, 11);
            s = dut.gy[11].gx[15].p.state; show(15, 11);
            s = dut.gy[12].gx[0].p.state; show(0, 12);
            s = dut.gy[12].gx[1].p.state; show(1, 12);
            s = dut.gy[12].gx[2].p.state; show(2, 12);
            s = dut.gy[12].gx[3].p.state; show(3, 12);
            s = dut.gy[12].gx[4].p.state; show(4, 12);
            s = dut.gy[12].gx[5].p.state; show(5, 12);
            s = dut.gy[12].gx[6].p.state; show(6, 12);
            s = dut.gy[12].gx[7].p.state; show(7, 12);
            s = dut.gy[12].gx[8].p.state; show(8, 12);
            s = dut.gy[12].gx[9].p.state; show(9, 12);
            s = dut.gy[12].gx[10].p.state; show(10, 12);
            s = dut.gy[12].gx[11].p.state; show(11, 12);
            s = dut.gy[12].gx[12].p.state; show(12, 12);
            s = dut.gy[12].gx[13].p.state; show(13, 12);
            s = dut.gy[12].gx[14].p.state; show(14, 12);
            s = dut.gy[12].gx[15].p.state; show(15, 12);
            s = dut.gy[13].gx[0].p.state; show(0, 13);
            s = dut.gy[13].gx[1].p.state; show(1, 13);
            s = dut.gy[13].gx[2].p.state; show(2, 13);
            s = dut.gy[13].gx[3].p.state; show(3, 13);
            s = dut.gy[13].gx[4].p.state; show(4, 13);
            s = dut.gy[13].gx[5].p.state; show(5, 13);
            s = dut.gy[13].gx[6].p.state; show(6, 13);
            s = dut.gy[13].gx[7].p.state; show(7, 13);
            s = dut.gy[13].gx[8].p.state; show(8, 13);
            s = dut.gy[13].gx[9].p.state; show(9, 13);
            s = dut.gy[13].gx[10].p.state; show(10, 13);
            s = dut.gy[13].gx[11].p.state; show(11, 13);
            s = dut.gy[13].gx[12].p.state; show(12, 13);
            s = dut.gy[13].gx[13].p.state; show(13, 13);
            s = dut.gy[13].gx[14].p.state; show(14, 13);
            s = dut.gy[13].gx[15].p.state; show(15, 13);
            s = dut.gy[14].gx[0].p.state; show(0, 14);
            s = dut.gy[14].gx[1].p.state; show(1, 14);
            s = dut.gy[14].gx[2].p.state; show(2, 14);
            s = dut.gy[14].gx[3].p.state; show(3, 14);
            s = dut.gy[14].gx[4].p.state; show(4, 14);
            s = dut.gy[14].gx[5].p.state; show(5, 14);
            s = dut.gy[14].gx[6].p.state; show(6, 14);
            s = dut.gy[14].gx[7].p.state; show(7, 14);
            s = dut.gy[14].gx[8].p.state; show(8, 14);
            s = dut.gy[14].gx[9].p.state; show(9, 14);
            s = dut.gy[14].gx[10].p.state; show(10, 14);
            s = dut.gy[14].gx[11].p.state; show(11, 14);
            s = dut.gy[14].gx[12].p.state; show(12, 14);
            s = dut.gy[14].gx[13].p.state; show(13, 14);
            s = dut.gy[14].gx[14].p.state; show(14, 14);
            s = dut.gy[14].gx[15].p.state; show(15, 14);
            s = dut.gy[15].gx[0].p.state; show(0, 15);
            s = dut.gy[15].gx[1].p.state; show(1, 15);
            s = dut.gy[15].gx[2].p.state; show(2, 15);
            s = dut.gy[15].gx[3].p.state; show(3, 15);
            s = dut.gy[15].gx[4].p.state; show(4, 15);
            s = dut.gy[15].gx[5].p.state; show(5, 15);
            s = dut.gy[15].gx[6].p.state; show(6, 15);
            s = dut.gy[15].gx[7].p.state; show(7, 15);
            s = dut.gy[15].gx[8].p.state; show(8, 15);
            s = dut.gy[15].gx[9].p.state; show(9, 15);
            s = dut.gy[15].gx[10].p.state; show(10, 15);
            s = dut.gy[15].gx[11].p.state; show(11, 15);
            s = dut.gy[15].gx[12].p.state; show(12, 15);
            s = dut.gy[15].gx[13].p.state; show(13, 15);
            s = dut.gy[15].gx[14].p.state; show(14, 15);
            s = dut.gy[15].gx[15].p.state; show(15, 15);
        end
    endtask
    initial begin
        if (!$value$plusargs("ctl=%s", file)) file = "control.hex";
        $readmemh(file, mem);
        #1 clk = 1; #1 clk = 0; rst = 0;
        while (!done) begin
            c = mem[t];
            #1 clk = 1; #1 clk = 0;
            if (c[1]) begin dump; ops = ops + 1; end
            done = c[0];
            t = t + 1;
        end
        $display("CLOCKS %0d OPS %0d", t, ops);
        $finish;
    end
endmodule
