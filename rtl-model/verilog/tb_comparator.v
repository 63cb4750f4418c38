// Checks `comparator` against the definitions of N J T M (§2.3.2); generated, do not edit.
module tb_comparator;
    localparam F = 10, I = 10, O = 11, W = 32;
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
            want = {A[W-1], $signed(A) <= $signed(R), A == R, ~A[W-1] & |A[W-2:F+I]};
            pairs = pairs + 1;
            if ({N, J, T, M} !== want) begin
                bad = bad + 1;
                $display("MISMATCH A=%h R=%h NJTM=%b expected %b", A, R, {N, J, T, M}, want);
            end
        end
    endtask
    initial begin
        run(32'h0, 32'h0);
        run(32'h0, 32'h1);
        run(32'h0, 32'hffffffff);
        run(32'h0, 32'hfffff);
        run(32'h0, 32'h100000);
        run(32'h0, 32'h100001);
        run(32'h0, 32'hfff00000);
        run(32'h0, 32'h7fffffff);
        run(32'h0, 32'h80000000);
        run(32'h0, 32'h400);
        run(32'h1, 32'h0);
        run(32'h1, 32'h1);
        run(32'h1, 32'hffffffff);
        run(32'h1, 32'hfffff);
        run(32'h1, 32'h100000);
        run(32'h1, 32'h100001);
        run(32'h1, 32'hfff00000);
        run(32'h1, 32'h7fffffff);
        run(32'h1, 32'h80000000);
        run(32'h1, 32'h400);
        run(32'hffffffff, 32'h0);
        run(32'hffffffff, 32'h1);
        run(32'hffffffff, 32'hffffffff);
        run(32'hffffffff, 32'hfffff);
        run(32'hffffffff, 32'h100000);
        run(32'hffffffff, 32'h100001);
        run(32'hffffffff, 32'hfff00000);
        run(32'hffffffff, 32'h7fffffff);
        run(32'hffffffff, 32'h80000000);
        run(32'hffffffff, 32'h400);
        run(32'hfffff, 32'h0);
        run(32'hfffff, 32'h1);
        run(32'hfffff, 32'hffffffff);
        run(32'hfffff, 32'hfffff);
        run(32'hfffff, 32'h100000);
        run(32'hfffff, 32'h100001);
        run(32'hfffff, 32'hfff00000);
        run(32'hfffff, 32'h7fffffff);
        run(32'hfffff, 32'h80000000);
        run(32'hfffff, 32'h400);
        run(32'h100000, 32'h0);
        run(32'h100000, 32'h1);
        run(32'h100000, 32'hffffffff);
        run(32'h100000, 32'hfffff);
        run(32'h100000, 32'h100000);
        run(32'h100000, 32'h100001);
        run(32'h100000, 32'hfff00000);
        run(32'h100000, 32'h7fffffff);
        run(32'h100000, 32'h80000000);
        run(32'h100000, 32'h400);
        run(32'h100001, 32'h0);
        run(32'h100001, 32'h1);
        run(32'h100001, 32'hffffffff);
        run(32'h100001, 32'hfffff);
        run(32'h100001, 32'h100000);
        run(32'h100001, 32'h100001);
        run(32'h100001, 32'hfff00000);
        run(32'h100001, 32'h7fffffff);
        run(32'h100001, 32'h80000000);
        run(32'h100001, 32'h400);
        run(32'hfff00000, 32'h0);
        run(32'hfff00000, 32'h1);
        run(32'hfff00000, 32'hffffffff);
        run(32'hfff00000, 32'hfffff);
        run(32'hfff00000, 32'h100000);
        run(32'hfff00000, 32'h100001);
        run(32'hfff00000, 32'hfff00000);
        run(32'hfff00000, 32'h7fffffff);
        run(32'hfff00000, 32'h80000000);
        run(32'hfff00000, 32'h400);
        run(32'h7fffffff, 32'h0);
        run(32'h7fffffff, 32'h1);
        run(32'h7fffffff, 32'hffffffff);
        run(32'h7fffffff, 32'hfffff);
        run(32'h7fffffff, 32'h100000);
        run(32'h7fffffff, 32'h100001);
        run(32'h7fffffff, 32'hfff00000);
        run(32'h7fffffff, 32'h7fffffff);
        run(32'h7fffffff, 32'h80000000);
        run(32'h7fffffff, 32'h400);
        run(32'h80000000, 32'h0);
        run(32'h80000000, 32'h1);
        run(32'h80000000, 32'hffffffff);
        run(32'h80000000, 32'hfffff);
        run(32'h80000000, 32'h100000);
        run(32'h80000000, 32'h100001);
        run(32'h80000000, 32'hfff00000);
        run(32'h80000000, 32'h7fffffff);
        run(32'h80000000, 32'h80000000);
        run(32'h80000000, 32'h400);
        run(32'h400, 32'h0);
        run(32'h400, 32'h1);
        run(32'h400, 32'hffffffff);
        run(32'h400, 32'hfffff);
        run(32'h400, 32'h100000);
        run(32'h400, 32'h100001);
        run(32'h400, 32'hfff00000);
        run(32'h400, 32'h7fffffff);
        run(32'h400, 32'h80000000);
        run(32'h400, 32'h400);
        for (n = 0; n < 2000; n = n + 1) begin
            x = $random(seed); y = (n % 2) ? x : $random(seed);
            run(x, y);
        end
        $display("COMPARATOR pairs %0d mismatches %0d", pairs, bad);
        $finish;
    end
endmodule
