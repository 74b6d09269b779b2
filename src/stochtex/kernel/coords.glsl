// The GLSL side of kernel/coords.h: texture coordinates are float on the
// GPU. The one kernel file that is GLSL only (C++ never includes it; the
// assembler puts it before the files whose headers include coords.h).
#define coord float
#define coord2 vec2
#define STOCHTEX_HOST_TYPE(T)
