#!/usr/bin/env python3
"""check.py DIR - the Kubernetes manifests of DIR parse as YAML and say what they should.

kubectl is not needed (nor here): this is a dry parse. Every *.yaml holds Kubernetes objects
with apiVersion, kind and metadata.name; a Job's pods mount the shared claim and restart
Never; an indexed Job (completionMode: Indexed) reads $JOB_COMPLETION_INDEX in its command;
the render's completions equal its WW_SLICES. Exit 0 when all hold, 1 with the reasons.
"""
import glob
import os
import sys

import yaml


def check_job(path, job, fail):
    spec = job.get("spec", {})
    pod = spec.get("template", {}).get("spec", {})
    if pod.get("restartPolicy") not in ("Never", "OnFailure"):
        fail(path, "a Job's pods need restartPolicy Never or OnFailure")
    claims = [v.get("persistentVolumeClaim", {}).get("claimName") for v in pod.get("volumes", [])]
    if "waterworld-farm" not in claims:
        fail(path, "the pods do not mount the shared claim waterworld-farm")
    for c in pod.get("containers", []):
        text = " ".join(c.get("command", []) + c.get("args", []))
        env = {e["name"]: e.get("value") for e in c.get("env", [])}
        if spec.get("completionMode") == "Indexed":
            if "$JOB_COMPLETION_INDEX" not in text:
                fail(path, "an indexed Job's command does not read $JOB_COMPLETION_INDEX")
            if "WW_SLICES" in env and str(spec.get("completions")) != env["WW_SLICES"]:
                fail(path, "completions %s != WW_SLICES %s" % (spec.get("completions"), env["WW_SLICES"]))
        if not any(m.get("mountPath") == "/farm" for m in c.get("volumeMounts", [])):
            fail(path, "container %s does not mount /farm" % c.get("name"))


def main():
    errors = []
    fail = lambda path, why: errors.append("%s: %s" % (path, why))
    files = sorted(glob.glob(os.path.join(sys.argv[1], "*.yaml")))
    kinds = []
    for path in files:
        with open(path) as f:
            docs = [d for d in yaml.safe_load_all(f) if d is not None]
        for d in docs:
            if not all(k in d for k in ("apiVersion", "kind", "metadata")) or "name" not in d["metadata"]:
                fail(path, "an object without apiVersion, kind or metadata.name")
                continue
            kinds.append((d["kind"], d["spec"].get("completionMode", "")))
            if d["kind"] == "Job":
                check_job(path, d, fail)
    if kinds.count(("Job", "Indexed")) < 2 or ("Job", "") not in kinds:
        fail(sys.argv[1], "want two indexed Jobs (render, sweep) and the join Job, got %s" % kinds)
    for e in errors:
        print(e, file=sys.stderr)
    print("%d manifests, %d objects: %s" % (len(files), len(kinds), "ok" if not errors else "FAIL"))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
