// Unit square with periodic top/bottom sides, saved with parametric coordinates, to exercise
// the $Periodic section and parametric node blocks of what Gmsh writes.
// Regenerate square_periodic_gmsh.msh with:
//   gmsh -2 square_periodic.geo -format msh41 -setnumber Mesh.SaveParametric 1 -o square_periodic_gmsh.msh
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.5};
Point(3) = {1, 1, 0, 0.5};
Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {4, 3};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, -3, 4};
Plane Surface(1) = {1};
Periodic Curve {3} = {1} Translate {0, 1, 0};
Physical Surface("domain", 3) = {1};
