// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A plate cut by MCAD's NEMA 17 motor mount outline, with slots to tension a belt
// (MCAD/motors.scad).
include <MCAD/units.scad>
use <MCAD/motors.scad>

difference() {
    translate([-30, -30, 0]) cube([60, 70, 5]);
    translate([0, 0, -1]) linear_extrude(height = 7) stepper_motor_mount(17, slide_distance = 10);
}
