// Source: BelfrySCAD/BOSL2 skin.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 12 of the file: skin() Example  Forma Candle Holder (from list-comprehension-demos)
include <BOSL2/std.scad>
r = 50;
height = 140;
layers = 10;
wallthickness = 5;
holeradius = r - wallthickness;
difference() {
    skin([for (i=[0:layers-1]) zrot(-30*i,p=path3d(hexagon(ir=r),i*height/layers))],slices=0);
    up(height/layers) cylinder(r=holeradius, h=height);
}
