// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A small open-topped box with rounded vertical edges (MCAD/boxes.scad).
use <MCAD/boxes.scad>

size = [60, 40, 25];
wall = 2;
difference() {
    translate([0, 0, size[2] / 2]) roundedBox(size, 5, true);
    translate([0, 0, size[2] / 2 + wall]) roundedBox(size - [2, 2, 0] * wall, 5 - wall, true);
}
