#declare V = <1, 2, 3>;
#declare W = vnormalize(vcross(V, <0, 1, 0>)) + vrotate(x, <0, 90, 0>) * vlength(V);
#declare F = abs(-2) + min(1, 2, 3) + max(4, 5) + pow(2, 10) + sqrt(16) + exp(1) + log(10) + ln(2)
  + sin(pi) + cos(2 * pi) + atan2(1, 1) + floor(2.5) + ceil(2.5) + int(-2.5) + mod(7, 3) + div(7, 2);
#declare G = (F > 3 ? 1 : 0) & (true | off) & !no;
#declare H = select(-1, 1, 2, 3) + V.x + W.z + <1,2,3,4,5>.t;
#declare S = concat(strupr("abc"), strlwr("DEF"), chr(65), substr("hello", 2, 3), str(pi, -8, 3));
#declare L = strlen(S) + asc("A") + val("2.5");
#switch (L)
  #case (0) #debug "zero\n" #break
  #range (1, 100) #debug "small\n" #break
  #else #debug "big\n"
#end
sphere { W, 1 pigment { color rgbft <1, G, H, 0.1, 0.2> } }
