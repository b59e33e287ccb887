# The lessons the browser build makes pages of, in course order (common/web/web.cmake builds
# them; tests/web/CMakeLists.txt checks each against the native lesson).
set(STENCIL_WEB_LESSONS 00-stencil-basics 01-planar-reflection 02-stenciled-mirrors 03-recursive-mirrors
    04-projected-shadows 05-light-blocking 06-coplanar-decals 07-shadow-volumes-invert
    08-shadow-volumes-counting 09-cutout-extrusion 10-soft-shadows 11-halo 12-dissolve 13-depth-complexity
    14-csg 15-robust-zfail 16-fast-robust-shadows)
