#declare X = ((((((((((1)))))))))) + <(((2))), 3, 4>.y;
union { union { union { union { sphere { 0, X } } } } }
