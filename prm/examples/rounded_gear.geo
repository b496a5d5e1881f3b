// The hub of prm/examples/gear_on_shaft.prm with its web rounded into the
// boss and into the rim (fillets R 4): boss D 50-80 (z -25..25), web
// D 80-150 (z -6..6), rim D 150-180 (z -15..15).
// coaxfit reads x as the radius r and y as the axial position z (mm).
// The physical curve "joint" is the bore that meets the shaft; the other
// names are faces that loads and reports can refer to.

fine   = 0.35; // at the ends of the joint, where the pressure peaks
middle = 3;    // at the joint's middle
coarse = 5;    // elsewhere
round  = 2;    // on the fillets

Point(1)  = {25, -25, 0, fine};
Point(2)  = {25,   0, 0, middle};
Point(3)  = {25,  25, 0, fine};
Point(4)  = {40,  25, 0, coarse};
Point(5)  = {40,  10, 0, round};
Point(6)  = {44,  10, 0};        // centre
Point(7)  = {44,   6, 0, round};
Point(8)  = {71,   6, 0, round};
Point(9)  = {71,  10, 0};        // centre
Point(10) = {75,  10, 0, round};
Point(11) = {75,  15, 0, coarse};
Point(12) = {90,  15, 0, coarse};
Point(13) = {90, -15, 0, coarse};
Point(14) = {75, -15, 0, coarse};
Point(15) = {75, -10, 0, round};
Point(16) = {71, -10, 0};        // centre
Point(17) = {71,  -6, 0, round};
Point(18) = {44,  -6, 0, round};
Point(19) = {44, -10, 0};        // centre
Point(20) = {40, -10, 0, round};
Point(21) = {40, -25, 0, coarse};

Line(1)   = {1, 2};
Line(2)   = {2, 3};
Line(3)   = {3, 4};
Line(4)   = {4, 5};
Circle(5) = {5, 6, 7};
Line(6)   = {7, 8};
Circle(7) = {8, 9, 10};
Line(8)   = {10, 11};
Line(9)   = {11, 12};
Line(10)  = {12, 13};
Line(11)  = {13, 14};
Line(12)  = {14, 15};
Circle(13) = {15, 16, 17};
Line(14)  = {17, 18};
Circle(15) = {18, 19, 20};
Line(16)  = {20, 21};
Line(17)  = {21, 1};

Curve Loop(1) = {1:17};
Plane Surface(1) = {1};
Recombine Surface{1};

Physical Curve("joint")    = {1, 2};
Physical Curve("rim")      = {10};
Physical Curve("hub_face") = {3, 17};
Physical Surface("hub")    = {1};
