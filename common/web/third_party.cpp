// The header-only libraries' implementations, compiled once for the browser build: the desktop
// build links Debian's compiled libstb and libtinyobjloader instead.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
