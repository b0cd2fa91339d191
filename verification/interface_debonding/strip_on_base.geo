// A soil strip (4 x 1 mm) bonded to the middle of a rigid base (8 x 1 mm): squares of 1 mm
// split into two triangles in the strip, 1 mm triangles in the base, and the same five
// vertices on both sides of the interface y = 0, 0 <= x <= 4 mm: four interface edges, which
// [interfaces.soil_base] bonds. The base reaches 2 mm past either end, so that the strip
// slides on it once debonded.
//   gmsh -2 -format msh41 -o strip_on_base.msh strip_on_base.geo
Point(1) = {-0.002, -0.001, 0, 0.001};
Point(2) = {0.006, -0.001, 0, 0.001};
Point(3) = {0.006, 0, 0, 0.001};
Point(4) = {0.004, 0, 0, 0.001};
Point(5) = {0, 0, 0, 0.001};
Point(6) = {-0.002, 0, 0, 0.001};
Point(7) = {0.004, 0.001, 0, 0.001};
Point(8) = {0, 0.001, 0, 0.001};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};  // the interface
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {4, 7};
Line(8) = {7, 8};
Line(9) = {8, 5};

Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {-4, 7, 8, 9};
Plane Surface(2) = {2};

Transfinite Curve{4, 8} = 5;
Transfinite Curve{7, 9} = 2;
Transfinite Surface{2};

Physical Surface("base") = {1};
Physical Surface("soil") = {2};
Physical Curve("top") = {8};
Physical Curve("soil_left") = {9};
Physical Curve("soil_right") = {7};
