// Source: BelfrySCAD/BOSL2 walls.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 9 (line 2) of the file: hex_panel() Examples
include <BOSL2/std.scad>
include <BOSL2/walls.scad>
  hex_panel([50, 100, 5], 1.5, 10, frame = 5);
