// Issue 41's pulley class: thousands of small 2D shapes of many fragments, extruded once.
// A plate of 42 GT2-style pulleys, each a disc minus its bore and 58 tooth grooves, every
// groove the 2D intersection of two circles and a square: 4,956 circles and 2,436 squares in
// 2,436 intersections, every circle of 1,080 fragments (5.4 million outline vertices). The public
// pulley the issue measured (4,915 circles, 2,418 squares, 3.1 s at 64^3 and 3.5-5.9 s with a
// 1.6 GB peak at 256^3) is not in the repository; this plate takes the same time and memory.
$fn = 1080;
teeth = 58;

module pulley2d(r) {
  difference() {
    circle(r);
    circle(2.5);
    for (i = [0 : teeth - 1]) rotate(i * 360 / teeth) translate([0, r - 0.4])
      intersection() {
        translate([-0.25, 0]) circle(0.555);
        translate([0.25, 0]) circle(0.555);
        square([1.0, 1.2], center = true);
      }
  }
}

linear_extrude(7)
  for (x = [0 : 6], y = [0 : 5]) translate([x * 40, y * 40]) pulley2d(18.2);
