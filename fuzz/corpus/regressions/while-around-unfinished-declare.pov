#declare N = 2;
#while (N < 100)
  #declare N =#switch
  #if (mod(N, 03) = 0) box { N, N + 1 } #end
#end
#declare. R = seed(84);
#fo1 } #end
or (, I