// Source: BelfrySCAD/BOSL2 rounding.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 78 of the file: offset_sweep() Example (3D,Med) Star shaped box
include <BOSL2/std.scad>
star = star(5, r=22, ir=13);
rounded_star = round_corners(star, cut=flatten(repeat([.5,0],5)), $fn=24);
thickness = 2;
ht=20;
difference(){
  offset_sweep(rounded_star, height=ht, bottom=["for","offset_sweep","r",4],
                                        top=["for","offset_sweep","r",1], steps=15);
  up(thickness)
      offset_sweep(offset(rounded_star,r=-thickness,closed=true),
                    height=ht-thickness, check_valid=false,
                    bottom=os_circle(r=7), top=os_circle(r=-1, extra=1),$fn=40);
  }
