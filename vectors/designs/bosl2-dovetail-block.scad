// Source: BelfrySCAD/BOSL2 joiners.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 10 of the file: dovetail() Example  A block that can link to itself
include <BOSL2/std.scad>
include <BOSL2/joiners.scad>
diff()
  cuboid([50,30,10]){
    attach(BACK) dovetail("male", slide=10, width=15, height=8);
    tag("remove")attach(FRONT) dovetail("female", slide=10, width=15, height=8);
  }
