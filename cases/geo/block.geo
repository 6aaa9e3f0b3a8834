// A square block, 20 mm a side, its top (Gamma_D) held, its other sides free (Gamma_N)
// and all candidates for contact (contact.boundary = "all"). fsicontact defines h
// (structure.h) before the first line: the bottom is meshed at h/4 where the wedge's
// tip meets it, h elsewhere.
a = 0.02;
Point(1) = {-a / 2, 0.0005, 0, h / 4};
Point(2) = {a / 2, 0.0005, 0, h / 4};
Point(3) = {a / 2, a + 0.0005, 0, h};
Point(4) = {-a / 2, a + 0.0005, 0, h};
Point(5) = {0, 0.0005, 0, h / 4};
Line(1) = {1, 5};
Line(2) = {5, 2};
Line(3) = {2, 3};
Line(4) = {3, 4};
Line(5) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Physical Surface("Omega_S") = {1};
Physical Curve("Gamma_D") = {4};
Physical Curve("Gamma_N") = {1, 2, 3, 5};
