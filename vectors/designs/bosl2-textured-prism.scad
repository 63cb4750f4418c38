// Source: BelfrySCAD/BOSL2 shapes3d.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 63 of the file: regular_prism() Example  Textured prism
include <BOSL2/std.scad>
regular_prism(5, side=25, h=50, texture="diamonds", tex_size=[5,5], style="concave");
