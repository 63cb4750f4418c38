// Source: BelfrySCAD/BOSL2 tripod_mounts.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 0 (line 1) of the file: manfrotto_rc2_plate() Examples
include <BOSL2/std.scad>
include <BOSL2/tripod_mounts.scad>
manfrotto_rc2_plate();
