// Runs a control stream through pixel_array and compares every register of every pixel
// with the expected state after every clock; generated, do not edit. Control word fields:
// pixel.rs FIELDS; state fields: pixel.rs state_fields.
module tb_array;
    localparam NX = 16, NY = 16, CW = 48, MAXCLK = 1 << 20;
    localparam SW = 176;
    reg clk = 0, rst = 1;
    reg [CW-1:0] mem [0:MAXCLK-1];
    reg [CW-1:0] c = {CW{1'b0}};
    reg [8*256-1:0] file;
    reg done = 0;
    integer t = 0, ops = 0;
    wire [NX*NY*8-1:0] image;
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
        .dg_first(c[43]),
        .dg_c0(c[44]),
        .dg_dx(c[45]),
        .dg_dy(c[46]),
        .image(image));
    reg [8*256-1:0] efile;
    reg [SW-1:0] s, e;
    integer fd, n, bad = 0;
    task field(input [8*8-1:0] name, input integer lo, input integer w, input integer x,
            input integer y);
        reg [SW-1:0] m;
        begin
            m = ({SW{1'b1}} >> (SW - w)) << lo;
            if ((s & m) !== (e & m)) begin
                bad = bad + 1;
                if (bad <= 20)
                    $display("MISMATCH %0d %0d %0d %0s %0h %0h", t + 1, x, y, name,
                        (e & m) >> lo, (s & m) >> lo);
            end
        end
    endtask
    task check(input integer x, input integer y);
        begin
            n = $fscanf(fd, "%h\n", e);
            if (n != 1) begin
                $display("EXPECTED ends before clock %0d", t + 1);
                $finish;
            end
            if (s !== e) begin
                field("A", 0, 32, x, y);
                field("F", 32, 32, x, y);
                field("B", 64, 32, x, y);
                field("C", 96, 32, x, y);
                field("D", 128, 8, x, y);
                field("E", 136, 8, x, y);
                field("G", 144, 8, x, y);
                field("S_hi", 152, 1, x, y);
                field("S_lo", 153, 1, x, y);
                field("N", 154, 1, x, y);
                field("J", 155, 1, x, y);
                field("T", 156, 1, x, y);
                field("M", 157, 1, x, y);
                field("lt", 158, 1, x, y);
                field("eq", 159, 1, x, y);
                field("ovf", 160, 1, x, y);
                field("sign", 161, 1, x, y);
                field("k", 162, 5, x, y);
                field("carry", 167, 1, x, y);
                field("stack", 168, 8, x, y);
            end
        end
    endtask
    task check_all;
        begin
            s = dut.gy[0].gx[0].p.state; check(0, 0);
            s = dut.gy[0].gx[1].p.state; check(1, 0);
            s = dut.gy[0].gx[2].p.state; check(2, 0);
            s = dut.gy[0].gx[3].p.state; check(3, 0);
            s = dut.gy[0].gx[4].p.state; check(4, 0);
            s = dut.gy[0].gx[5].p.state; check(5, 0);
            s = dut.gy[0].gx[6].p.state; check(6, 0);
            s = dut.gy[0].gx[7].p.state; check(7, 0);
            s = dut.gy[0].gx[8].p.state; check(8, 0);
            s = dut.gy[0].gx[9].p.state; check(9, 0);
            s = dut.gy[0].gx[10].p.state; check(10, 0);
            s = dut.gy[0].gx[11].p.state; check(11, 0);
            s = dut.gy[0].gx[12].p.state; check(12, 0);
            s = dut.gy[0].gx[13].p.state; check(13, 0);
            s = dut.gy[0].gx[14].p.state; check(14, 0);
            s = dut.gy[0].gx[15].p.state; check(15, 0);
            s = dut.gy[1].gx[0].p.state; check(0, 1);
            s = dut.gy[1].gx[1].p.state; check(1, 1);
            s = dut.gy[1].gx[2].p.state; check(2, 1);
            s = dut.gy[1].gx[3].p.state; check(3, 1);
            s = dut.gy[1].gx[4].p.state; check(4, 1);
            s = dut.gy[1].gx[5].p.state; check(5, 1);
            s = dut.gy[1].gx[6].p.state; check(6, 1);
            s = dut.gy[1].gx[7].p.state; check(7, 1);
            s = dut.gy[1].gx[8].p.state; check(8, 1);
            s = dut.gy[1].gx[9].p.state; check(9, 1);
            s = dut.gy[1].gx[10].p.state; check(10, 1);
            s = dut.gy[1].gx[11].p.state; check(11, 1);
            s = dut.gy[1].gx[12].p.state; check(12, 1);
            s = dut.gy[1].gx[13].p.state; check(13, 1);
            s = dut.gy[1].gx[14].p.state; check(14, 1);
            s = dut.gy[1].gx[15].p.state; check(15, 1);
            s = dut.gy[2].gx[0].p.state; check(0, 2);
            s = dut.gy[2].gx[1].p.state; check(1, 2);
            s = dut.gy[2].gx[2].p.state; check(2, 2);
            s = dut.gy[2].gx[3].p.state; check(3, 2);
            s = dut.gy[2].gx[4].p.state; check(4, 2);
            s = dut.gy[2].gx[5].p.state; check(5, 2);
            s = dut.gy[2].gx[6].p.state; check(6, 2);
            s = dut.gy[2].gx[7].p.state; check(7, 2);
            s = dut.gy[2].gx[8].p.state; check(8, 2);
            s = dut.gy[2].gx[9].p.state; check(9, 2);
            s = dut.gy[2].gx[10].p.state; check(10, 2);
            s = dut.gy[2].gx[11].p.state; check(11, 2);
            s = dut.gy[2].gx[12].p.state; check(12, 2);
            s = dut.gy[2].gx[13].p.state; check(13, 2);
            s = dut.gy[2].gx[14].p.state; check(14, 2);
            s = dut.gy[2].gx[15].p.state; check(15, 2);
            s = dut.gy[3].gx[0].p.state; check(0, 3);
            s = dut.gy[3].gx[1].p.state; check(1, 3);
            s = dut.gy[3].gx[2].p.state; check(2, 3);
            s = dut.gy[3].gx[3].p.state; check(3, 3);
            s = dut.gy[3].gx[4].p.state; check(4, 3);
            s = dut.gy[3].gx[5].p.state; check(5, 3);
            s = dut.gy[3].gx[6].p.state; check(6, 3);
            s = dut.gy[3].gx[7].p.state; check(7, 3);
            s = dut.gy[3].gx[8].p.state; check(8, 3);
            s = dut.gy[3].gx[9].p.state; check(9, 3);
            s = dut.gy[3].gx[10].p.state; check(10, 3);
            s = dut.gy[3].gx[11].p.state; check(11, 3);
            s = dut.gy[3].gx[12].p.state; check(12, 3);
            s = dut.gy[3].gx[13].p.state; check(13, 3);
            s = dut.gy[3].gx[14].p.state; check(14, 3);
            s = dut.gy[3].gx[15].p.state; check(15, 3);
            s = dut.gy[4].gx[0].p.state; check(0, 4);
            s = dut.gy[4].gx[1].p.state; check(1, 4);
            s = dut.gy[4].gx[2].p.state; check(2, 4);
            s = dut.gy[4].gx[3].p.state; check(3, 4);
            s = dut.gy[4].gx[4].p.state; check(4, 4);
            s = dut.gy[4].gx[5].p.state; check(5, 4);
            s = dut.gy[4].gx[6].p.state; check(6, 4);
            s = dut.gy[4].gx[7].p.state; check(7, 4);
            s = dut.gy[4].gx[8].p.state; check(8, 4);
            s = dut.gy[4].gx[9].p.state; check(9, 4);
            s = dut.gy[4].gx[10].p.state; check(10, 4);
            s = dut.gy[4].gx[11].p.state; check(11, 4);
            s = dut.gy[4].gx[12].p.state; check(12, 4);
            s = dut.gy[4].gx[13].p.state; check(13, 4);
            s = dut.gy[4].gx[14].p.state; check(14, 4);
            s = dut.gy[4].gx[15].p.state; check(15, 4);
            s = dut.gy[5].gx[0].p.state; check(0, 5);
            s = dut.gy[5].gx[1].p.state; check(1, 5);
            s = dut.gy[5].gx[2].p.state; check(2, 5);
            s = dut.gy[5].gx[3].p.state; check(3, 5);
            s = dut.gy[5].gx[4].p.state; check(4, 5);
            s = dut.gy[5].gx[5].p.state; check(5, 5);
            s = dut.gy[5].gx[6].p.state; check(6, 5);
            s = dut.gy[5].gx[7].p.state; check(7, 5);
            s = dut.gy[5].gx[8].p.state; check(8, 5);
            s = dut.gy[5].gx[9].p.state; check(9, 5);
            s = dut.gy[5].gx[10].p.state; check(10, 5);
            s = dut.gy[5].gx[11].p.state; check(11, 5);
            s = dut.gy[5].gx[12].p.state; check(12, 5);
            s = dut.gy[5].gx[13].p.state; check(13, 5);
            s = dut.gy[5].gx[14].p.state; check(14, 5);
            s = dut.gy[5].gx[15].p.state; check(15, 5);
            s = dut.gy[6].gx[0].p.state; check(0, 6);
            s = dut.gy[6].gx[1].p.state; check(1, 6);
            s = dut.gy[6].gx[2].p.state; check(2, 6);
            s = dut.gy[6].gx[3].p.state; check(3, 6);
            s = dut.gy[6].gx[4].p.state; check(4, 6);
            s = dut.gy[6].gx[5].p.state; check(5, 6);
            s = dut.gy[6].gx[6].p.state; check(6, 6);
            s = dut.gy[6].gx[7].p.state; check(7, 6);
            s = dut.gy[6].gx[8].p.state; check(8, 6);
            s = dut.gy[6].gx[9].p.state; check(9, 6);
            s = dut.gy[6].gx[10].p.state; check(10, 6);
            s = dut.gy[6].gx[11].p.state; check(11, 6);
            s = dut.gy[6].gx[12].p.state; check(12, 6);
            s = dut.gy[6].gx[13].p.state; check(13, 6);
            s = dut.gy[6].gx[14].p.state; check(14, 6);
            s = dut.gy[6].gx[15].p.state; check(15, 6);
            s = dut.gy[7].gx[0].p.state; check(0, 7);
            s = dut.gy[7].gx[1].p.state; check(1, 7);
            s = dut.gy[7].gx[2].p.state; check(2, 7);
            s = dut.gy[7].gx[3].p.state; check(3, 7);
            s = dut.gy[7].gx[4].p.state; check(4, 7);
            s = dut.gy[7].gx[5].p.state; check(5, 7);
            s = dut.gy[7].gx[6].p.state; check(6, 7);
            s = dut.gy[7].gx[7].p.state; check(7, 7);
            s = dut.gy[7].gx[8].p.state; check(8, 7);
            s = dut.gy[7].gx[9].p.state; check(9, 7);
            s = dut.gy[7].gx[10].p.state; check(10, 7);
            s = dut.gy[7].gx[11].p.state; check(11, 7);
            s = dut.gy[7].gx[12].p.state; check(12, 7);
            s = dut.gy[7].gx[13].p.state; check(13, 7);
            s = dut.gy[7].gx[14].p.state; check(14, 7);
            s = dut.gy[7].gx[15].p.state; check(15, 7);
            s = dut.gy[8].gx[0].p.state; check(0, 8);
            s = dut.gy[8].gx[1].p.state; check(1, 8);
            s = dut.gy[8].gx[2].p.state; check(2, 8);
            s = dut.gy[8].gx[3].p.state; check(3, 8);
            s = dut.gy[8].gx[4].p.state; check(4, 8);
            s = dut.gy[8].gx[5].p.state; check(5, 8);
            s = dut.gy[8].gx[6].p.state; check(6, 8);
            s = dut.gy[8].gx[7].p.state; check(7, 8);
            s = dut.gy[8].gx[8].p.state; check(8, 8);
            s = dut.gy[8].gx[9].p.state; check(9, 8);
            s = dut.gy[8].gx[10].p.state; check(10, 8);
            s = dut.gy[8].gx[11].p.state; check(11, 8);
            s = dut.gy[8].gx[12].p.state; check(12, 8);
            s = dut.gy[8].gx[13].p.state; check(13, 8);
            s = dut.gy[8].gx[14].p.state; check(14, 8);
            s = dut.gy[8].gx[15].p.state; check(15, 8);
            s = dut.gy[9].gx[0].p.state; check(0, 9);
            s = dut.gy[9].gx[1].p.state; check(1, 9);
            s = dut.gy[9].gx[2].p.state; check(2, 9);
            s = dut.gy[9].gx[3].p.state; check(3, 9);
            s = dut.gy[9].gx[4].p.state; check(4, 9);
            s = dut.gy[9].gx[5].p.state; check(5, 9);
            s = dut.gy[9].gx[6].p.state; check(6, 9);
            s = dut.gy[9].gx[7].p.state; check(7, 9);
            s = dut.gy[9].gx[8].p.state; check(8, 9);
            s = dut.gy[9].gx[9].p.state; check(9, 9);
            s = dut.gy[9].gx[10].p.state; check(10, 9);
            s = dut.gy[9].gx[11].p.state; check(11, 9);
            s = dut.gy[9].gx[12].p.state; check(12, 9);
            s = dut.gy[9].gx[13].p.state; check(13, 9);
            s = dut.gy[9].gx[14].p.state; check(14, 9);
            s = dut.gy[9].gx[15].p.state; check(15, 9);
            s = dut.gy[10].gx[0].p.state; check(0, 10);
            s = dut.gy[10].gx[1].p.state; check(1, 10);
            s = dut.gy[10].gx[2].p.state; check(2, 10);
            s = dut.gy[10].gx[3].p.state; check(3, 10);
            s = dut.gy[10].gx[4].p.state; check(4, 10);
            s = dut.gy[10].gx[5].p.state; check(5, 10);
            s = dut.gy[10].gx[6].p.state; check(6, 10);
            s = dut.gy[10].gx[7].p.state; check(7, 10);
            s = dut.gy[10].gx[8].p.state; check(8, 10);
            s = dut.gy[10].gx[9].p.state; check(9, 10);
            s = dut.gy[10].gx[10].p.state; check(10, 10);
            s = dut.gy[10].gx[11].p.state; check(11, 10);
            s = dut.gy[10].gx[12].p.state; check(12, 10);
            s = dut.gy[10].gx[13].p.state; check(13, 10);
            s = dut.gy[10].gx[14].p.state; check(14, 10);
            s = dut.gy[10].gx[15].p.state; check(15, 10);
            s = dut.gy[11].gx[0].p.state; check(0, 11);
            s = dut.gy[11].gx[1].p.state; check(1, 11);
            s = dut.gy[11].gx[2].p.state; check(2, 11);
            s = dut.gy[11].gx[3].p.state; check(3, 11);
            s = dut.gy[11].gx[4].p.state; check(4, 11);
            s = dut.gy[11].gx[5].p.state; check(5, 11);
            s = dut.gy[11].gx[6].p.state; check(6, 11);
            s = dut.gy[11].gx[7].p.state; check(7, 11);
            s = dut.gy[11].gx[8].p.state; check(8, 11);
            s = dut.gy[11].gx[9].p.state; check(9, 11);
            s = dut.gy[11].gx[10].p.state; check(10, 11);
            s = dut.gy[11].gx[11].p.state; check(11, 11);
            s = dut.gy[11].gx[12].p.state; check(12, 11);
            s = dut.gy[11].gx[13].p.state; check(13, 11);
            s = dut.gy[11].gx[14].p.state; check(14, 11);
            s = dut.gy[11].gx[15].p.state; check(15, 11);
            s = dut.gy[12].gx[0].p.state; check(0, 12);
            s = dut.gy[12].gx[1].p.state; check(1, 12);
            s = dut.gy[12].gx[2].p.state; check(2, 12);
            s = dut.gy[12].gx[3].p.state; check(3, 12);
            s = dut.gy[12].gx[4].p.state; check(4, 12);
            s = dut.gy[12].gx[5].p.state; check(5, 12);
            s = dut.gy[12].gx[6].p.state; check(6, 12);
            s = dut.gy[12].gx[7].p.state; check(7, 12);
            s = dut.gy[12].gx[8].p.state; check(8, 12);
            s = dut.gy[12].gx[9].p.state; check(9, 12);
            s = dut.gy[12].gx[10].p.state; check(10, 12);
            s = dut.gy[12].gx[11].p.state; check(11, 12);
            s = dut.gy[12].gx[12].p.state; check(12, 12);
            s = dut.gy[12].gx[13].p.state; check(13, 12);
            s = dut.gy[12].gx[14].p.state; check(14, 12);
            s = dut.gy[12].gx[15].p.state; check(15, 12);
            s = dut.gy[13].gx[0].p.state; check(0, 13);
            s = dut.gy[13].gx[1].p.state; check(1, 13);
            s = dut.gy[13].gx[2].p.state; check(2, 13);
            s = dut.gy[13].gx[3].p.state; check(3, 13);
            s = dut.gy[13].gx[4].p.state; check(4, 13);
            s = dut.gy[13].gx[5].p.state; check(5, 13);
            s = dut.gy[13].gx[6].p.state; check(6, 13);
            s = dut.gy[13].gx[7].p.state; check(7, 13);
            s = dut.gy[13].gx[8].p.state; check(8, 13);
            s = dut.gy[13].gx[9].p.state; check(9, 13);
            s = dut.gy[13].gx[10].p.state; check(10, 13);
            s = dut.gy[13].gx[11].p.state; check(11, 13);
            s = dut.gy[13].gx[12].p.state; check(12, 13);
            s = dut.gy[13].gx[13].p.state; check(13, 13);
            s = dut.gy[13].gx[14].p.state; check(14, 13);
            s = dut.gy[13].gx[15].p.state; check(15, 13);
            s = dut.gy[14].gx[0].p.state; check(0, 14);
            s = dut.gy[14].gx[1].p.state; check(1, 14);
            s = dut.gy[14].gx[2].p.state; check(2, 14);
            s = dut.gy[14].gx[3].p.state; check(3, 14);
            s = dut.gy[14].gx[4].p.state; check(4, 14);
            s = dut.gy[14].gx[5].p.state; check(5, 14);
            s = dut.gy[14].gx[6].p.state; check(6, 14);
            s = dut.gy[14].gx[7].p.state; check(7, 14);
            s = dut.gy[14].gx[8].p.state; check(8, 14);
            s = dut.gy[14].gx[9].p.state; check(9, 14);
            s = dut.gy[14].gx[10].p.state; check(10, 14);
            s = dut.gy[14].gx[11].p.state; check(11, 14);
            s = dut.gy[14].gx[12].p.state; check(12, 14);
            s = dut.gy[14].gx[13].p.state; check(13, 14);
            s = dut.gy[14].gx[14].p.state; check(14, 14);
            s = dut.gy[14].gx[15].p.state; check(15, 14);
            s = dut.gy[15].gx[0].p.state; check(0, 15);
            s = dut.gy[15].gx[1].p.state; check(1, 15);
            s = dut.gy[15].gx[2].p.state; check(2, 15);
            s = dut.gy[15].gx[3].p.state; check(3, 15);
            s = dut.gy[15].gx[4].p.state; check(4, 15);
            s = dut.gy[15].gx[5].p.state; check(5, 15);
            s = dut.gy[15].gx[6].p.state; check(6, 15);
            s = dut.gy[15].gx[7].p.state; check(7, 15);
            s = dut.gy[15].gx[8].p.state; check(8, 15);
            s = dut.gy[15].gx[9].p.state; check(9, 15);
            s = dut.gy[15].gx[10].p.state; check(10, 15);
            s = dut.gy[15].gx[11].p.state; check(11, 15);
            s = dut.gy[15].gx[12].p.state; check(12, 15);
            s = dut.gy[15].gx[13].p.state; check(13, 15);
            s = dut.gy[15].gx[14].p.state; check(14, 15);
            s = dut.gy[15].gx[15].p.state; check(15, 15);
        end
    endtask
    initial begin
        if (!$value$plusargs("ctl=%s", file)) file = "control.hex";
        if (!$value$plusargs("exp=%s", efile)) efile = "expected.hex";
        $readmemh(file, mem);
        fd = $fopen(efile, "r");
        if (fd == 0) $display("CHECK off");
        #1 clk = 1; #1 clk = 0; rst = 0;
        while (!done) begin
            c = mem[t];
            #1 clk = 1; #1 clk = 0;
            if (fd != 0) check_all;
            if (c[1]) ops = ops + 1;
            done = c[0];
            t = t + 1;
        end
        $display("CLOCKS %0d OPS %0d MISMATCHES %0d", t, ops, bad);
        $finish;
    end
endmodule
