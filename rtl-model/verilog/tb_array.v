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
    reg [SW-1:0] st [0:NX*NY-1];
    integer fd, n, p, bad = 0;
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
            st[0] = dut.gy[0].gx[0].p.state;
            st[1] = dut.gy[0].gx[1].p.state;
            st[2] = dut.gy[0].gx[2].p.state;
            st[3] = dut.gy[0].gx[3].p.state;
            st[4] = dut.gy[0].gx[4].p.state;
            st[5] = dut.gy[0].gx[5].p.state;
            st[6] = dut.gy[0].gx[6].p.state;
            st[7] = dut.gy[0].gx[7].p.state;
            st[8] = dut.gy[0].gx[8].p.state;
            st[9] = dut.gy[0].gx[9].p.state;
            st[10] = dut.gy[0].gx[10].p.state;
            st[11] = dut.gy[0].gx[11].p.state;
            st[12] = dut.gy[0].gx[12].p.state;
            st[13] = dut.gy[0].gx[13].p.state;
            st[14] = dut.gy[0].gx[14].p.state;
            st[15] = dut.gy[0].gx[15].p.state;
            st[16] = dut.gy[1].gx[0].p.state;
            st[17] = dut.gy[1].gx[1].p.state;
            st[18] = dut.gy[1].gx[2].p.state;
            st[19] = dut.gy[1].gx[3].p.state;
            st[20] = dut.gy[1].gx[4].p.state;
            st[21] = dut.gy[1].gx[5].p.state;
            st[22] = dut.gy[1].gx[6].p.state;
            st[23] = dut.gy[1].gx[7].p.state;
            st[24] = dut.gy[1].gx[8].p.state;
            st[25] = dut.gy[1].gx[9].p.state;
            st[26] = dut.gy[1].gx[10].p.state;
            st[27] = dut.gy[1].gx[11].p.state;
            st[28] = dut.gy[1].gx[12].p.state;
            st[29] = dut.gy[1].gx[13].p.state;
            st[30] = dut.gy[1].gx[14].p.state;
            st[31] = dut.gy[1].gx[15].p.state;
            st[32] = dut.gy[2].gx[0].p.state;
            st[33] = dut.gy[2].gx[1].p.state;
            st[34] = dut.gy[2].gx[2].p.state;
            st[35] = dut.gy[2].gx[3].p.state;
            st[36] = dut.gy[2].gx[4].p.state;
            st[37] = dut.gy[2].gx[5].p.state;
            st[38] = dut.gy[2].gx[6].p.state;
            st[39] = dut.gy[2].gx[7].p.state;
            st[40] = dut.gy[2].gx[8].p.state;
            st[41] = dut.gy[2].gx[9].p.state;
            st[42] = dut.gy[2].gx[10].p.state;
            st[43] = dut.gy[2].gx[11].p.state;
            st[44] = dut.gy[2].gx[12].p.state;
            st[45] = dut.gy[2].gx[13].p.state;
            st[46] = dut.gy[2].gx[14].p.state;
            st[47] = dut.gy[2].gx[15].p.state;
            st[48] = dut.gy[3].gx[0].p.state;
            st[49] = dut.gy[3].gx[1].p.state;
            st[50] = dut.gy[3].gx[2].p.state;
            st[51] = dut.gy[3].gx[3].p.state;
            st[52] = dut.gy[3].gx[4].p.state;
            st[53] = dut.gy[3].gx[5].p.state;
            st[54] = dut.gy[3].gx[6].p.state;
            st[55] = dut.gy[3].gx[7].p.state;
            st[56] = dut.gy[3].gx[8].p.state;
            st[57] = dut.gy[3].gx[9].p.state;
            st[58] = dut.gy[3].gx[10].p.state;
            st[59] = dut.gy[3].gx[11].p.state;
            st[60] = dut.gy[3].gx[12].p.state;
            st[61] = dut.gy[3].gx[13].p.state;
            st[62] = dut.gy[3].gx[14].p.state;
            st[63] = dut.gy[3].gx[15].p.state;
            st[64] = dut.gy[4].gx[0].p.state;
            st[65] = dut.gy[4].gx[1].p.state;
            st[66] = dut.gy[4].gx[2].p.state;
            st[67] = dut.gy[4].gx[3].p.state;
            st[68] = dut.gy[4].gx[4].p.state;
            st[69] = dut.gy[4].gx[5].p.state;
            st[70] = dut.gy[4].gx[6].p.state;
            st[71] = dut.gy[4].gx[7].p.state;
            st[72] = dut.gy[4].gx[8].p.state;
            st[73] = dut.gy[4].gx[9].p.state;
            st[74] = dut.gy[4].gx[10].p.state;
            st[75] = dut.gy[4].gx[11].p.state;
            st[76] = dut.gy[4].gx[12].p.state;
            st[77] = dut.gy[4].gx[13].p.state;
            st[78] = dut.gy[4].gx[14].p.state;
            st[79] = dut.gy[4].gx[15].p.state;
            st[80] = dut.gy[5].gx[0].p.state;
            st[81] = dut.gy[5].gx[1].p.state;
            st[82] = dut.gy[5].gx[2].p.state;
            st[83] = dut.gy[5].gx[3].p.state;
            st[84] = dut.gy[5].gx[4].p.state;
            st[85] = dut.gy[5].gx[5].p.state;
            st[86] = dut.gy[5].gx[6].p.state;
            st[87] = dut.gy[5].gx[7].p.state;
            st[88] = dut.gy[5].gx[8].p.state;
            st[89] = dut.gy[5].gx[9].p.state;
            st[90] = dut.gy[5].gx[10].p.state;
            st[91] = dut.gy[5].gx[11].p.state;
            st[92] = dut.gy[5].gx[12].p.state;
            st[93] = dut.gy[5].gx[13].p.state;
            st[94] = dut.gy[5].gx[14].p.state;
            st[95] = dut.gy[5].gx[15].p.state;
            st[96] = dut.gy[6].gx[0].p.state;
            st[97] = dut.gy[6].gx[1].p.state;
            st[98] = dut.gy[6].gx[2].p.state;
            st[99] = dut.gy[6].gx[3].p.state;
            st[100] = dut.gy[6].gx[4].p.state;
            st[101] = dut.gy[6].gx[5].p.state;
            st[102] = dut.gy[6].gx[6].p.state;
            st[103] = dut.gy[6].gx[7].p.state;
            st[104] = dut.gy[6].gx[8].p.state;
            st[105] = dut.gy[6].gx[9].p.state;
            st[106] = dut.gy[6].gx[10].p.state;
            st[107] = dut.gy[6].gx[11].p.state;
            st[108] = dut.gy[6].gx[12].p.state;
            st[109] = dut.gy[6].gx[13].p.state;
            st[110] = dut.gy[6].gx[14].p.state;
            st[111] = dut.gy[6].gx[15].p.state;
            st[112] = dut.gy[7].gx[0].p.state;
            st[113] = dut.gy[7].gx[1].p.state;
            st[114] = dut.gy[7].gx[2].p.state;
            st[115] = dut.gy[7].gx[3].p.state;
            st[116] = dut.gy[7].gx[4].p.state;
            st[117] = dut.gy[7].gx[5].p.state;
            st[118] = dut.gy[7].gx[6].p.state;
            st[119] = dut.gy[7].gx[7].p.state;
            st[120] = dut.gy[7].gx[8].p.state;
            st[121] = dut.gy[7].gx[9].p.state;
            st[122] = dut.gy[7].gx[10].p.state;
            st[123] = dut.gy[7].gx[11].p.state;
            st[124] = dut.gy[7].gx[12].p.state;
            st[125] = dut.gy[7].gx[13].p.state;
            st[126] = dut.gy[7].gx[14].p.state;
            st[127] = dut.gy[7].gx[15].p.state;
            st[128] = dut.gy[8].gx[0].p.state;
            st[129] = dut.gy[8].gx[1].p.state;
            st[130] = dut.gy[8].gx[2].p.state;
            st[131] = dut.gy[8].gx[3].p.state;
            st[132] = dut.gy[8].gx[4].p.state;
            st[133] = dut.gy[8].gx[5].p.state;
            st[134] = dut.gy[8].gx[6].p.state;
            st[135] = dut.gy[8].gx[7].p.state;
            st[136] = dut.gy[8].gx[8].p.state;
            st[137] = dut.gy[8].gx[9].p.state;
            st[138] = dut.gy[8].gx[10].p.state;
            st[139] = dut.gy[8].gx[11].p.state;
            st[140] = dut.gy[8].gx[12].p.state;
            st[141] = dut.gy[8].gx[13].p.state;
            st[142] = dut.gy[8].gx[14].p.state;
            st[143] = dut.gy[8].gx[15].p.state;
            st[144] = dut.gy[9].gx[0].p.state;
            st[145] = dut.gy[9].gx[1].p.state;
            st[146] = dut.gy[9].gx[2].p.state;
            st[147] = dut.gy[9].gx[3].p.state;
            st[148] = dut.gy[9].gx[4].p.state;
            st[149] = dut.gy[9].gx[5].p.state;
            st[150] = dut.gy[9].gx[6].p.state;
            st[151] = dut.gy[9].gx[7].p.state;
            st[152] = dut.gy[9].gx[8].p.state;
            st[153] = dut.gy[9].gx[9].p.state;
            st[154] = dut.gy[9].gx[10].p.state;
            st[155] = dut.gy[9].gx[11].p.state;
            st[156] = dut.gy[9].gx[12].p.state;
            st[157] = dut.gy[9].gx[13].p.state;
            st[158] = dut.gy[9].gx[14].p.state;
            st[159] = dut.gy[9].gx[15].p.state;
            st[160] = dut.gy[10].gx[0].p.state;
            st[161] = dut.gy[10].gx[1].p.state;
            st[162] = dut.gy[10].gx[2].p.state;
            st[163] = dut.gy[10].gx[3].p.state;
            st[164] = dut.gy[10].gx[4].p.state;
            st[165] = dut.gy[10].gx[5].p.state;
            st[166] = dut.gy[10].gx[6].p.state;
            st[167] = dut.gy[10].gx[7].p.state;
            st[168] = dut.gy[10].gx[8].p.state;
            st[169] = dut.gy[10].gx[9].p.state;
            st[170] = dut.gy[10].gx[10].p.state;
            st[171] = dut.gy[10].gx[11].p.state;
            st[172] = dut.gy[10].gx[12].p.state;
            st[173] = dut.gy[10].gx[13].p.state;
            st[174] = dut.gy[10].gx[14].p.state;
            st[175] = dut.gy[10].gx[15].p.state;
            st[176] = dut.gy[11].gx[0].p.state;
            st[177] = dut.gy[11].gx[1].p.state;
            st[178] = dut.gy[11].gx[2].p.state;
            st[179] = dut.gy[11].gx[3].p.state;
            st[180] = dut.gy[11].gx[4].p.state;
            st[181] = dut.gy[11].gx[5].p.state;
            st[182] = dut.gy[11].gx[6].p.state;
            st[183] = dut.gy[11].gx[7].p.state;
            st[184] = dut.gy[11].gx[8].p.state;
            st[185] = dut.gy[11].gx[9].p.state;
            st[186] = dut.gy[11].gx[10].p.state;
            st[187] = dut.gy[11].gx[11].p.state;
            st[188] = dut.gy[11].gx[12].p.state;
            st[189] = dut.gy[11].gx[13].p.state;
            st[190] = dut.gy[11].gx[14].p.state;
            st[191] = dut.gy[11].gx[15].p.state;
            st[192] = dut.gy[12].gx[0].p.state;
            st[193] = dut.gy[12].gx[1].p.state;
            st[194] = dut.gy[12].gx[2].p.state;
            st[195] = dut.gy[12].gx[3].p.state;
            st[196] = dut.gy[12].gx[4].p.state;
            st[197] = dut.gy[12].gx[5].p.state;
            st[198] = dut.gy[12].gx[6].p.state;
            st[199] = dut.gy[12].gx[7].p.state;
            st[200] = dut.gy[12].gx[8].p.state;
            st[201] = dut.gy[12].gx[9].p.state;
            st[202] = dut.gy[12].gx[10].p.state;
            st[203] = dut.gy[12].gx[11].p.state;
            st[204] = dut.gy[12].gx[12].p.state;
            st[205] = dut.gy[12].gx[13].p.state;
            st[206] = dut.gy[12].gx[14].p.state;
            st[207] = dut.gy[12].gx[15].p.state;
            st[208] = dut.gy[13].gx[0].p.state;
            st[209] = dut.gy[13].gx[1].p.state;
            st[210] = dut.gy[13].gx[2].p.state;
            st[211] = dut.gy[13].gx[3].p.state;
            st[212] = dut.gy[13].gx[4].p.state;
            st[213] = dut.gy[13].gx[5].p.state;
            st[214] = dut.gy[13].gx[6].p.state;
            st[215] = dut.gy[13].gx[7].p.state;
            st[216] = dut.gy[13].gx[8].p.state;
            st[217] = dut.gy[13].gx[9].p.state;
            st[218] = dut.gy[13].gx[10].p.state;
            st[219] = dut.gy[13].gx[11].p.state;
            st[220] = dut.gy[13].gx[12].p.state;
            st[221] = dut.gy[13].gx[13].p.state;
            st[222] = dut.gy[13].gx[14].p.state;
            st[223] = dut.gy[13].gx[15].p.state;
            st[224] = dut.gy[14].gx[0].p.state;
            st[225] = dut.gy[14].gx[1].p.state;
            st[226] = dut.gy[14].gx[2].p.state;
            st[227] = dut.gy[14].gx[3].p.state;
            st[228] = dut.gy[14].gx[4].p.state;
            st[229] = dut.gy[14].gx[5].p.state;
            st[230] = dut.gy[14].gx[6].p.state;
            st[231] = dut.gy[14].gx[7].p.state;
            st[232] = dut.gy[14].gx[8].p.state;
            st[233] = dut.gy[14].gx[9].p.state;
            st[234] = dut.gy[14].gx[10].p.state;
            st[235] = dut.gy[14].gx[11].p.state;
            st[236] = dut.gy[14].gx[12].p.state;
            st[237] = dut.gy[14].gx[13].p.state;
            st[238] = dut.gy[14].gx[14].p.state;
            st[239] = dut.gy[14].gx[15].p.state;
            st[240] = dut.gy[15].gx[0].p.state;
            st[241] = dut.gy[15].gx[1].p.state;
            st[242] = dut.gy[15].gx[2].p.state;
            st[243] = dut.gy[15].gx[3].p.state;
            st[244] = dut.gy[15].gx[4].p.state;
            st[245] = dut.gy[15].gx[5].p.state;
            st[246] = dut.gy[15].gx[6].p.state;
            st[247] = dut.gy[15].gx[7].p.state;
            st[248] = dut.gy[15].gx[8].p.state;
            st[249] = dut.gy[15].gx[9].p.state;
            st[250] = dut.gy[15].gx[10].p.state;
            st[251] = dut.gy[15].gx[11].p.state;
            st[252] = dut.gy[15].gx[12].p.state;
            st[253] = dut.gy[15].gx[13].p.state;
            st[254] = dut.gy[15].gx[14].p.state;
            st[255] = dut.gy[15].gx[15].p.state;
            for (p = 0; p < NX * NY; p = p + 1) begin
                s = st[p];
                check(p % NX, p / NX);
            end
        end
    endtask
    initial begin
        if (!$value$plusargs("ctl=%s", file)) file = "control.hex";
        if (!$value$plusargs("exp=%s", efile)) efile = "expected.hex";
        $readmemh(file, mem);
        fd = $fopen(efile, "r");
        if (fd == 0) $display("CHECK off");
        #1 clk = 1; #1 clk = 0; rst = 0;
        while (!done && bad < 20) begin
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
