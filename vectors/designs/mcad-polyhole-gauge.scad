// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A drill gauge of polyholes from 2 to 10 mm (MCAD/polyholes.scad).
use <MCAD/polyholes.scad>

difference() {
    cube([100, 20, 4]);
    for (i = [0:8]) translate([6 + i * 11, 10, -1]) polyhole(6, 2 + i);
}
