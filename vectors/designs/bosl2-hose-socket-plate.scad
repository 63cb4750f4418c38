// Source: BelfrySCAD/BOSL2 modular_hose.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 2 of the file: modular_hose() Example  Mounting plate for something at the end of the hose
include <BOSL2/std.scad>
include <BOSL2/modular_hose.scad>
 cuboid([50,50,5])
    attach(TOP) modular_hose(3/4, "socket", waist_len=0);
