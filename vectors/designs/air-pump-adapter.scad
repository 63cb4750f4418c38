// Source: koen-lee/OpenSCAD-designs Air pump adapter.scad@66d0967a23a5c2eda22fa21bbae1a2839b84beac, licence MIT

rotate_extrude()
{
    polygon([
    [16,0],
    [15,20],
    [12,20],
    [9,18],
    [9,0],
    [10.4,0],
    [10.4, 17],
    [14,17],
    [14,0],
    ]);
}

translate([0,12,10])
    rotate([90,0,0])
    cylinder(d=3, h=6, center=true);

translate([0,-12,10])
    rotate([90,0,0])
    cylinder(d=3, h=6, center=true);