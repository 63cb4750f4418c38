// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A flat spur gear with a hex-shaft bore (MCAD/gears.scad).
use <MCAD/gears.scad>

difference() {
    linear_extrude(height = 6) gear(number_of_teeth = 24, circular_pitch = 200);
    translate([0, 0, -1]) cylinder(r = 4, h = 8, $fn = 6);
}
