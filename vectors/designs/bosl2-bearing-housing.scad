// Source: BelfrySCAD/BOSL2 linear_bearings.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 0 of the file: linear_bearing_housing() Example
include <BOSL2/std.scad>
include <BOSL2/linear_bearings.scad>
linear_bearing_housing(d=19, l=29, wall=2, tab=8, screwsize=2.5);
