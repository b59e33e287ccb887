// tinyobjloader's implementation compiled into the fuzz targets and instrumented like the rest,
// so coverage and the sanitizers see inside the OBJ reader too. Its definitions take the place of
// Debian's shared library, which is not instrumented; the header is the one that library is
// built from.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
