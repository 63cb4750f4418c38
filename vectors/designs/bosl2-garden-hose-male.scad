// Source: BelfrySCAD/BOSL2 threading.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 27 of the file: garden_hose_male() Example
include <BOSL2/std.scad>
include <BOSL2/threading.scad>
garden_hose_male();
