// Source: BelfrySCAD/BOSL2 bottlecaps.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 10 of the file: pco1881_cap() Example
include <BOSL2/std.scad>
include <BOSL2/bottlecaps.scad>
pco1881_cap();
