// The Peron et al. constrained desiccation test (paper section 5, Fig. 17): a 295 mm x 12 mm
// soil layer on an aluminium base whose top carries notches 2 mm wide and 2 mm deep, 2 mm
// apart; the slurry fills the notches, so the soil's bottom is a row of 2 mm teeth. Soil and
// base are meshed conformally along their common boundary, but they are different materials,
// so no joint ties them: the soil only rests on the base and presses on the notch walls
// (contact, as in verification/contact_rest). Regenerate the mesh from the repository root:
//   gmsh -2 -format msh41 -o inputs/peron/peron.msh inputs/peron/peron.geo
// and with elements half as large (h is the element size at the soil's top, m):
//   gmsh -2 -format msh41 -setnumber h 0.00075 -o inputs/peron/peron_fine.msh inputs/peron/peron.geo
// Origin at the soil's bottom-left corner on the base's top; notch bottoms at y = -2 mm.
DefineConstant[ h = {0.0015, Name "element size at the soil top (m)"} ];
hn = h / 2;   // along the soil-base interface: a 2 mm tooth is 3 edges wide at h = 1.5 mm
hb = 2 * h;   // the base's far side: it is rigid, a contact surface only

L = 0.295;             // layer length
H = 0.012;             // layer height above the base's top (the mould's height)
notch_width = 0.002;
notch_depth = 0.002;
notch_gap = 0.002;     // base top between two notches
pitch = notch_width + notch_gap;
notches = Floor((L - notch_gap) / pitch);              // 73
margin = (L - (notches * pitch - notch_gap)) / 2;      // 2.5 mm of flat base top at each end
overhang = 0.005;      // the base reaches past the soil's ends, so a lifting end corner
                       // never meets a corner of the base
base_below = 0.003;    // base thickness under the notch bottoms

// The interface, left to right: flat top of the base, then per notch down, across, up.
p = newp;
Point(p) = {0, 0, 0};
first = p;
For i In {0 : notches - 1}
  xa = margin + i * pitch;
  Point(p + 4 * i + 1) = {xa, 0, 0};
  Point(p + 4 * i + 2) = {xa, -notch_depth, 0};
  Point(p + 4 * i + 3) = {xa + notch_width, -notch_depth, 0};
  Point(p + 4 * i + 4) = {xa + notch_width, 0, 0};
EndFor
last = p + 4 * notches + 1;
Point(last) = {L, 0, 0};

interface[] = {};
For k In {first : last - 1}
  l = newl;
  Line(l) = {k, k + 1};
  interface[] += {l};
EndFor

// Soil: the interface, its right end, its top, its left end.
p_top_right = newp; Point(p_top_right) = {L, H, 0};
p_top_left = newp;  Point(p_top_left) = {0, H, 0};
right = newl; Line(right) = {last, p_top_right};
top = newl;   Line(top) = {p_top_right, p_top_left};
left = newl;  Line(left) = {p_top_left, first};
Curve Loop(1) = {interface[], right, top, left};
soil = 1; Plane Surface(soil) = {1};

// Base: the interface seen from below, with an overhang at each end.
b1 = newp; Point(b1) = {L + overhang, 0, 0};
b2 = newp; Point(b2) = {L + overhang, -notch_depth - base_below, 0};
b3 = newp; Point(b3) = {-overhang, -notch_depth - base_below, 0};
b4 = newp; Point(b4) = {-overhang, 0, 0};
c1 = newl; Line(c1) = {last, b1};
c2 = newl; Line(c2) = {b1, b2};
c3 = newl; Line(c3) = {b2, b3};
c4 = newl; Line(c4) = {b3, b4};
c5 = newl; Line(c5) = {b4, first};
Curve Loop(2) = {c1, c2, c3, c4, c5, interface[]};
base = 2; Plane Surface(base) = {2};

// Element size: hn on the interface, growing to h (soil) or hb (base) over the notch depth.
// The fields alone set it (not the points), on the curves too: Restrict lists them.
Field[1] = Distance;
Field[1].CurvesList = {interface[]};
Field[1].NumPointsPerCurve = 20;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hn;
Field[2].SizeMax = h;
Field[2].DistMin = hn;
Field[2].DistMax = notch_depth;
Field[3] = Restrict;
Field[3].InField = 2;
Field[3].SurfacesList = {soil};
Field[3].CurvesList = {interface[], right, top, left};
Field[4] = Threshold;
Field[4].InField = 1;
Field[4].SizeMin = hn;
Field[4].SizeMax = hb;
Field[4].DistMin = hn;
Field[4].DistMax = notch_depth;
Field[5] = Restrict;
Field[5].InField = 4;
Field[5].SurfacesList = {base};
Field[5].CurvesList = {interface[], c1, c2, c3, c4, c5};
Field[6] = Min;
Field[6].FieldsList = {3, 5};
Background Field = 6;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Surface("soil") = {soil};
Physical Surface("base") = {base};
Physical Curve("top") = {top};              // evaporation
Physical Curve("interface") = {interface[]}; // soil on base: contact only, no joints
Physical Curve("left") = {left};            // the soil's ends: free (README)
Physical Curve("right") = {right};
