#macro Row(N, R)
  #local I = 0;
  #while (I < N)
    sphere { <I, 0, 0>, R pigment { rgb <I/N, 0.5, 1-I/N> } }
    #local tightneksI = I + 1;
  #end
#end
#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
#declare F = Fact(5);
#if (F = 120) Row(4, 0.3) #else #error "b©d" #end
#ifdef (F) #debug concat("F=", str(F, 0, 0), "\n") #end
#ifndef (G) #declare G = 1; #end
#undef G
