/* test_farm.c - renders and sweeps farmed out as job lines (scripts/farm/): through GNU
 * parallel, joined, the same bytes as one process; the Slurm and Kubernetes files parse.
 * The real Slurm cluster is `make farm-test` (scripts/farm/check-slurm.sh), not part of the suite.
 */
#include <stdio.h>
#include <stdlib.h>

#include "test.h"

/* the exit status check-parallel.sh gives when GNU parallel is missing (automake's "skip") */
#define FARM_SKIP_STATUS 77

/* the script's stderr, for a failure's message */
static const char *err_text(const char *path) {
    static char buf[2048];
    char *t = ww_test_read_file(path, NULL);
    snprintf(buf, sizeof buf, "%s", t ? t : "(none)");
    free(t);
    return buf;
}

/* a short scene with its sound track in 3 slices, and a 4-point sweep with thumbnails, each
 * through `parallel`, joined: frames, audio.wav, sweep.jsonl and thumbnails equal to one run's;
 * the render first without slice 1, which join must name and whose command it prints */
TEST_PROC(farm_parallel_matches_one_process) {
    REQUIRE_GL();
    REQUIRE_TOOL("parallel");
    char dir[512], cmd[2048], out[700], err[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("farm_parallel"));
    snprintf(out, sizeof out, "%s/out.txt", dir);
    snprintf(err, sizeof err, "%s/err.txt", dir);
    snprintf(cmd, sizeof cmd, "WW_BIN=%s sh scripts/farm/check-parallel.sh %s/work", ww_test_bin(), dir);
    int rc = ww_test_run(cmd, out, err);
    if (rc == FARM_SKIP_STATUS) SKIP("%s", err_text(err));
    ENSURE_MSG(rc == 0, "check-parallel.sh exit %d: %s", rc, err_text(err));
    ENSURE(ww_test_file_contains(out, "slice 1 missing: join exit 1"));
    ENSURE(ww_test_file_contains(out, "same bytes: 9 frames and audio.wav"));
    ENSURE(ww_test_file_contains(out, "same bytes: sweep.jsonl (4 points), sweep.csv, contact sheet, 4 thumbnails"));
}

/* the Kubernetes manifests are YAML with an indexed Job, the Slurm and parallel scripts are
 * sh that parses */
TEST_PROC(farm_scripts_parse) {
    char dir[512], cmd[1024], err[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("farm_parse"));
    snprintf(err, sizeof err, "%s/err.txt", dir);
    const char *scripts[] = {"lib.sh", "check-parallel.sh", "check-slurm.sh", "check-ssh.sh", "parallel.sh",
                             "slurm/submit.sh", "slurm/render.sbatch", "slurm/sweep.sbatch", "slurm/checkpoints.sbatch",
                             "slurm/join.sbatch"};
    for (size_t i = 0; i < sizeof scripts / sizeof scripts[0]; i++) {
        snprintf(cmd, sizeof cmd, "sh -n scripts/farm/%s", scripts[i]);
        ENSURE_MSG(ww_test_run(cmd, NULL, err) == 0, "%s: %s", cmd, err_text(err));
    }
    if (ww_test_run("python3 -c 'import yaml'", NULL, NULL) != 0)
        SKIP("python3 with its yaml module (Debian: python3-yaml) is not installed");
    ENSURE_MSG(ww_test_run("python3 scripts/farm/k8s/check.py scripts/farm/k8s", NULL, err) == 0,
               "k8s/check.py: %s", err_text(err));
}
