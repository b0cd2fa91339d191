// A block (0.1 x 0.05 m) resting on a wider base (0.2 x 0.05 m); the block's bottom is the
// middle third of the base's top, meshed once so both sides have coincident vertices there,
// but no joint ties them (they are different materials): the block only touches the base.
//   gmsh -2 -format msh41 -o block_on_base.msh block_on_base.geo
h = 0.0125;
Point(1) = {0, 0, 0, h};
Point(2) = {0.2, 0, 0, h};
Point(3) = {0.2, 0.05, 0, h};
Point(4) = {0.15, 0.05, 0, h};
Point(5) = {0.05, 0.05, 0, h};
Point(6) = {0, 0.05, 0, h};
Point(7) = {0.15, 0.1, 0, h};
Point(8) = {0.05, 0.1, 0, h};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};  // interface: the block's bottom
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {4, 7};
Line(8) = {7, 8};
Line(9) = {8, 5};

Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {-4, 7, 8, 9};
Plane Surface(2) = {2};

Physical Surface("base") = {1};
Physical Surface("block") = {2};
Physical Curve("interface") = {4};
Physical Curve("block_top") = {8};
