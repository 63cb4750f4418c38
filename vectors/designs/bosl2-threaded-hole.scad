// Source: BelfrySCAD/BOSL2 threading.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 20 of the file: trapezoidal_threaded_rod() Example (Med;VPR=[100,0,5];VPD=220) Masking a horizontal threaded hole
include <BOSL2/std.scad>
include <BOSL2/threading.scad>
difference() {
  cuboid(50);
  trapezoidal_threaded_rod(
      d=25, l=51, pitch=4, $fn=36,
      thread_angle=30,
      internal=true, bevel=true,
      blunt_start=false,
      teardrop=true, orient=FWD
  );
}
