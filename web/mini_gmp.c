/* The web build's GMP (cmake/web.cmake): GMP's own mini-gmp, from Debian's gmp source package,
   rationals included. One unit, because mini-mpq.c uses mini-gmp.c's internal macros. */
#include "mini-gmp.c"
#include "mini-mpq.c"
