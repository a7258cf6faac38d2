/* The web build's PNG writer: the desktop viewer links Debian's libstb for it; here the same
   header from libstb-dev is compiled in (viewer/renderer.cpp includes it for the declarations). */
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
