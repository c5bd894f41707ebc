// Bad on purpose: a unit square whose curve loop runs clockwise, so gmsh meshes it with its
// normal along -z and every triangle comes out clockwise (tests/io/gmsh_mesh_test.cpp expects
// bimrock to say so and to suggest `ReverseMesh Surface{1};`). SI units (m).
// Regenerate clockwise_surface.msh with:  gmsh -2 -format msh41 clockwise_surface.geo -o clockwise_surface.msh
// The same mesh in MSH 2.2 (version22.msh, refused):  gmsh -2 -format msh22 clockwise_surface.geo -o version22.msh
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.5};
Point(3) = {1, 1, 0, 0.5};
Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 4};
Line(2) = {4, 3};
Line(3) = {3, 2};
Line(4) = {2, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("rock") = {1};
Physical Curve("base") = {4};
