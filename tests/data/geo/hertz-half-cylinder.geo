// Hertz's problem (SPEC §9, tests/solid/hertz_test.cpp): the lower half of a cylinder of
// radius R, its centre at (0, R), clamped on its flat top (Gamma_D), pressed by its
// weight onto the rigid half-plane y <= 0 that it touches at rest at the origin.
// fsicontact defines h (structure.h) before the first line: every size follows it, so
// a refinement study refines the contact zone too. The contact zone, |x| < a ~ 0.02 R,
// is meshed at h/50, growing to h away from it.
R = 1;
theta = 0.3;  // Gamma_C: the arc within theta of the bottom (contact stays within 0.05 R)
Point(1) = {0, R, 0};
Point(2) = {-R, R, 0};
Point(3) = {R, R, 0};
Point(4) = {0, 0, 0};
Point(5) = {-R * Sin(theta), R - R * Cos(theta), 0};
Point(6) = {R * Sin(theta), R - R * Cos(theta), 0};
Circle(1) = {2, 1, 5};
Circle(2) = {5, 1, 4};
Circle(3) = {4, 1, 6};
Circle(4) = {6, 1, 3};
Line(5) = {3, 2};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Physical Surface("Omega_S") = {1};
Physical Curve("Gamma_D") = {5};
Physical Curve("Gamma_C") = {2, 3};
Physical Curve("Gamma_N") = {1, 4};

Field[1] = Distance;
Field[1].PointsList = {4};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h / 50;
Field[2].SizeMax = h;
Field[2].DistMin = 0.05 * R;
Field[2].DistMax = 0.6 * R;
Background Field = 2;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
