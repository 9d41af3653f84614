// Gmsh's anisotropic 2D mesher (BAMG, Mesh.Algorithm = 7) on the unit square or, with
// -setnumber lshape 1, the L-shape [0,1]x[0,1/2] u [0,1/2]x[1/2,1], for the metric of the tensor
// view bg.pos beside this file (written by `anisocert metric --grid`), as Gmsh's tutorial t17
// drives it: the view is the background mesh. Gmsh remeshes three times, re-evaluating the view
// at the new vertices. Everything else is Gmsh's default but what would override the metric:
// sizes from points and curvature, and the extension of boundary sizes. scripts/validate runs it.
DefineConstant[ lshape = 0 ];
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};
If (lshape)
  Point(3) = {1, 0.5, 0}; Point(4) = {0.5, 0.5, 0}; Point(5) = {0.5, 1, 0}; Point(6) = {0, 1, 0};
  Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
  Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Else
  Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
  Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
  Curve Loop(1) = {1, 2, 3, 4};
EndIf
Plane Surface(1) = {1};
Merge "bg.pos";
Background Mesh View[0];
Mesh.Algorithm = 7;
Mesh.AnisoMax = 1e6;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MshFileVersion = 4.1;
