#declare f_a = function(x, y, z) { x*x + y*y + z*z - 1 }
#declare f_b = function { f_a(x, y, z) * 2 + sin(x) }
#declare P = f_b(1, 2, 3);
sphere { 0, P pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } }
