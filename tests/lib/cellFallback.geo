// A fast cell mesh of the tests (tests/badInput/runCorpus.sh,
// tests/indentation/restartInputs.sh, outputLost.sh; no tutorial uses it:
// a tutorial's cell is cellMesh's or none): axisymmetric r-z section of the semi-spheroid
// cell (semi-axes a = D/2, H) with a spheroidal nucleus of volume fraction f
// and the same D/H ratio centred at z = H/2, and a membrane layer between
// the outer ellipse and the ellipse of semi-axes (a - t, H - t) (thickness
// exactly t on the axis and the substrate, within 3 % elsewhere).
// All-quad mesh (subdivision), geometry in um, written in metres.
// gmsh -2 -setnumber D 16.8 -setnumber H 7.9 -setnumber h 0.6 ... cellFallback.geo -o constant/cell.msh
If (!Exists(D)) D = 16.8; EndIf            // cell diameter [um]
If (!Exists(H)) H = 7.9; EndIf             // cell height [um]
If (!Exists(f)) f = 0.3333; EndIf          // nucleus volume fraction
If (!Exists(t)) t = 0.2; EndIf             // membrane thickness [um]
If (!Exists(h)) h = 0.8; EndIf             // bulk element size [um]
If (!Exists(hc)) hc = 0.3; EndIf           // size at the indenter [um]
If (!Exists(nm)) nm = 60; EndIf            // membrane elements along arc
a = D/2;
// nucleus semi-axes: (4/3) pi an^2 bn = f (2/3) pi a^2 H, an/bn = a/(H/2)
bn = H/2*f^(1/3);
an = 2*a/H*bn;
zc = H/2;
Point(1) = {0, 0, 0, h};
Point(2) = {a - t, 0, 0, h};
Point(3) = {a, 0, 0, h};
Point(4) = {0, H - t, 0, hc};
Point(5) = {0, H, 0, hc};
Point(6) = {0, zc, 0, h};
Point(7) = {0, zc - bn, 0, h};
Point(8) = {an, zc, 0, h};
Point(9) = {0, zc + bn, 0, hc};
If (a >= H)
    Ellipse(1) = {3, 1, 3, 5};             // outer surface
    Ellipse(2) = {2, 1, 2, 4};             // membrane/cytoplasm
Else
    Ellipse(1) = {3, 1, 5, 5};
    Ellipse(2) = {2, 1, 4, 4};
EndIf
Ellipse(3) = {7, 6, 8, 8};                 // nucleus, lower
Ellipse(4) = {8, 6, 8, 9};                 // nucleus, upper
Line(5) = {1, 2};                          // substrate, cytoplasm
Line(6) = {2, 3};                          // substrate, membrane
Line(7) = {1, 7};                          // axis pieces
Line(8) = {7, 9};
Line(9) = {9, 4};
Line(10) = {4, 5};
Curve Loop(1) = {3, 4, -8};
Plane Surface(1) = {1};                    // nucleus
Curve Loop(2) = {5, 2, -9, -4, -3, -7};
Plane Surface(2) = {2};                    // cytoplasm
Curve Loop(3) = {6, 1, -10, -2};
Plane Surface(3) = {3};                    // membrane
Transfinite Curve{1, 2} = nm + 1;
Transfinite Curve{6, 10} = 2;
Transfinite Surface{3} = {2, 3, 5, 4};
Recombine Surface{1, 2, 3};
Physical Surface("nucleus") = {1};
Physical Surface("cytoplasm") = {2};
Physical Surface("membrane") = {3};
Physical Curve("fixedBottom") = {5, 6};
Physical Curve("axis") = {7, 8, 9, 10};
Physical Curve("outerSurface") = {1};
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.SubdivisionAlgorithm = 1;
Mesh.ScalingFactor = 1e-6;
Mesh.MshFileVersion = 4.1;
