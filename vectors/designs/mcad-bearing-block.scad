// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A pillow block for a 608 skate bearing, cut with MCAD's bearing outline (MCAD/bearing.scad).
use <MCAD/bearing.scad>

difference() {
    translate([-18, -18, 0]) cube([36, 36, 7]);
    translate([0, 0, -0.01]) bearing(outline = true);
    translate([0, 0, -1]) cylinder(d = 12, h = 10, $fn = 48);
    for (x = [-13, 13], y = [-13, 13]) translate([x, y, -1]) cylinder(d = 3.2, h = 10, $fn = 24);
}
