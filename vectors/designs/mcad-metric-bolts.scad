// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A row of MCAD's metric fasteners: cap and countersunk bolts, nuts and washers
// (MCAD/metric_fastners.scad).
include <MCAD/metric_fastners.scad>

cap_bolt(5, 20);
translate([15, 0, 0]) csk_bolt(5, 20);
translate([30, 0, 0]) flat_nut(5);
translate([45, 0, 0]) washer(5);
translate([60, 0, 0]) bolt(4, 16);
