// sgene_derived against the golden vectors' care set; generated, do not edit.

module miter_derived_front(
    input wire L, S, Y, N, J, T, M,
    output wire ok_S1, ok_S2
);
    wire front_S1;
    wire front_S2;
    sgene_derived dut(.L(L), .S(S), .H(1'b0), .Y(Y), .X(1'b0), .P(1'b0), .N(N), .J(J), .T(T), .M(M), .front_S1(front_S1), .front_S2(front_S2));
    wire care_S1, val_S1;
    wire care_S2, val_S2;
    spec_front spec(.L(L), .S(S), .Y(Y), .N(N), .J(J), .T(T), .M(M), .care_S1(care_S1), .val_S1(val_S1), .care_S2(care_S2), .val_S2(val_S2));
    assign ok_S1 = ~care_S1 | (front_S1 == val_S1);
    assign ok_S2 = ~care_S2 | (front_S2 == val_S2);
endmodule

module miter_derived_back(
    input wire L, S, N, J, T, M,
    output wire ok_S1, ok_S2
);
    wire back_S1;
    wire back_S2;
    sgene_derived dut(.L(L), .S(S), .H(1'b0), .Y(1'b0), .X(1'b0), .P(1'b0), .N(N), .J(J), .T(T), .M(M), .back_S1(back_S1), .back_S2(back_S2));
    wire care_S1, val_S1;
    wire care_S2, val_S2;
    spec_back spec(.L(L), .S(S), .N(N), .J(J), .T(T), .M(M), .care_S1(care_S1), .val_S1(val_S1), .care_S2(care_S2), .val_S2(val_S2));
    assign ok_S1 = ~care_S1 | (back_S1 == val_S1);
    assign ok_S2 = ~care_S2 | (back_S2 == val_S2);
endmodule

module miter_derived_close(
    input wire L, N, J, T, M,
    output wire ok_S1, ok_S2
);
    wire close_S1;
    wire close_S2;
    sgene_derived dut(.L(L), .S(1'b0), .H(1'b0), .Y(1'b0), .X(1'b0), .P(1'b0), .N(N), .J(J), .T(T), .M(M), .close_S1(close_S1), .close_S2(close_S2));
    wire care_S1, val_S1;
    wire care_S2, val_S2;
    spec_close spec(.L(L), .N(N), .J(J), .T(T), .M(M), .care_S1(care_S1), .val_S1(val_S1), .care_S2(care_S2), .val_S2(val_S2));
    assign ok_S1 = ~care_S1 | (close_S1 == val_S1);
    assign ok_S2 = ~care_S2 | (close_S2 == val_S2);
endmodule

module miter_derived_clip(
    input wire H, Y, X, N, J, T, M,
    output wire ok_LL
);
    wire clip_LL;
    sgene_derived dut(.L(1'b0), .S(1'b0), .H(H), .Y(Y), .X(X), .P(1'b0), .N(N), .J(J), .T(T), .M(M), .clip_LL(clip_LL));
    wire care_LL, val_LL;
    spec_clip spec(.H(H), .Y(Y), .X(X), .N(N), .J(J), .T(T), .M(M), .care_LL(care_LL), .val_LL(val_LL));
    assign ok_LL = ~care_LL | (clip_LL == val_LL);
endmodule

module miter_derived_second(
    input wire P, N, J, T, M,
    output wire ok_S3, ok_S4
);
    wire second_S3;
    wire second_S4;
    sgene_derived dut(.L(1'b0), .S(1'b0), .H(1'b0), .Y(1'b0), .X(1'b0), .P(P), .N(N), .J(J), .T(T), .M(M), .second_S3(second_S3), .second_S4(second_S4));
    wire care_S3, val_S3;
    wire care_S4, val_S4;
    spec_second spec(.P(P), .N(N), .J(J), .T(T), .M(M), .care_S3(care_S3), .val_S3(val_S3), .care_S4(care_S4), .val_S4(val_S4));
    assign ok_S3 = ~care_S3 | (second_S3 == val_S3);
    assign ok_S4 = ~care_S4 | (second_S4 == val_S4);
endmodule

