// Source: BelfrySCAD/BOSL2 shapes3d.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 81 of the file: rect_tube() Example  Outer Rounding, Inner Chamfer
include <BOSL2/std.scad>
rect_tube(size=100, wall=5, rounding=10, ichamfer=8, h=30);
