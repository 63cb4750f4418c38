// Source: BelfrySCAD/BOSL2 threading.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 4 (line 1) of the file: threaded_nut() Examples (Med)
include <BOSL2/std.scad>
include <BOSL2/threading.scad>
threaded_nut(nutwidth=16, id=8, h=8, pitch=1.25, $slop=0.05, $fa=1, $fs=1);
