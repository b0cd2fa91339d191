// The paper's thickness study (section 6.3, Table 2): a 100 mm long soil layer of thickness h
// on a flat rigid base, no notches. Soil and base are meshed conformally along their common
// boundary but are different materials, so no joint ties them: the soil only touches
// the base (contact, as in inputs/peron/peron.geo, whose physical names it keeps); the deck
// layer.toml glues the soil's bottom (README.md). The three meshes of the sweep, from the
// repository root:
//   gmsh -2 -format msh41 -setnumber h 0.004 -o inputs/sweeps/layer_h4.msh inputs/sweeps/layer.geo
//   gmsh -2 -format msh41 -setnumber h 0.008 -o inputs/sweeps/layer_h8.msh inputs/sweeps/layer.geo
//   gmsh -2 -format msh41 -setnumber h 0.016 -o inputs/sweeps/layer_h16.msh inputs/sweeps/layer.geo
// Origin at the soil's bottom-left corner on the base's top.
DefineConstant[ h = {0.008, Name "layer thickness (m)"} ];
DefineConstant[ size = {0.001, Name "element size (m)"} ];

L = 0.1;              // layer length
overhang = 0.005;     // the base reaches past the soil's ends, so a lifting end corner
                      // never meets a corner of the base
base_below = 0.003;   // base thickness

Point(1) = {0, 0, 0, size};
Point(2) = {L, 0, 0, size};
Point(3) = {L, h, 0, size};
Point(4) = {0, h, 0, size};
Point(5) = {L + overhang, 0, 0, 2 * size};
Point(6) = {L + overhang, -base_below, 0, 2 * size};
Point(7) = {-overhang, -base_below, 0, 2 * size};
Point(8) = {-overhang, 0, 0, 2 * size};

Line(1) = {1, 2};  // interface: the soil's bottom on the base's top
Line(2) = {2, 3};  // right end
Line(3) = {3, 4};  // top
Line(4) = {4, 1};  // left end
Line(5) = {2, 5};
Line(6) = {5, 6};
Line(7) = {6, 7};
Line(8) = {7, 8};
Line(9) = {8, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8, 9, 1};
Plane Surface(2) = {2};

Physical Surface("soil") = {1};
Physical Surface("base") = {2};
Physical Curve("top") = {3};          // evaporation
Physical Curve("interface") = {1};    // soil on base: contact only, no joints
Physical Curve("left") = {4};         // the soil's ends: free
Physical Curve("right") = {2};
