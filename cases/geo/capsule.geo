// A capsule: a 40 mm stadium of radius 5 mm (a rectangle between two half disks),
// held by a 6 mm stem at the top of its left cap (Gamma_D), its boundary otherwise
// free (Gamma_N). fsicontact defines h (structure.h) before the first line.
r = 0.005;
l = 0.03;  // between the caps' centres
Point(1) = {0, 0, 0, h};        // left cap's centre
Point(2) = {l, 0, 0, h};        // right cap's centre
Point(3) = {0, -r, 0, h};
Point(4) = {l, -r, 0, h};
Point(5) = {l + r, 0, 0, h};
Point(6) = {l, r, 0, h};
Point(7) = {0.003, r, 0, h};    // the stem: 3 mm either side of the left centre
Point(8) = {-0.003, Sqrt(r * r - 0.003 * 0.003), 0, h};
Point(9) = {0.003, r + 0.001, 0, h};
Point(10) = {-0.003, r + 0.001, 0, h};
Point(11) = {-r, 0, 0, h};
Point(12) = {0, r, 0, h};
Line(1) = {3, 4};                // bottom
Circle(2) = {4, 2, 5};           // right cap
Circle(3) = {5, 2, 6};
Line(4) = {6, 7};                // top, up to the stem
Line(5) = {7, 9};                // the stem
Line(6) = {9, 10};
Line(7) = {10, 8};
Circle(8) = {8, 1, 11};          // left cap
Circle(9) = {11, 1, 3};
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 8, 9};
Plane Surface(1) = {1};
Physical Surface("Omega_S") = {1};
Physical Curve("Gamma_D") = {6};
Physical Curve("Gamma_N") = {1, 2, 3, 4, 5, 7, 8, 9};
