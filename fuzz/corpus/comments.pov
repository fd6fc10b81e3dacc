/* nested /* block */ comment */ // line comment
# declare  A = 1; #version 3.6;
#declare S = "tab\tquote\" backslash\\ path\d";
#if (version < 3.7) #declare B = A; #elseif (A) #declare B = 2; #else #declare B = 3; #end
#declare M = colour_map { [0 colour rgb 1] [1 colour rgb 0] }
