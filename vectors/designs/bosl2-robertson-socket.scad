// Source: BelfrySCAD/BOSL2 screw_drive.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 4 of the file: robertson_mask() Example
include <BOSL2/std.scad>
include <BOSL2/screw_drive.scad>
difference() {
    cyl(d1=2, d2=8, h=4, anchor=TOP);
    robertson_mask(size=2);
}
