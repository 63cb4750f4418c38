// Source: BelfrySCAD/BOSL2 rounding.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 94 of the file: rounded_prism() Example  rounding all the edges differently
include <BOSL2/std.scad>
rounded_prism(pentagon(side=3), height=3, joint_top=0.25, joint_bot=0.5,
              joint_sides=[1.7,.5,.7,1.2,.4], splinesteps=32);
