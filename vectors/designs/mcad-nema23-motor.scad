// Source: csgpix vectors/designs (written for this corpus), licence MIT; uses MCAD (LGPL-2.1, not copied) from OpenSCAD's library folder
// MCAD's model of a NEMA 23 stepper motor with a rear shaft (MCAD/stepper.scad).
include <MCAD/stepper.scad>

motor(Nema23, NemaMedium, dualAxis = true);
