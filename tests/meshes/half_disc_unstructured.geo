// An unstructured quadrilateral mesh of the half disc of prm/hertz.prm (the
// lower half of the disc of radius 0.5 around (0, 1)), finer toward the
// lowest point. Its cells are numbered in no consistent orientation (Gmsh's
// recombination), which deal.II's reader orders. Physical tags: 1 = the
// curved side (contact), 2 = the flat top. Written by Gmsh 4.8.4:
//   gmsh -2 half_disc_unstructured.geo -format msh22 -o half_disc_unstructured_v2.msh
//   gmsh -2 half_disc_unstructured.geo -format msh41 -o half_disc_unstructured_v4.msh
// (and half_disc_unstructured.inp by convert_msh.py from the first)
Point(1) = {0, 1, 0, 0.2};
Point(2) = {-0.5, 1, 0, 0.25};
Point(3) = {0, 0.5, 0, 0.06};
Point(4) = {0.5, 1, 0, 0.25};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Mesh.RecombineAll = 1;
Mesh.SubdivisionAlgorithm = 1;
Physical Curve(1) = {1, 2};
Physical Curve(2) = {3};
Physical Surface(1) = {1};
