// Source: BelfrySCAD/BOSL2 sliders.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 2 of the file: rail() Example
include <BOSL2/std.scad>
include <BOSL2/sliders.scad>
rail(l=100, w=10, h=10);
