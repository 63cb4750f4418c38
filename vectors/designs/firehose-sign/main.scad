// Source: koen-lee/OpenSCAD-designs Firehose sign/sign.scad@66d0967a23a5c2eda22fa21bbae1a2839b84beac, licence MIT
color("red")
linear_extrude(0.4)
          import("sign.svg");