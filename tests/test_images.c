/* test_images.c - rendered pixels: golden frames (exact on the Mesa that blessed them, close
 * elsewhere), EGL and OSMesa giving the same bytes, and llvmpipe's thread count not mattering.
 * Images by tolerance, simulation by hash: this file never looks at the state.
 */
#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gfx/backend.h"
#include "io/writers.h"
#include "test.h"

static int render(const char *args) {
    char c[2048];
    snprintf(c, sizeof c, "%s render %s --quiet", ww_test_bin(), args);
    return ww_test_run(c, NULL, NULL);
}

TEST_IMAGE(images_golden_minimal) {
    REQUIRE_GL();
    char dir[512], args[1024], actual[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden_minimal"));
    snprintf(args, sizeof args, "scenes/minimal.yaml --frames 1 -o %s", dir);
    ENSURE_EQ_INT(render(args), 0);
    snprintf(actual, sizeof actual, "%s/frame_00000.png", dir);
    ww_test_check_golden("golden/minimal/frame_00000.png", actual);
}

TEST_IMAGE(images_golden_demo_two_frames) {
    REQUIRE_GL();
    char dir[512], args[1024], actual[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden_demo"));
    snprintf(args, sizeof args, "scenes/demo.yaml --size 256x144 --frames 1 -o %s", dir);
    ENSURE_EQ_INT(render(args), 0);
    snprintf(args, sizeof args, "scenes/demo.yaml --size 256x144 --frames 150:151 -o %s", dir);
    ENSURE_EQ_INT(render(args), 0);
    snprintf(actual, sizeof actual, "%s/frame_00000.png", dir);
    ww_test_check_golden("golden/demo/frame_00000.png", actual);
    snprintf(actual, sizeof actual, "%s/frame_00150.png", dir);
    ww_test_check_golden("golden/demo/frame_00150.png", actual);
}

static void same_files(const char *pa, const char *pb) {
    size_t na = 0, nb = 0;
    char *a = ww_test_read_file(pa, &na), *b = ww_test_read_file(pb, &nb);
    ENSURE_MSG(a && b && na == nb && memcmp(a, b, na) == 0, "%s and %s differ", pa, pb);
    free(a);
    free(b);
}

TEST_IMAGE(images_egl_and_osmesa_identical) {
    REQUIRE_GL();
    REQUIRE_BACKEND(WW_BACKEND_EGL);
    REQUIRE_BACKEND(WW_BACKEND_OSMESA);
    char dir[512], args[1024], pa[700], pb[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("backends"));
    snprintf(args, sizeof args, "scenes/demo.yaml --size 256x144 --frames 90:91 --backend egl -o %s/egl", dir);
    ENSURE_EQ_INT(render(args), 0);
    snprintf(args, sizeof args, "scenes/demo.yaml --size 256x144 --frames 90:91 --backend osmesa -o %s/osmesa", dir);
    ENSURE_EQ_INT(render(args), 0);
    snprintf(pa, sizeof pa, "%s/egl/frame_00090.png", dir);
    snprintf(pb, sizeof pb, "%s/osmesa/frame_00090.png", dir);
    same_files(pa, pb);
}

TEST_IMAGE(images_llvmpipe_thread_count_does_not_matter) {
    REQUIRE_GL();
    char dir[512], args[1024], pa[700], pb[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("threads"));
    snprintf(args, sizeof args, "scenes/minimal.yaml --frames 1 -o %s/t1", dir);
    setenv("LP_NUM_THREADS", "1", 1);
    ENSURE_EQ_INT(render(args), 0);
    snprintf(args, sizeof args, "scenes/minimal.yaml --frames 1 -o %s/t4", dir);
    setenv("LP_NUM_THREADS", "4", 1);
    ENSURE_EQ_INT(render(args), 0);
    unsetenv("LP_NUM_THREADS");
    snprintf(pa, sizeof pa, "%s/t1/frame_00000.png", dir);
    snprintf(pb, sizeof pb, "%s/t4/frame_00000.png", dir);
    same_files(pa, pb);
}

/* every feature golden (blessed through EGL) comes out of OSMesa byte for byte: the two
 * backends run one pipeline, so every pass must be identical on both */
TEST_IMAGE(images_feature_goldens_on_osmesa) {
    REQUIRE_GL();
    REQUIRE_BLESSED_RENDERER();
    REQUIRE_BACKEND(WW_BACKEND_OSMESA);
    DIR *d = opendir("scenes/features");
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t len = strlen(e->d_name);
        if (len < 6 || strcmp(e->d_name + len - 5, ".yaml") != 0) continue;
        char scene[600], out[700], actual[800], golden[600];
        snprintf(scene, sizeof scene, "scenes/features/%s", e->d_name);
        snprintf(out, sizeof out, "%s", ww_test_tmpdir("features_osmesa"));
        ENSURE_EQ_INT(ww_test_render(scene, "--backend osmesa", out), 0);
        snprintf(actual, sizeof actual, "%s/frame_00000.png", out);
        snprintf(golden, sizeof golden, "golden/features/%.*s.png", (int)(len - 5), e->d_name);
        ww_test_check_golden(golden, actual);
        n++;
    }
    if (d) closedir(d);
    ENSURE_MSG(n >= 16, "%d feature scenes", n);
}
