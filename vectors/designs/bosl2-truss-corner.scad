// Source: BelfrySCAD/BOSL2 cubetruss.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 1 (line 1) of the file: cubetruss_corner() Examples
include <BOSL2/std.scad>
include <BOSL2/cubetruss.scad>
cubetruss_corner(extents=2);
