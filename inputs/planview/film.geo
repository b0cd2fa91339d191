// A square film seen from above (issue 49, the plan view): side L, unstructured triangles of
// size h, so that its cracks follow no direction of the mesh. Regenerate the mesh from the
// repository root:
//   gmsh -2 -format msh41 -o inputs/planview/film.msh inputs/planview/film.geo
DefineConstant[ L = {0.1, Name "side of the film (m)"} ];
DefineConstant[ h = {0.00105, Name "element size (m)"} ];

Point(1) = {0, 0, 0, h};
Point(2) = {L, 0, 0, h};
Point(3) = {L, L, 0, h};
Point(4) = {0, L, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Physical Surface("film") = {1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};

Mesh.Algorithm = 6;          // Frontal-Delaunay: near-equilateral triangles in no set direction
Mesh.RandomSeed = 1;
