#declare A = array[3] { 1, 2, 3 };
#declare B = array[2][2] { { <1,0,0>, <0,1,0> }, { <0,0,1>, <1,1,1> } };
#declare C = array[4];
#for (I, 0, 3) #declare C[I] = A[mod(I, 3)] * 2; #end
#declare S = 0;
#for (I, 0, dimension_size(C, 1) - 1, 1) #declare S = S + C[I]; #end
sphere { B[1][1] * S, dimensions(B) }
#ifdef (C[0]) box { -1, 1 } #end
