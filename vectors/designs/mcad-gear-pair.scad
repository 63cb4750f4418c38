// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// Two meshing spur gears on a base plate (MCAD/involute_gears.scad).
use <MCAD/involute_gears.scad>

pitch = 300;
teeth = [17, 11];
distance = (teeth[0] + teeth[1]) * pitch / 360;
translate([0, 0, 3]) gear(number_of_teeth = teeth[0], circular_pitch = pitch,
    gear_thickness = 5, rim_thickness = 6, hub_thickness = 10, bore_diameter = 5, circles = 4);
translate([distance, 0, 3]) rotate([0, 0, 180 / teeth[1]])
    gear(number_of_teeth = teeth[1], circular_pitch = pitch,
        gear_thickness = 6, rim_thickness = 6, hub_thickness = 8, bore_diameter = 4);
translate([-16, -16, 0]) cube([distance + 30, 32, 3]);
