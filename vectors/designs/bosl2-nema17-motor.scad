// Source: BelfrySCAD/BOSL2 nema_steppers.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 0 (line 3) of the file: nema_stepper_motor() Examples
include <BOSL2/std.scad>
include <BOSL2/nema_steppers.scad>
nema_stepper_motor(size=17, h=40, shaft_len=30);
