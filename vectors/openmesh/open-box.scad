// OpenSCAD 2021.01 drops this cube without its top face ("The given mesh is not closed!"); csgpix voxelizes it.
difference() { polyhedron(points=[[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0], [0, 0, 10], [10, 0, 10], [10, 10, 10], [0, 10, 10]], faces=[[0,1,2,3],[0,4,5,1],[1,5,6,2],[2,6,7,3],[3,7,4,0]]); translate([20, 20, 20]) cube(1); }
