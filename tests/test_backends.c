/* test_backends.c - what `waterworld backends` advises for each machine, and that the optional
 * OSMesa backend builds where Mesa no longer ships its header (Mesa 25.1 and later).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "test.h"

TEST(backends_advice_fits_the_mesa) {
    /* both open: nothing to say */
    ENSURE(ww_cli_backends_advice(1, "4.5 (Core Profile) Mesa 22.3.6", 1) == NULL);
    /* Mesa 25.1 and later have no OSMesa: EGL alone, nothing to install */
    const char *a = ww_cli_backends_advice(1, "4.5 (Core Profile) Mesa 26.0.1", 0);
    ENSURE_MSG(a && strstr(a, "EGL is the path") && strstr(a, "nothing to install") &&
                   !strstr(a, "libosmesa6"),
               "Mesa 26.0: %s", a ? a : "(none)");
    a = ww_cli_backends_advice(1, "4.5 (Core Profile) Mesa 25.1.0-devel (git-abc)", 0);
    ENSURE_MSG(a && !strstr(a, "libosmesa6"), "Mesa 25.1: %s", a ? a : "(none)");
    /* before 25.1 the package exists: name it, as optional */
    a = ww_cli_backends_advice(1, "4.5 (Core Profile) Mesa 25.0.7", 0);
    ENSURE_MSG(a && strstr(a, "optional") && strstr(a, "libosmesa6"), "Mesa 25.0: %s",
               a ? a : "(none)");
    /* a GPU driver that is not Mesa */
    a = ww_cli_backends_advice(1, "4.6.0 NVIDIA 580.159.04", 0);
    ENSURE_MSG(a && strstr(a, "optional") && !strstr(a, "libosmesa6"), "NVIDIA: %s",
               a ? a : "(none)");
    /* no EGL: name its packages */
    a = ww_cli_backends_advice(0, "", 1);
    ENSURE_MSG(a && strstr(a, "libegl-mesa0"), "OSMesa alone: %s", a ? a : "(none)");
    a = ww_cli_backends_advice(0, "", 0);
    ENSURE_MSG(a && strstr(a, "libegl-mesa0"), "none: %s", a ? a : "(none)");
}

/* backend_osmesa.c declares the OSMesa API it uses itself; compiled as on a machine without
 * GL/osmesa.h (the check against the header off), with the project's warnings */
TEST_PROC(backends_osmesa_builds_without_its_header) {
    REQUIRE_TOOL("cc");
    char log[600];
    snprintf(log, sizeof log, "%s/cc.txt", ww_test_tmpdir("osmesa_build"));
    int rc = ww_test_run("cc -std=c11 -Wall -Wextra -Wpedantic -Werror -Wvla -Wmissing-prototypes "
                         "-Wstrict-prototypes -D_DEFAULT_SOURCE -D_POSIX_C_SOURCE=200809L -Isrc "
                         "-DWW_OSMESA_HEADER_CHECK=0 -fsyntax-only src/gfx/backend_osmesa.c",
                         log, log);
    char *text = ww_test_read_file(log, NULL);
    ENSURE_MSG(rc == 0, "exit %d: %s", rc, text ? text : "");
    free(text);
}

/* `waterworld backends` lists the three kinds and, when one is missing, ends with advice */
TEST_PROC(backends_command_lists_and_advises) {
    REQUIRE_GL();
    char path[600];
    snprintf(path, sizeof path, "%s/out.txt", ww_test_tmpdir("backends_cmd"));
    ENSURE_EQ_INT(ww_test_ww("backends", path, NULL), 0);
    char *out = ww_test_read_file(path, NULL);
    ENSURE(out != NULL);
    if (!out) return;
    ENSURE_MSG(strstr(out, "auto ") && strstr(out, "egl ") && strstr(out, "osmesa "), "%s", out);
    int osmesa_missing = strstr(out, "osmesa  unavailable") != NULL;
    ENSURE_MSG(osmesa_missing == (strstr(out, "advice: ") != NULL), "%s", out);
    free(out);
}
