// A 2 x 1 rectangle in two layers: "base" (0 <= y <= 0.5) under "soil" (0.5 <= y <= 1),
// sharing the curve "interface"; "top" and "bottom" are also in "outer", so one curve carries
// two boundary names. Meshes for tests/test_gmsh.cpp (the second with parametric nodes):
//   gmsh -2 -format msh41 -o tests/data/two_materials.msh tests/data/two_materials.geo
//   gmsh -2 -format msh41 -setnumber Mesh.SaveParametric 1 \
//        -o tests/data/two_materials_parametric.msh tests/data/two_materials.geo
h = 0.4;
Point(1) = {0, 0, 0, h};
Point(2) = {2, 0, 0, h};
Point(3) = {2, 0.5, 0, h};
Point(4) = {0, 0.5, 0, h};
Point(5) = {2, 1, 0, h};
Point(6) = {0, 1, 0, h};

Line(1) = {1, 2};  // bottom
Line(2) = {2, 3};  // right side of base
Line(3) = {3, 4};  // interface
Line(4) = {4, 1};  // left side of base
Line(5) = {3, 5};  // right side of soil
Line(6) = {5, 6};  // top
Line(7) = {6, 4};  // left side of soil

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7};
Plane Surface(2) = {2};

Physical Surface("base") = {1};
Physical Surface("soil") = {2};
Physical Curve("bottom") = {1};
Physical Curve("top") = {6};
Physical Curve("interface") = {3};
Physical Curve("outer") = {1, 2, 4, 5, 6, 7};
