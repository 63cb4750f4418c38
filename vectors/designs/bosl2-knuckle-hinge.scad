// Source: BelfrySCAD/BOSL2 hinges.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 1 of the file: knuckle_hinge() Example (NoScales) Basic hinge, mounted.  Odd segment count means the "outside"
include <BOSL2/std.scad>
include <BOSL2/hinges.scad>
$fn=32;
cuboid([2,40,15])
  position(TOP+RIGHT) orient(anchor=RIGHT)
    knuckle_hinge(length=35, segs=9, offset=3, arm_height=1);
