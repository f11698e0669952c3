// An unstructured hexahedral mesh of the quarter ball of
// prm/quarter_ball_file.prm (x >= 0, y >= 0 of the lower half of the ball
// of radius 0.5 around (0, 0, 1)): Gmsh's tetrahedra, each cut into four
// hexahedra, whose faces meet in all orientations (non-standard face
// orientations in deal.II). Physical tags as in prm/meshes/quarter_ball.msh:
// 1 = curved surface, 2 = flat top, 3 = plane x = 0, 4 = plane y = 0.
// Written by Gmsh 4.8.4:
//   gmsh -3 quarter_ball_unstructured.geo -format msh41 -o quarter_ball_unstructured.msh
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 1, 0.5};
Box(2) = {0, 0, 0.5, 0.5, 0.5, 0.5};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.CharacteristicLengthMin = 0.25;
Mesh.CharacteristicLengthMax = 0.25;
Mesh.SubdivisionAlgorithm = 2;
e = 1e-6;
Physical Surface(2) = Surface In BoundingBox{-e, -e, 1 - e, 0.5 + e, 0.5 + e, 1 + e};
Physical Surface(3) = Surface In BoundingBox{-e, -e, 0.5 - e, e, 0.5 + e, 1 + e};
Physical Surface(4) = Surface In BoundingBox{-e, -e, 0.5 - e, 0.5 + e, e, 1 + e};
Physical Surface(1) = Surface{:};
Physical Surface(1) -= {Surface In BoundingBox{-e, -e, 1 - e, 0.5 + e, 0.5 + e, 1 + e}};
Physical Surface(1) -= {Surface In BoundingBox{-e, -e, 0.5 - e, e, 0.5 + e, 1 + e}};
Physical Surface(1) -= {Surface In BoundingBox{-e, -e, 0.5 - e, 0.5 + e, e, 1 + e}};
Physical Volume(1) = {3};
