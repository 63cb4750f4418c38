// Source: BelfrySCAD/BOSL2 gears.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 16 of the file: ring_gear() Example
include <BOSL2/std.scad>
include <BOSL2/gears.scad>
ring_gear(circ_pitch=5, teeth=48, thickness=10);
