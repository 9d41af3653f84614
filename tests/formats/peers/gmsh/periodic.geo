// A unit square with periodic bottom and top sides (curve 3 the image of curve 1 by (0, 1)): physical curve 5, surface 6.
lc = 0.5;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {4, 3}; Line(4) = {1, 4};
Curve Loop(1) = {1, 2, -3, -4};
Plane Surface(1) = {1};
Periodic Curve {3} = {1} Translate {0, 1, 0};
Physical Curve(5) = {1, 2, 3, 4};
Physical Surface(6) = {1};
