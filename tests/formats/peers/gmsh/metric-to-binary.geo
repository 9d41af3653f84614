// Re-saves metric-hand-written.msh (hand-written: 4 nodes with sparse tags, a 9-component $NodeData view) as
// gmsh writes it in binary MSH 4.1: the mesh, then the view.
Merge "metric-hand-written.msh";
Mesh.Binary = 1;
PostProcessing.SaveMesh = 1;
Save View[0] "metric-41-bin.msh";
