// Source: BelfrySCAD/BOSL2 hooks.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 9 of the file: ring_hook() Example  Rounding all edges
include <BOSL2/std.scad>
include <BOSL2/hooks.scad>
ring_hook([50, 10], 40, 25, ir=15, rounding=5, hole_rounding=5, fillet=5);
