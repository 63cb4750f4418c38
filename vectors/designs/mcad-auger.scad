// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A tapered auger (MCAD/screw.scad).
use <MCAD/screw.scad>

auger(pitch = 30, length = 60, outside_radius = 20, inner_radius = 5, taper_ratio = 0.3);
