// SGENE, the select logic of seed 001 §2.3.3-2.3.5, `printed` equation set.
// Externals L S H Y X P (§2.3.2), comparator flags N J T M (§2.4.2).
module sgene_printed(
    input wire L, S, H, Y, X, P, N, J, T, M,
    output wire front_S1, front_S2, back_S1, back_S2, close_S1, close_S2, clip_LL, second_S3, second_S4
);
    // front.S1' = L'S'Y'N + Y'N'M' + L'S'YN' + LS'Y'N' + LS'YN
    assign front_S1 = ~((~L & ~S & ~Y & N) | (~Y & ~N & ~M) | (~L & ~S & Y & ~N) | (L & ~S & ~Y & ~N) | (L & ~S & Y & N));
    // front.S2' = SY'N + L'Y'N'J'M' + SYN' + LY'N + LYN' + SN'M' + LN'JT'M'
    assign front_S2 = ~((S & ~Y & N) | (~L & ~Y & ~N & ~J & ~M) | (S & Y & ~N) | (L & ~Y & N) | (L & Y & ~N) | (S & ~N & ~M) | (L & ~N & J & ~T & ~M));
    // back.S1' = L'S'N'J' + L'S'N'M' + LS'N + LS'N'JM'
    assign back_S1 = ~((~L & ~S & ~N & ~J) | (~L & ~S & ~N & ~M) | (L & ~S & N) | (L & ~S & ~N & J & ~M));
    // back.S2' = SN' + L'N'JT'M' + LN'J'M'
    assign back_S2 = ~((S & ~N) | (~L & ~N & J & ~T & ~M) | (L & ~N & ~J & ~M));
    // close.S1 = LJ' + L'J + T
    assign close_S1 = (L & ~J) | (~L & J) | (T);
    // close.S2 = 1
    assign close_S2 = (1'b1);
    // clip.LL = H'YT' + HY'N + HY'X'JM' + YJ'T' + HYJT + H'Y'N'M + H'Y'N'T + HY'XJT'M' + H'Y'N'J'
    assign clip_LL = (~H & Y & ~T) | (H & ~Y & N) | (H & ~Y & ~X & J & ~M) | (Y & ~J & ~T) | (H & Y & J & T) | (~H & ~Y & ~N & M) | (~H & ~Y & ~N & T) | (H & ~Y & X & J & ~T & ~M) | (~H & ~Y & ~N & ~J);
    // second.S3 = P'J'
    assign second_S3 = (~P & ~J);
    // second.S4 = P'
    assign second_S4 = (~P);
endmodule
