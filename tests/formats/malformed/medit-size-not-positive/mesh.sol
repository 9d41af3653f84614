MeshVersionFormatted 2
Dimension 2
SolAtVertices
3
1 1
0.5
0
0.5
End
