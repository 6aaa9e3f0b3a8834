// Turek & Hron's elastic flag (2006): (0.2489, 0.6) x (0.19, 0.21), its left end the arc
// of the cylinder of centre (0.2, 0.2) and radius 0.05 it is attached to (Gamma_D); the
// rest free (Gamma_N). fsicontact defines h (structure.h) before the first line.
r = 0.05;
xa = 0.2 + Sqrt(r * r - 0.01 * 0.01);   // 0.248989...: where the flag's sides meet the circle
Point(1) = {0.2, 0.2, 0, h};            // the cylinder's centre
Point(2) = {xa, 0.19, 0, h};
Point(3) = {0.6, 0.19, 0, h};
Point(4) = {0.6, 0.21, 0, h};
Point(5) = {xa, 0.21, 0, h};
Line(1) = {2, 3};
Line(2) = {3, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("Omega_S") = {1};
Physical Curve("Gamma_D") = {4};
Physical Curve("Gamma_N") = {1, 2, 3};
