// Source: BelfrySCAD/BOSL2 screws.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 8 of the file: screw_hole() Example  Counterbored clearance hole
include <BOSL2/std.scad>
include <BOSL2/screws.scad>
diff()
  cuboid(20)
    attach(TOP)
      screw_hole("1/4-20,.5",head="socket",counterbore=5,anchor=TOP);
