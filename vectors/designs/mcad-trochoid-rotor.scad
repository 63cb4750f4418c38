// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// An epitrochoid rotor with a bore, twisted as it rises (MCAD/trochoids.scad).
use <MCAD/trochoids.scad>

epitrochoidWBoreLinear(R = 20, r = 5, d = 4, n = 60, p = 60, thickness = 15, rb = 4, twist = 30);
