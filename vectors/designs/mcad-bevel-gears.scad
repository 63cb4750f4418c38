// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// MCAD's bevel gear pair at right angles (MCAD/involute_gears.scad).
use <MCAD/involute_gears.scad>

bevel_gear_pair(gear1_teeth = 21, gear2_teeth = 13, axis_angle = 90, outside_circular_pitch = 600);
