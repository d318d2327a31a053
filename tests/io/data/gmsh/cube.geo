// Unit cube, 3D: the face z = 0 is physical surface 11, the volume physical volume 5.
// Regenerate cube_gmsh.msh with: gmsh -3 cube.geo -format msh41 -o cube_gmsh.msh
SetFactory("Built-in");
Point(1) = {0, 0, 0, 0.6};
Point(2) = {1, 0, 0, 0.6};
Point(3) = {1, 1, 0, 0.6};
Point(4) = {0, 1, 0, 0.6};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Extrude {0, 0, 1} { Surface{1}; }
Physical Surface("bottom", 11) = {1};
Physical Volume("cube", 5) = {1};
