// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A corner gusset bracket made of MCAD's right triangles (MCAD/triangles.scad).
use <MCAD/triangles.scad>

difference() {
    union() {
        cube([40, 40, 3]);
        cube([40, 3, 40]);
        for (x = [0, 37]) translate([x, 3, 3]) rotate([90, 0, 90]) triangle(30, 30, 3);
    }
    for (x = [10, 30]) {
        translate([x, 20, -1]) cylinder(d = 4, h = 5, $fn = 24);
        translate([x, -1, 20]) rotate([-90, 0, 0]) cylinder(d = 4, h = 5, $fn = 24);
    }
}
