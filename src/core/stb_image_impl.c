/* stb_image_impl.c - the one copy of stb_image's decoder in the program (PNG, TGA, JPEG, from
 * memory only), shared by io/png.c (frames and goldens) and scene/assets.c (textures, cubemap
 * faces), which include the header alone. Its compile-time settings are pinned here; callers pin
 * the run-time ones (flip, unpremultiply) before each decode. It compiles clean under our warning
 * flags, so no diagnostic is silenced around it.
 */
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_TGA
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STBI_MAX_DIMENSIONS 32768
#include <stb/stb_image.h>
