// Unit square, 2D: the bottom side is physical curve 7, the surface physical surface 3.
// Regenerate square_gmsh.msh with: gmsh -2 square.geo -format msh41 -o square_gmsh.msh
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.5};
Point(3) = {1, 1, 0, 0.5};
Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("bottom", 7) = {1};
Physical Surface("domain", 3) = {1};
