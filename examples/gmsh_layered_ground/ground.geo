// Example 4 (examples/gmsh_layered_ground): 4 m of soil on 6 m of rock, 10 m wide. SI units (m).
// The rock is meshed in quadrangles, the soil in triangles; the physical groups are what the
// case file refers to. Regenerate ground.msh with:  gmsh -2 -format msh41 ground.geo -o ground.msh
h = 1.0;
Point(1) = {0, 0, 0, h};
Point(2) = {10, 0, 0, h};
Point(3) = {10, 6, 0, h};
Point(4) = {10, 10, 0, h};
Point(5) = {0, 10, 0, h};
Point(6) = {0, 6, 0, h};
Line(1) = {1, 2};  // base
Line(2) = {2, 3};  // right, rock
Line(3) = {3, 4};  // right, soil
Line(4) = {4, 5};  // ground surface
Line(5) = {5, 6};  // left, soil
Line(6) = {6, 1};  // left, rock
Line(7) = {6, 3};  // rock-soil contact
Curve Loop(1) = {1, 2, -7, 6};  // counter-clockwise: the cells come out counter-clockwise
Plane Surface(1) = {1};
Curve Loop(2) = {7, 3, 4, 5};
Plane Surface(2) = {2};
Recombine Surface{1};
Physical Surface("rock") = {1};
Physical Surface("soil") = {2};
Physical Curve("base") = {1};
Physical Curve("sides") = {2, 3, 5, 6};
Physical Curve("surface") = {4};
Mesh.MshFileVersion = 4.1;
