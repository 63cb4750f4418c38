// Source: BelfrySCAD/BOSL2 walls.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 0 of the file: sparse_wall() Example  Typical Shape
include <BOSL2/std.scad>
include <BOSL2/walls.scad>
sparse_wall(h=40, l=100, thick=3);
