// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A bracket with a pocket shaped by MCAD's Futaba S3003 servo model (MCAD/servos.scad).
use <MCAD/servos.scad>

difference() {
    translate([-6, -4, -2]) cube([54, 28, 24]);
    futabas3003([0, 0, 0], [0, 0, 0]);
}
