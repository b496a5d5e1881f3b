// The gear wheel of prm/examples/gear_wheel_with_web.prm drawn in gmsh:
// boss D 50-80 (z -25..25), web D 80-140 (z -8..8) rounded into the boss
// and into the rim with fillets R 4, rim D 140-160 (z -25..25).
// coaxfit reads x as the radius r and y as the axial position z (mm).
// In a stack the joints are found where the sections meet (the bore on
// the shaft, the rim's outside in the ring shrunk onto it); the
// neighbours are meshed with this file's nodes on them.

end_size = 0.5; // at the ends of the joints, where the pressure peaks
middle   = 2.5; // at their middles
coarse   = 4;   // elsewhere
round    = 1.5; // on the fillets

Point(1)  = {25, -25, 0, end_size};
Point(2)  = {25,   0, 0, middle};
Point(3)  = {25,  25, 0, end_size};
Point(4)  = {40,  25, 0, coarse};
Point(5)  = {40,  12, 0, round};
Point(6)  = {44,  12, 0};        // centre
Point(7)  = {44,   8, 0, round};
Point(8)  = {66,   8, 0, round};
Point(9)  = {66,  12, 0};        // centre
Point(10) = {70,  12, 0, round};
Point(11) = {70,  25, 0, coarse};
Point(12) = {80,  25, 0, end_size};
Point(13) = {80,   0, 0, middle};
Point(14) = {80, -25, 0, end_size};
Point(15) = {70, -25, 0, coarse};
Point(16) = {70, -12, 0, round};
Point(17) = {66, -12, 0};        // centre
Point(18) = {66,  -8, 0, round};
Point(19) = {44,  -8, 0, round};
Point(20) = {44, -12, 0};        // centre
Point(21) = {40, -12, 0, round};
Point(22) = {40, -25, 0, coarse};

Line(1)    = {1, 2};
Line(2)    = {2, 3};
Line(3)    = {3, 4};
Line(4)    = {4, 5};
Circle(5)  = {5, 6, 7};
Line(6)    = {7, 8};
Circle(7)  = {8, 9, 10};
Line(8)    = {10, 11};
Line(9)    = {11, 12};
Line(10)   = {12, 13};
Line(11)   = {13, 14};
Line(12)   = {14, 15};
Line(13)   = {15, 16};
Circle(14) = {16, 17, 18};
Line(15)   = {18, 19};
Circle(16) = {19, 20, 21};
Line(17)   = {21, 22};
Line(18)   = {22, 1};

Curve Loop(1) = {1:18};
Plane Surface(1) = {1};
Recombine Surface{1};
