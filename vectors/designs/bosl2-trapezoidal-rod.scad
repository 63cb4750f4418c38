// Source: BelfrySCAD/BOSL2 threading.scad@df336a2c28f31ffc6554d331d8323f48cbe7a04b, licence BSD-2-Clause
// Documentation example 6 of the file: trapezoidal_threaded_rod() Example  Standard metric threading
include <BOSL2/std.scad>
include <BOSL2/threading.scad>
trapezoidal_threaded_rod(d=10, l=40, pitch=2, $fn=32);
