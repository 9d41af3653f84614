MeshVersionFormatted 2
Dimension 2
SolAtVertices
2
1 1
0.5
0.5
End
