// A small cousin of inputs/peron/peron.geo for the thread-invariance test: a 40 mm x 6 mm
// soil layer resting on a rigid base with four 2 mm notches that the soil fills, meshed
// coarsely (about 300 triangles). The physical names are Peron's, so inputs/peron/peron.toml
// runs on it with mesh.file overridden. Regenerate from the repository root:
//   gmsh -2 -format msh41 -o tests/data/notched_layer.msh tests/data/notched_layer.geo
h = 0.002;      // element size in the soil
hn = 0.001;     // at the notches
L = 0.04;
H = 0.006;
notch = 0.002;  // width and depth
first_notch = 0.006;
pitch = 0.009;
notches = 4;

// The soil-base interface, left to right: per notch down, across, up.
Point(1) = {0, 0, 0, hn};
For i In {0 : notches - 1}
  xa = first_notch + i * pitch;
  Point(2 + 4 * i) = {xa, 0, 0, hn};
  Point(3 + 4 * i) = {xa, -notch, 0, hn};
  Point(4 + 4 * i) = {xa + notch, -notch, 0, hn};
  Point(5 + 4 * i) = {xa + notch, 0, 0, hn};
EndFor
last = 2 + 4 * notches;
Point(last) = {L, 0, 0, hn};
interface[] = {};
For k In {1 : last - 1}
  Line(k) = {k, k + 1};
  interface[] += {k};
EndFor

// Soil above the interface; base below it, reaching 2 mm past the soil's ends.
Point(100) = {L, H, 0, h};
Point(101) = {0, H, 0, h};
Line(100) = {last, 100};  // right
Line(101) = {100, 101};   // top
Line(102) = {101, 1};     // left
Curve Loop(1) = {interface[], 100, 101, 102};
Plane Surface(1) = {1};

Point(200) = {L + 0.002, 0, 0, h};
Point(201) = {L + 0.002, -notch - 0.002, 0, h};
Point(202) = {-0.002, -notch - 0.002, 0, h};
Point(203) = {-0.002, 0, 0, h};
Line(200) = {last, 200};
Line(201) = {200, 201};
Line(202) = {201, 202};
Line(203) = {202, 203};
Line(204) = {203, 1};
Curve Loop(2) = {200, 201, 202, 203, 204, interface[]};
Plane Surface(2) = {2};

Physical Surface("soil") = {1};
Physical Surface("base") = {2};
Physical Curve("top") = {101};
Physical Curve("interface") = {interface[]};
Physical Curve("left") = {102};
Physical Curve("right") = {100};
