// Source: BelfrySCAD/BOSL2 joiners.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 7 of the file: joiner() Example (3D)
include <BOSL2/std.scad>
include <BOSL2/joiners.scad>
diff()
cuboid(50)
  attach([FWD,TOP,RIGHT])
    zrot_copies(n=2,r=15)
      joiner();
