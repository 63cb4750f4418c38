// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// Two meshing double-helix gears (MCAD/involute_gears.scad's own demo module).
use <MCAD/involute_gears.scad>

meshing_double_helix();
