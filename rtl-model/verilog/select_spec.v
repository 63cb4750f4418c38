// The golden select vectors (vectors/select/*.pla, seed 001 §2.3.3-2.3.5) as Verilog.

// front.pla as a function: care_O = 1 on a care row, val_O its expected value.
module spec_front(
    input wire L, S, Y, N, J, T, M,
    output reg care_S1, val_S1, care_S2, val_S2
);
    always @* begin
        {care_S1, val_S1, care_S2, val_S2} = 4'b0;
        casez ({L, S, Y, N, J, T, M})
            7'b0000000: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b0000001: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0000100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0000101: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0000110: begin care_S1 = 1'b1; val_S1 = 1'b0; end
            7'b0000111: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0001100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0010000: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0010001: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0010100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0010101: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0010110: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0010111: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0011100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0100000: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b0100001: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0100100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b0100101: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0100110: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b0100111: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b0101100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b0110000: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b0110001: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b0110100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b0110101: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b0110110: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b0110111: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b0111100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b1000000: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b1000001: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b1000100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1000101: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b1000110: begin care_S1 = 1'b1; val_S1 = 1'b0; end
            7'b1000111: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b1001100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1010000: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1010001: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1010100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1010101: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1010110: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1010111: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1011100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b1100000: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1100001: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b1100100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1100101: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b1100110: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1100111: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            7'b1101100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1110000: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1110001: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1110100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1110101: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1110110: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1110111: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b0; end
            7'b1111100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            default: ;
        endcase
    end
endmodule

// back.pla as a function: care_O = 1 on a care row, val_O its expected value.
module spec_back(
    input wire L, S, N, J, T, M,
    output reg care_S1, val_S1, care_S2, val_S2
);
    always @* begin
        {care_S1, val_S1, care_S2, val_S2} = 4'b0;
        casez ({L, S, N, J, T, M})
            6'b000000: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            6'b000001: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            6'b000100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b000101: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            6'b000110: begin care_S1 = 1'b1; val_S1 = 1'b0; end
            6'b000111: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            6'b001100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            6'b010000: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b010001: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b010100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b010101: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b010110: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b010111: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b011100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            6'b100000: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b100001: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            6'b100100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            6'b100101: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            6'b100110: begin care_S1 = 1'b1; val_S1 = 1'b0; end
            6'b100111: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            6'b101100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            6'b110000: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b110001: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b110100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b110101: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b110110: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b110111: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b0; end
            6'b111100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            default: ;
        endcase
    end
endmodule

// close.pla as a function: care_O = 1 on a care row, val_O its expected value.
module spec_close(
    input wire L, N, J, T, M,
    output reg care_S1, val_S1, care_S2, val_S2
);
    always @* begin
        {care_S1, val_S1, care_S2, val_S2} = 4'b0;
        casez ({L, N, J, T, M})
            5'b00000: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            5'b00001: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            5'b00100: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            5'b00101: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            5'b00110: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            5'b00111: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            5'b10000: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            5'b10001: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            5'b10100: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            5'b10101: begin care_S1 = 1'b1; val_S1 = 1'b0; care_S2 = 1'b1; val_S2 = 1'b1; end
            5'b10110: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            5'b10111: begin care_S1 = 1'b1; val_S1 = 1'b1; care_S2 = 1'b1; val_S2 = 1'b1; end
            default: ;
        endcase
    end
endmodule

// clip.pla as a function: care_O = 1 on a care row, val_O its expected value.
module spec_clip(
    input wire H, Y, X, N, J, T, M,
    output reg care_LL, val_LL
);
    always @* begin
        {care_LL, val_LL} = 2'b0;
        casez ({H, Y, X, N, J, T, M})
            7'b0000000: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0000001: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0000100: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b0000101: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0000110: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0000111: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0001100: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b0010000: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0010001: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0010100: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b0010101: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0010110: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b0010111: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0011100: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b0100000: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0100001: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0100100: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0100101: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0100110: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0100111: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0101100: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b0110000: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0110001: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0110100: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0110101: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0110110: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0110111: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b0111100: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b1000000: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b1000001: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b1000100: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1000101: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b1000110: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1000111: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b1001100: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1010000: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b1010001: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b1010100: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1010101: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b1010110: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b1010111: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b1011100: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1100000: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1100001: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1100100: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1100101: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1100110: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1100111: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1101100: begin care_LL = 1'b1; val_LL = 1'b0; end
            7'b1110000: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1110001: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1110100: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1110101: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1110110: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1110111: begin care_LL = 1'b1; val_LL = 1'b1; end
            7'b1111100: begin care_LL = 1'b1; val_LL = 1'b0; end
            default: ;
        endcase
    end
endmodule

// second.pla as a function: care_O = 1 on a care row, val_O its expected value.
module spec_second(
    input wire P, N, J, T, M,
    output reg care_S3, val_S3, care_S4, val_S4
);
    always @* begin
        {care_S3, val_S3, care_S4, val_S4} = 4'b0;
        casez ({P, N, J, T, M})
            5'b00000: begin care_S3 = 1'b1; val_S3 = 1'b1; end
            5'b00001: begin care_S3 = 1'b1; val_S3 = 1'b1; end
            5'b00100: begin care_S3 = 1'b1; val_S3 = 1'b0; care_S4 = 1'b1; val_S4 = 1'b1; end
            5'b00110: begin care_S3 = 1'b1; val_S3 = 1'b0; care_S4 = 1'b1; val_S4 = 1'b1; end
            5'b00111: begin care_S3 = 1'b1; val_S3 = 1'b0; care_S4 = 1'b1; val_S4 = 1'b1; end
            5'b10000: begin care_S3 = 1'b1; val_S3 = 1'b0; care_S4 = 1'b1; val_S4 = 1'b0; end
            5'b10001: begin care_S3 = 1'b1; val_S3 = 1'b0; care_S4 = 1'b1; val_S4 = 1'b0; end
            5'b10100: begin care_S3 = 1'b1; val_S3 = 1'b0; care_S4 = 1'b1; val_S4 = 1'b0; end
            5'b10110: begin care_S3 = 1'b1; val_S3 = 1'b0; care_S4 = 1'b1; val_S4 = 1'b0; end
            5'b10111: begin care_S3 = 1'b1; val_S3 = 1'b0; care_S4 = 1'b1; val_S4 = 1'b0; end
            default: ;
        endcase
    end
endmodule

