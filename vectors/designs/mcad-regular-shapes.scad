// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// A pen holder of polygonal tubes on a torus-rimmed base (MCAD/regular_shapes.scad).
use <MCAD/regular_shapes.scad>

$fn = 48;
cylinder(r = 32, h = 3);
translate([0, 0, 3]) torus(34, 28);
translate([-14, 0, 0]) hexagon_tube(40, 12, 2);
translate([14, 0, 0]) octagon_tube(55, 12, 2);
translate([0, 20, 0]) pentagon_tube(30, 9, 2);
translate([0, -20, 0]) cylinder_tube(45, 8, 2);
