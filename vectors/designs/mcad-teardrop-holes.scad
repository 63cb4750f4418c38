// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A bar with horizontal teardrop holes that print without support (MCAD/teardrop.scad).
use <MCAD/teardrop.scad>

difference() {
    cube([80, 12, 14]);
    for (i = [0:4]) translate([10 + i * 15, 6, 7]) rotate([0, 0, 90])
        teardrop(radius = 2 + i * 0.5, length = 20, angle = 90);
}
