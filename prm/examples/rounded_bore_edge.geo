// The hub of prm/examples/rounded_bore_edge.prm drawn in gmsh: a steel
// ring D 50-100 x 50 (z -25..25) with both bore edges rounded, R 3 mm.
// coaxfit reads x as the radius r and y as the axial position z (mm). The
// physical curve "joint" is the straight bore; the fillets, tangent to it,
// are where contact may spread beyond it (coaxfit finds them: circle arcs
// tangent to the joint at its ends).

tangent = 0.04; // at the tangent points: contact spreads ~0.06 mm beyond
fillet  = 0.8;  // where the fillets meet the end faces
middle  = 5;    // at the joint's middle
coarse  = 10;   // elsewhere

Point(1)  = {25, -22, 0, tangent};
Point(2)  = {25,   0, 0, middle};
Point(3)  = {25,  22, 0, tangent};
Point(4)  = {28,  22, 0};          // centre of the fillet
Point(5)  = {28,  25, 0, fillet};
Point(6)  = {50,  25, 0, coarse};
Point(7)  = {50, -25, 0, coarse};
Point(8)  = {28, -25, 0, fillet};
Point(9)  = {28, -22, 0};          // centre of the fillet

Line(1)   = {1, 2};
Line(2)   = {2, 3};
Circle(3) = {3, 4, 5};
Line(4)   = {5, 6};
Line(5)   = {6, 7};
Line(6)   = {7, 8};
Circle(7) = {8, 9, 1};

Curve Loop(1) = {1:7};
Plane Surface(1) = {1};
Recombine Surface{1};

Physical Curve("joint")   = {1, 2};
Physical Curve("outer")   = {5};
Physical Curve("faces")   = {4, 6};
Physical Surface("hub")   = {1};
