// A rock slope for tests/app/gmsh_case_test.cpp: a quadrangle rock layer (0 <= y <= 5 m) under
// a triangle soil layer, with a fault embedded in the soil. SI units (m).
// Regenerate slope.msh with:  gmsh -2 -format msh41 slope.geo -o slope.msh
// Outline (counter-clockwise): (0,0) (40,0) (40,20) (25,20) (15,10) (0,10); area 600 m^2.
h = 2.5;
Point(1) = {0, 0, 0, h};
Point(2) = {40, 0, 0, h};
Point(3) = {40, 5, 0, h};
Point(4) = {40, 20, 0, h};
Point(5) = {25, 20, 0, h};
Point(6) = {15, 10, 0, h};
Point(7) = {0, 10, 0, h};
Point(8) = {0, 5, 0, h};
Point(9) = {22, 8, 0, h};   // the fault's ends, inside the soil
Point(10) = {32, 15, 0, h};
Line(1) = {1, 2};   // base
Line(2) = {2, 3};   // right, rock
Line(3) = {3, 4};   // right, soil
Line(4) = {4, 5};   // crest
Line(5) = {5, 6};   // slope face
Line(6) = {6, 7};   // toe
Line(7) = {7, 8};   // left, soil
Line(8) = {8, 1};   // left, rock
Line(9) = {8, 3};   // rock-soil contact
Line(10) = {9, 10}; // fault
Curve Loop(1) = {1, 2, -9, 8};
Plane Surface(1) = {1};
Curve Loop(2) = {9, 3, 4, 5, 6, 7};
Plane Surface(2) = {2};
Curve{10} In Surface{2};
Recombine Surface{1};
Physical Surface("rock") = {1};
Physical Surface("soil") = {2};
Physical Curve("base") = {1};
Physical Curve("right") = {2, 3};
Physical Curve("left") = {7, 8};
Physical Curve("slope_face") = {5};
Physical Curve("fault") = {10};
Mesh.MshFileVersion = 4.1;
