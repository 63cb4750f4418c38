// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A clamp block with two M4 bolt holes and captive nut traps (MCAD/nuts_and_bolts.scad).
include <MCAD/units.scad>
use <MCAD/nuts_and_bolts.scad>

difference() {
    translate([-20, -8, 0]) cube([40, 16, 12]);
    for (x = [-12, 12]) translate([x, 0, 0]) {
        translate([0, 0, 12]) rotate([180, 0, 0]) boltHole(4, length = 14);
        translate([0, 0, -0.01]) nutHole(4);
    }
    translate([0, 0, 6]) rotate([0, 90, 0]) cylinder(d = 8, h = 50, center = true, $fn = 40);
}
