SetFactory("OpenCASCADE");
Rectangle(1) = {-0.5, -0.5, 0, 1, 1};
Mesh.MeshSizeMax = 0.08; Mesh.MeshSizeMin = 0.08;
out[] = Extrude {0, 0, 2} { Surface{1}; Layers{10}; Recombine; };
Physical Volume("fluid") = {out[1]};
Physical Surface("inlet") = {1};
Physical Surface("outlet") = {out[0]};
Physical Surface("wall") = {out[2], out[3], out[4], out[5]};
Mesh.MshFileVersion = 2.2;
