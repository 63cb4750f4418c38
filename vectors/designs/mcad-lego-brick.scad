// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A 2x4 brick of MCAD's LEGO-compatible blocks (MCAD/lego_compatibility.scad).
include <MCAD/lego_compatibility.scad>

block(width = 2, length = 4, height = 1, reinforcement = true);
