// SGENE, the select logic of seed 001 §2.3.3-2.3.5, `derived` equation set.
// Externals L S H Y X P (§2.3.2), comparator flags N J T M (§2.4.2).
module sgene_derived(
    input wire L, S, H, Y, X, P, N, J, T, M,
    output wire front_S1, front_S2, back_S1, back_S2, close_S1, close_S2, clip_LL, second_S3, second_S4
);
    // front.S1 = SY + SN + LYN' + LY'N + L'YN + SM + L'Y'M
    assign front_S1 = (S & Y) | (S & N) | (L & Y & ~N) | (L & ~Y & N) | (~L & Y & N) | (S & M) | (~L & ~Y & M);
    // front.S2 = L'S'Y + YN + L'S'J + LS'Y'J' + Y'M
    assign front_S2 = (~L & ~S & Y) | (Y & N) | (~L & ~S & J) | (L & ~S & ~Y & ~J) | (~Y & M);
    // back.S1 = L'N + SN + LS'M
    assign back_S1 = (~L & N) | (S & N) | (L & ~S & M);
    // back.S2 = N + L'S'J' + LS'J + S'M
    assign back_S2 = (N) | (~L & ~S & ~J) | (L & ~S & J) | (~S & M);
    // close.S1 = LJ' + L'J + T
    assign close_S1 = (L & ~J) | (~L & J) | (T);
    // close.S2 = 1
    assign close_S2 = (1'b1);
    // clip.LL = YN' + H'J' + H'M + X'TM' + HY'JT'M'
    assign clip_LL = (Y & ~N) | (~H & ~J) | (~H & M) | (~X & T & ~M) | (H & ~Y & J & ~T & ~M);
    // second.S3 = P'J'
    assign second_S3 = (~P & ~J);
    // second.S4 = P'
    assign second_S4 = (~P);
endmodule
