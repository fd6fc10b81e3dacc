#include "colors.inc"
#include "textures.inc"
sphere { 0, 1 pigment { color Red } }
box { -1, 1 texture { Polished_Chrome } translate x * 3 }
