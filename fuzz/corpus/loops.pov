#declare N = 0;
#while (N < 100)
  #declare N = N + 1;
  #if (mod(N, 10) = 0) box { N, N + 1 } #end
#end
#declare R = seed(42);
#for (I, 10, 0, -2) sphere { <rand(R), rand(R), I>, 0.1 } #end
