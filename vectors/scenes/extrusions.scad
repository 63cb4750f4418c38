// OpenSCAD nodes built from 2D shapes (docs/volume-scenes.md): a twisted holed bar, a
// revolved profile, a hull and an offset, minus a drilled hole.
difference() {
    union() {
        linear_extrude(height = 20, twist = 60)
            difference() { square(10, center = true); circle(r = 3); }
        translate([18, 0, 0]) rotate_extrude($fn = 32)
            polygon([[0, 0], [6, 0], [4, 4], [5, 10], [0, 12]]);
        translate([0, 18, 0]) hull() { cylinder(r = 3, h = 4); translate([8, 0, 6]) sphere(r = 2); }
        translate([18, 18, 0]) linear_extrude(height = 5) offset(r = 1.5) square(6, center = true);
    }
    translate([18, 18, -1]) cylinder(r = 1.5, h = 10, $fn = 16);
}
