sgene_derived.v
comparator.v
depgen.v
pixel.v
pixel_array.v
controller.v
machine.v
