// Applies every care row of vectors/select/*.pla to sgene_printed; generated, do not edit.
module tb_sgene_printed;
    reg L, S, H, Y, X, P, N, J, T, M;
    wire front_S1, front_S2, back_S1, back_S2, close_S1, close_S2, clip_LL, second_S3, second_S4;
    integer rows [0:8];
    integer bad [0:8];
    integer k, total;
    sgene_printed dut(.L(L), .S(S), .H(H), .Y(Y), .X(X), .P(P), .N(N), .J(J), .T(T), .M(M), .front_S1(front_S1), .front_S2(front_S2), .back_S1(back_S1), .back_S2(back_S2), .close_S1(close_S1), .close_S2(close_S2), .clip_LL(clip_LL), .second_S3(second_S3), .second_S4(second_S4));
    task clear; begin {L, S, H, Y, X, P, N, J, T, M} = 10'b0; end endtask
    initial begin
        for (k = 0; k < 9; k = k + 1) begin rows[k] = 0; bad[k] = 0; end
        clear; L = 1'b0; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=0 N=0 J=0 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=0 N=0 J=0 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=0 N=0 J=0 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=0 N=0 J=0 T=0 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=0 N=0 J=1 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=0 N=0 J=1 T=0 M=0 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=0 N=0 J=1 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=0 N=0 J=1 T=0 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=0 N=0 J=1 T=1 M=0 expected 0 got %b", front_S1); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=0 N=0 J=1 T=1 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=0 N=0 J=1 T=1 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b0; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=0 N=1 J=1 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=0 N=1 J=1 T=0 M=0 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=1 N=0 J=0 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=1 N=0 J=0 T=0 M=0 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=1 N=0 J=0 T=0 M=1 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=1 N=0 J=0 T=0 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=1 N=0 J=1 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=1 N=0 J=1 T=0 M=0 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=1 N=0 J=1 T=0 M=1 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=1 N=0 J=1 T=0 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=1 N=0 J=1 T=1 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=1 N=0 J=1 T=1 M=0 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=1 N=0 J=1 T=1 M=1 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=1 N=0 J=1 T=1 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; Y = 1'b1; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=0 Y=1 N=1 J=1 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=0 Y=1 N=1 J=1 T=0 M=0 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=0 N=0 J=0 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=0 N=0 J=0 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=0 N=0 J=0 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=0 N=0 J=0 T=0 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=0 N=0 J=1 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=0 N=0 J=1 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=0 N=0 J=1 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=0 N=0 J=1 T=0 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=0 N=0 J=1 T=1 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=0 N=0 J=1 T=1 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=0 N=0 J=1 T=1 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=0 N=0 J=1 T=1 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b0; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=0 N=1 J=1 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=0 N=1 J=1 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=1 N=0 J=0 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=1 N=0 J=0 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=1 N=0 J=0 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=1 N=0 J=0 T=0 M=1 expected 0 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=1 N=0 J=1 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=1 N=0 J=1 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=1 N=0 J=1 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=1 N=0 J=1 T=0 M=1 expected 0 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=1 N=0 J=1 T=1 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=1 N=0 J=1 T=1 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=1 N=0 J=1 T=1 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=1 N=0 J=1 T=1 M=1 expected 0 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b1; Y = 1'b1; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=0 S=1 Y=1 N=1 J=1 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=0 S=1 Y=1 N=1 J=1 T=0 M=0 expected 1 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=0 N=0 J=0 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=0 N=0 J=0 T=0 M=0 expected 1 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=0 N=0 J=0 T=0 M=1 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=0 N=0 J=0 T=0 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=0 N=0 J=1 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=0 N=0 J=1 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=0 N=0 J=1 T=0 M=1 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=0 N=0 J=1 T=0 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=0 N=0 J=1 T=1 M=0 expected 0 got %b", front_S1); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=0 N=0 J=1 T=1 M=1 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=0 N=0 J=1 T=1 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b0; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=0 N=1 J=1 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=0 N=1 J=1 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=1 N=0 J=0 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=1 N=0 J=0 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=1 N=0 J=0 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=1 N=0 J=0 T=0 M=1 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=1 N=0 J=1 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=1 N=0 J=1 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=1 N=0 J=1 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=1 N=0 J=1 T=0 M=1 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=1 N=0 J=1 T=1 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=1 N=0 J=1 T=1 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=1 N=0 J=1 T=1 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=1 N=0 J=1 T=1 M=1 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b0; Y = 1'b1; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=0 Y=1 N=1 J=1 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=0 Y=1 N=1 J=1 T=0 M=0 expected 1 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=0 N=0 J=0 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=0 N=0 J=0 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=0 N=0 J=0 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=0 N=0 J=0 T=0 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=0 N=0 J=1 T=0 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=0 N=0 J=1 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=0 N=0 J=1 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=0 N=0 J=1 T=0 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b0) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=0 N=0 J=1 T=1 M=0 expected 0 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=0 N=0 J=1 T=1 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=0 N=0 J=1 T=1 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=0 N=0 J=1 T=1 M=1 expected 1 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b0; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=0 N=1 J=1 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=0 N=1 J=1 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=1 N=0 J=0 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=1 N=0 J=0 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=1 N=0 J=0 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=1 N=0 J=0 T=0 M=1 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=1 N=0 J=1 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=1 N=0 J=1 T=0 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=1 N=0 J=1 T=0 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=1 N=0 J=1 T=0 M=1 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=1 N=0 J=1 T=1 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=1 N=0 J=1 T=1 M=0 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=1 N=0 J=1 T=1 M=1 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b0) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=1 N=0 J=1 T=1 M=1 expected 0 got %b", front_S2); end
        clear; L = 1'b1; S = 1'b1; Y = 1'b1; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[0] = rows[0] + 1;
        if (front_S1 !== 1'b1) begin bad[0] = bad[0] + 1; $display("MISMATCH front.S1 L=1 S=1 Y=1 N=1 J=1 T=0 M=0 expected 1 got %b", front_S1); end
        rows[1] = rows[1] + 1;
        if (front_S2 !== 1'b1) begin bad[1] = bad[1] + 1; $display("MISMATCH front.S2 L=1 S=1 Y=1 N=1 J=1 T=0 M=0 expected 1 got %b", front_S2); end
        clear; L = 1'b0; S = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=0 N=0 J=0 T=0 M=0 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=0 N=0 J=0 T=0 M=0 expected 1 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=0 N=0 J=0 T=0 M=1 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=0 N=0 J=0 T=0 M=1 expected 1 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=0 N=0 J=1 T=0 M=0 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=0 N=0 J=1 T=0 M=0 expected 0 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=0 N=0 J=1 T=0 M=1 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=0 N=0 J=1 T=0 M=1 expected 1 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=0 N=0 J=1 T=1 M=0 expected 0 got %b", back_S1); end
        clear; L = 1'b0; S = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=0 N=0 J=1 T=1 M=1 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=0 N=0 J=1 T=1 M=1 expected 1 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b0; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b1) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=0 N=1 J=1 T=0 M=0 expected 1 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=0 N=1 J=1 T=0 M=0 expected 1 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=1 N=0 J=0 T=0 M=0 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=1 N=0 J=0 T=0 M=0 expected 0 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=1 N=0 J=0 T=0 M=1 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=1 N=0 J=0 T=0 M=1 expected 0 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=1 N=0 J=1 T=0 M=0 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=1 N=0 J=1 T=0 M=0 expected 0 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=1 N=0 J=1 T=0 M=1 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=1 N=0 J=1 T=0 M=1 expected 0 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=1 N=0 J=1 T=1 M=0 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=1 N=0 J=1 T=1 M=0 expected 0 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=1 N=0 J=1 T=1 M=1 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=1 N=0 J=1 T=1 M=1 expected 0 got %b", back_S2); end
        clear; L = 1'b0; S = 1'b1; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b1) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=0 S=1 N=1 J=1 T=0 M=0 expected 1 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=0 S=1 N=1 J=1 T=0 M=0 expected 1 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=0 N=0 J=0 T=0 M=0 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=0 N=0 J=0 T=0 M=0 expected 0 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b1) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=0 N=0 J=0 T=0 M=1 expected 1 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=0 N=0 J=0 T=0 M=1 expected 1 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=0 N=0 J=1 T=0 M=0 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=0 N=0 J=1 T=0 M=0 expected 1 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b1) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=0 N=0 J=1 T=0 M=1 expected 1 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=0 N=0 J=1 T=0 M=1 expected 1 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=0 N=0 J=1 T=1 M=0 expected 0 got %b", back_S1); end
        clear; L = 1'b1; S = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b1) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=0 N=0 J=1 T=1 M=1 expected 1 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=0 N=0 J=1 T=1 M=1 expected 1 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b0; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=0 N=1 J=1 T=0 M=0 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=0 N=1 J=1 T=0 M=0 expected 1 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=1 N=0 J=0 T=0 M=0 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=1 N=0 J=0 T=0 M=0 expected 0 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=1 N=0 J=0 T=0 M=1 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=1 N=0 J=0 T=0 M=1 expected 0 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=1 N=0 J=1 T=0 M=0 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=1 N=0 J=1 T=0 M=0 expected 0 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=1 N=0 J=1 T=0 M=1 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=1 N=0 J=1 T=0 M=1 expected 0 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=1 N=0 J=1 T=1 M=0 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=1 N=0 J=1 T=1 M=0 expected 0 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b0) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=1 N=0 J=1 T=1 M=1 expected 0 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b0) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=1 N=0 J=1 T=1 M=1 expected 0 got %b", back_S2); end
        clear; L = 1'b1; S = 1'b1; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[2] = rows[2] + 1;
        if (back_S1 !== 1'b1) begin bad[2] = bad[2] + 1; $display("MISMATCH back.S1 L=1 S=1 N=1 J=1 T=0 M=0 expected 1 got %b", back_S1); end
        rows[3] = rows[3] + 1;
        if (back_S2 !== 1'b1) begin bad[3] = bad[3] + 1; $display("MISMATCH back.S2 L=1 S=1 N=1 J=1 T=0 M=0 expected 1 got %b", back_S2); end
        clear; L = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b0) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=0 N=0 J=0 T=0 M=0 expected 0 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=0 N=0 J=0 T=0 M=0 expected 1 got %b", close_S2); end
        clear; L = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b0) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=0 N=0 J=0 T=0 M=1 expected 0 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=0 N=0 J=0 T=0 M=1 expected 1 got %b", close_S2); end
        clear; L = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b1) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=0 N=0 J=1 T=0 M=0 expected 1 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=0 N=0 J=1 T=0 M=0 expected 1 got %b", close_S2); end
        clear; L = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b1) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=0 N=0 J=1 T=0 M=1 expected 1 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=0 N=0 J=1 T=0 M=1 expected 1 got %b", close_S2); end
        clear; L = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b1) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=0 N=0 J=1 T=1 M=0 expected 1 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=0 N=0 J=1 T=1 M=0 expected 1 got %b", close_S2); end
        clear; L = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b1) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=0 N=0 J=1 T=1 M=1 expected 1 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=0 N=0 J=1 T=1 M=1 expected 1 got %b", close_S2); end
        clear; L = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b1) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=1 N=0 J=0 T=0 M=0 expected 1 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=1 N=0 J=0 T=0 M=0 expected 1 got %b", close_S2); end
        clear; L = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b1) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=1 N=0 J=0 T=0 M=1 expected 1 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=1 N=0 J=0 T=0 M=1 expected 1 got %b", close_S2); end
        clear; L = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b0) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=1 N=0 J=1 T=0 M=0 expected 0 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=1 N=0 J=1 T=0 M=0 expected 1 got %b", close_S2); end
        clear; L = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b0) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=1 N=0 J=1 T=0 M=1 expected 0 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=1 N=0 J=1 T=0 M=1 expected 1 got %b", close_S2); end
        clear; L = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b1) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=1 N=0 J=1 T=1 M=0 expected 1 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=1 N=0 J=1 T=1 M=0 expected 1 got %b", close_S2); end
        clear; L = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[4] = rows[4] + 1;
        if (close_S1 !== 1'b1) begin bad[4] = bad[4] + 1; $display("MISMATCH close.S1 L=1 N=0 J=1 T=1 M=1 expected 1 got %b", close_S1); end
        rows[5] = rows[5] + 1;
        if (close_S2 !== 1'b1) begin bad[5] = bad[5] + 1; $display("MISMATCH close.S2 L=1 N=0 J=1 T=1 M=1 expected 1 got %b", close_S2); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=0 N=0 J=0 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=0 N=0 J=0 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=0 N=0 J=1 T=0 M=0 expected 0 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=0 N=0 J=1 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=0 N=0 J=1 T=1 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=0 N=0 J=1 T=1 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b0; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=0 N=1 J=1 T=0 M=0 expected 0 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=1 N=0 J=0 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=1 N=0 J=0 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=1 N=0 J=1 T=0 M=0 expected 0 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=1 N=0 J=1 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=1 N=0 J=1 T=1 M=0 expected 0 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=1 N=0 J=1 T=1 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b0; X = 1'b1; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=0 X=1 N=1 J=1 T=0 M=0 expected 0 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=0 N=0 J=0 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=0 N=0 J=0 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=0 N=0 J=1 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=0 N=0 J=1 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=0 N=0 J=1 T=1 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=0 N=0 J=1 T=1 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b0; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=0 N=1 J=1 T=0 M=0 expected 0 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=1 N=0 J=0 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=1 N=0 J=0 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=1 N=0 J=1 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=1 N=0 J=1 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=1 N=0 J=1 T=1 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=1 N=0 J=1 T=1 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b0; Y = 1'b1; X = 1'b1; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=0 Y=1 X=1 N=1 J=1 T=0 M=0 expected 0 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=0 N=0 J=0 T=0 M=0 expected 0 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=0 N=0 J=0 T=0 M=1 expected 0 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=0 N=0 J=1 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=0 N=0 J=1 T=0 M=1 expected 0 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=0 N=0 J=1 T=1 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=0 N=0 J=1 T=1 M=1 expected 0 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b0; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=0 N=1 J=1 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=1 N=0 J=0 T=0 M=0 expected 0 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=1 N=0 J=0 T=0 M=1 expected 0 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=1 N=0 J=1 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=1 N=0 J=1 T=0 M=1 expected 0 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=1 N=0 J=1 T=1 M=0 expected 0 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=1 N=0 J=1 T=1 M=1 expected 0 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b0; X = 1'b1; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=0 X=1 N=1 J=1 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=0 N=0 J=0 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=0 N=0 J=0 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=0 N=0 J=1 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=0 N=0 J=1 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=0 N=0 J=1 T=1 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=0 N=0 J=1 T=1 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b0; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=0 N=1 J=1 T=0 M=0 expected 0 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=1 N=0 J=0 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=1 N=0 J=0 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=1 N=0 J=1 T=0 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=1 N=0 J=1 T=0 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=1 N=0 J=1 T=1 M=0 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b1) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=1 N=0 J=1 T=1 M=1 expected 1 got %b", clip_LL); end
        clear; H = 1'b1; Y = 1'b1; X = 1'b1; N = 1'b1; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[6] = rows[6] + 1;
        if (clip_LL !== 1'b0) begin bad[6] = bad[6] + 1; $display("MISMATCH clip.LL H=1 Y=1 X=1 N=1 J=1 T=0 M=0 expected 0 got %b", clip_LL); end
        clear; P = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[7] = rows[7] + 1;
        if (second_S3 !== 1'b1) begin bad[7] = bad[7] + 1; $display("MISMATCH second.S3 P=0 N=0 J=0 T=0 M=0 expected 1 got %b", second_S3); end
        clear; P = 1'b0; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[7] = rows[7] + 1;
        if (second_S3 !== 1'b1) begin bad[7] = bad[7] + 1; $display("MISMATCH second.S3 P=0 N=0 J=0 T=0 M=1 expected 1 got %b", second_S3); end
        clear; P = 1'b0; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[7] = rows[7] + 1;
        if (second_S3 !== 1'b0) begin bad[7] = bad[7] + 1; $display("MISMATCH second.S3 P=0 N=0 J=1 T=0 M=0 expected 0 got %b", second_S3); end
        rows[8] = rows[8] + 1;
        if (second_S4 !== 1'b1) begin bad[8] = bad[8] + 1; $display("MISMATCH second.S4 P=0 N=0 J=1 T=0 M=0 expected 1 got %b", second_S4); end
        clear; P = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[7] = rows[7] + 1;
        if (second_S3 !== 1'b0) begin bad[7] = bad[7] + 1; $display("MISMATCH second.S3 P=0 N=0 J=1 T=1 M=0 expected 0 got %b", second_S3); end
        rows[8] = rows[8] + 1;
        if (second_S4 !== 1'b1) begin bad[8] = bad[8] + 1; $display("MISMATCH second.S4 P=0 N=0 J=1 T=1 M=0 expected 1 got %b", second_S4); end
        clear; P = 1'b0; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[7] = rows[7] + 1;
        if (second_S3 !== 1'b0) begin bad[7] = bad[7] + 1; $display("MISMATCH second.S3 P=0 N=0 J=1 T=1 M=1 expected 0 got %b", second_S3); end
        rows[8] = rows[8] + 1;
        if (second_S4 !== 1'b1) begin bad[8] = bad[8] + 1; $display("MISMATCH second.S4 P=0 N=0 J=1 T=1 M=1 expected 1 got %b", second_S4); end
        clear; P = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b0;
        #1;
        rows[7] = rows[7] + 1;
        if (second_S3 !== 1'b0) begin bad[7] = bad[7] + 1; $display("MISMATCH second.S3 P=1 N=0 J=0 T=0 M=0 expected 0 got %b", second_S3); end
        rows[8] = rows[8] + 1;
        if (second_S4 !== 1'b0) begin bad[8] = bad[8] + 1; $display("MISMATCH second.S4 P=1 N=0 J=0 T=0 M=0 expected 0 got %b", second_S4); end
        clear; P = 1'b1; N = 1'b0; J = 1'b0; T = 1'b0; M = 1'b1;
        #1;
        rows[7] = rows[7] + 1;
        if (second_S3 !== 1'b0) begin bad[7] = bad[7] + 1; $display("MISMATCH second.S3 P=1 N=0 J=0 T=0 M=1 expected 0 got %b", second_S3); end
        rows[8] = rows[8] + 1;
        if (second_S4 !== 1'b0) begin bad[8] = bad[8] + 1; $display("MISMATCH second.S4 P=1 N=0 J=0 T=0 M=1 expected 0 got %b", second_S4); end
        clear; P = 1'b1; N = 1'b0; J = 1'b1; T = 1'b0; M = 1'b0;
        #1;
        rows[7] = rows[7] + 1;
        if (second_S3 !== 1'b0) begin bad[7] = bad[7] + 1; $display("MISMATCH second.S3 P=1 N=0 J=1 T=0 M=0 expected 0 got %b", second_S3); end
        rows[8] = rows[8] + 1;
        if (second_S4 !== 1'b0) begin bad[8] = bad[8] + 1; $display("MISMATCH second.S4 P=1 N=0 J=1 T=0 M=0 expected 0 got %b", second_S4); end
        clear; P = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b0;
        #1;
        rows[7] = rows[7] + 1;
        if (second_S3 !== 1'b0) begin bad[7] = bad[7] + 1; $display("MISMATCH second.S3 P=1 N=0 J=1 T=1 M=0 expected 0 got %b", second_S3); end
        rows[8] = rows[8] + 1;
        if (second_S4 !== 1'b0) begin bad[8] = bad[8] + 1; $display("MISMATCH second.S4 P=1 N=0 J=1 T=1 M=0 expected 0 got %b", second_S4); end
        clear; P = 1'b1; N = 1'b0; J = 1'b1; T = 1'b1; M = 1'b1;
        #1;
        rows[7] = rows[7] + 1;
        if (second_S3 !== 1'b0) begin bad[7] = bad[7] + 1; $display("MISMATCH second.S3 P=1 N=0 J=1 T=1 M=1 expected 0 got %b", second_S3); end
        rows[8] = rows[8] + 1;
        if (second_S4 !== 1'b0) begin bad[8] = bad[8] + 1; $display("MISMATCH second.S4 P=1 N=0 J=1 T=1 M=1 expected 0 got %b", second_S4); end
        total = 0;
        $display("SIGNAL front.S1 rows %0d mismatches %0d", rows[0], bad[0]); total = total + bad[0];
        $display("SIGNAL front.S2 rows %0d mismatches %0d", rows[1], bad[1]); total = total + bad[1];
        $display("SIGNAL back.S1 rows %0d mismatches %0d", rows[2], bad[2]); total = total + bad[2];
        $display("SIGNAL back.S2 rows %0d mismatches %0d", rows[3], bad[3]); total = total + bad[3];
        $display("SIGNAL close.S1 rows %0d mismatches %0d", rows[4], bad[4]); total = total + bad[4];
        $display("SIGNAL close.S2 rows %0d mismatches %0d", rows[5], bad[5]); total = total + bad[5];
        $display("SIGNAL clip.LL rows %0d mismatches %0d", rows[6], bad[6]); total = total + bad[6];
        $display("SIGNAL second.S3 rows %0d mismatches %0d", rows[7], bad[7]); total = total + bad[7];
        $display("SIGNAL second.S4 rows %0d mismatches %0d", rows[8], bad[8]); total = total + bad[8];
        $display("TOTAL mismatches %0d", total);
        $finish;
    end
endmodule
