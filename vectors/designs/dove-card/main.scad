// Source: lkiesow/3d-models karten/taube.scad@90a2ae03598e8069a2904025c21e6c3d90d31564, licence MIT
linear_extrude(height = 2) {
  import(file = "taube.svg", center = false, dpi = 96);
}
