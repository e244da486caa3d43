#!/usr/bin/env python3
"""Checks the repository's CI workflow (.github/workflows/ci.yml), as check_workflow.py checks the
students' grade.yml: it parses as YAML (Debian's python3-yaml) and runs what issue 28 asks of CI:

- triggers on push and pull_request;
- `make test` on a debian:12 container, a debian:13 container and the ubuntu-24.04 runner (matrix
  entries resolved), with ctest's summary written to $GITHUB_STEP_SUMMARY and, on failure(), an
  upload of build/tests/out/ (the golden renders and differences);
- a job that runs `make fuzz-build`;
- a job that runs `make distro-check DISTRO=trixie` in a privileged container (mount namespaces);
- a job that runs `make windows-check` (issue 31: the MinGW-w64 cross build and its tests under Wine);
- every `uses:` pinned to a version (@...).

  ci_workflow.py WORKFLOW_YML             prints every fault; exit 0 when there is none
  ci_workflow.py --self-test WORKFLOW_YML  breaks a copy of the workflow in each of the ways above and
                                          exits 0 only when every broken copy is rejected"""
import copy
import re
import sys


def systems(job):
    """(container, runs-on) of each run of a job, its matrix's include entries substituted."""
    entries = job.get("strategy", {}).get("matrix", {}).get("include") or [{}]
    out = []
    for entry in entries:
        def resolve(value):
            if isinstance(value, str):
                return re.sub(r"\$\{\{\s*matrix\.([\w-]+)\s*\}\}", lambda m: str(entry.get(m.group(1), "")), value)
            return value
        container = job.get("container", "")
        if isinstance(container, dict):
            container = container.get("image", "")
        out.append((resolve(container) or "", resolve(job.get("runs-on", ""))))
    return out


def runs(job):
    return "\n".join(str(s.get("run", "")) for s in job.get("steps", []))


def check(workflow):
    errors = []
    if not isinstance(workflow, dict):
        return ["the workflow is not a YAML mapping"]
    triggers = workflow.get("on", workflow.get(True))  # YAML 1.1 reads the key `on` as true
    if not isinstance(triggers, dict) or "push" not in triggers or "pull_request" not in triggers:
        errors.append(f"triggers {triggers!r}: push and pull_request are needed")
    jobs = workflow.get("jobs") or {}
    if not isinstance(jobs, dict) or not jobs:
        return errors + ["no jobs"]
    tested = set()
    for name, job in jobs.items():
        text = runs(job)
        if not re.search(r"(^|[;&|\s])make test\b", text):
            continue
        steps = job.get("steps", [])
        for container, runner in systems(job):
            tested.add(container if container else runner)
        if not any("GITHUB_STEP_SUMMARY" in str(s.get("run", "")) and "tests passed" in str(s.get("run", ""))
                   and s.get("if") == "always()" for s in steps):
            errors.append(f"job {name}: no step (if: always()) writes ctest's summary ('tests passed') to $GITHUB_STEP_SUMMARY")
        uploads = [s for s in steps if str(s.get("uses", "")).startswith("actions/upload-artifact")]
        if not any(s.get("if") == "failure()" and "build/tests/out" in str(s.get("with", {}).get("path", ""))
                   for s in uploads):
            errors.append(f"job {name}: no upload of build/tests/out/ (the golden differences) if: failure()")
    for wanted in ("debian:12", "debian:13", "ubuntu-24.04"):
        if wanted not in tested:
            errors.append(f"no job runs `make test` on {wanted}")
    if not any(re.search(r"\bmake fuzz-build\b", runs(j)) for j in jobs.values()):
        errors.append("no job runs `make fuzz-build`")
    distro = [j for j in jobs.values() if re.search(r"\bmake distro-check DISTRO=trixie\b", runs(j))]
    if not distro:
        errors.append("no job runs `make distro-check DISTRO=trixie`")
    for job in distro:
        container = job.get("container")
        if isinstance(container, dict) and "--privileged" not in str(container.get("options", "")):
            errors.append("the distro-check job's container is not --privileged (mmdebstrap, mount namespaces)")
    if not any(re.search(r"\bmake windows-check\b", runs(j)) for j in jobs.values()):
        errors.append("no job runs `make windows-check`")
    for name, job in jobs.items():
        for step in job.get("steps", []):
            uses = step.get("uses")
            if uses and "@" not in str(uses):
                errors.append(f"job {name}: `uses: {uses}` is not pinned to a version")
    return errors


def breakages(workflow):
    """Copies of the workflow, each broken in one way check() must reject."""
    def edit(label, change):
        broken = copy.deepcopy(workflow)
        change(broken)
        return label, broken

    def jobs_running(broken, command):
        return [j for j in broken["jobs"].values() if command in runs(j)]

    def drop_system(broken, system):
        for job in jobs_running(broken, "make test"):
            include = job.get("strategy", {}).get("matrix", {}).get("include", [])
            include[:] = [e for e in include if system not in e.values()]

    def drop_step(broken, command, predicate):
        for job in jobs_running(broken, command):
            job["steps"] = [s for s in job["steps"] if not predicate(s)]

    def unpin(broken):
        for job in broken["jobs"].values():
            for step in job["steps"]:
                if "uses" in step:
                    step["uses"] = step["uses"].split("@")[0]

    def unprivileged(broken):
        for job in jobs_running(broken, "make distro-check"):
            job["container"]["options"] = ""

    return [
        edit("no debian:13", lambda w: drop_system(w, "debian:13")),
        edit("no debian:12", lambda w: drop_system(w, "debian:12")),
        edit("no ubuntu-24.04 runner", lambda w: drop_system(w, "")),
        edit("no job summary", lambda w: drop_step(w, "make test", lambda s: "GITHUB_STEP_SUMMARY" in str(s.get("run", "")))),
        edit("no golden upload", lambda w: drop_step(w, "make test", lambda s: "upload-artifact" in str(s.get("uses", "")))),
        edit("no fuzz build", lambda w: drop_step(w, "make fuzz-build", lambda s: "make fuzz-build" in str(s.get("run", "")))),
        edit("no distro check", lambda w: drop_step(w, "make distro-check", lambda s: "distro-check" in str(s.get("run", "")))),
        edit("unprivileged distro check", unprivileged),
        edit("no windows check", lambda w: drop_step(w, "make windows-check", lambda s: "windows-check" in str(s.get("run", "")))),
        edit("unpinned action", unpin),
        edit("no pull_request trigger", lambda w: w.get("on", w.get(True)).pop("pull_request")),
    ]


def main():
    args = sys.argv[1:]
    self_test = bool(args) and args[0] == "--self-test"
    if self_test:
        args = args[1:]
    if len(args) != 1:
        print(__doc__)
        return 2
    try:
        import yaml
    except ImportError:
        print("python3-yaml is not installed (make test installs it: the Makefile's TEST_PACKAGES)")
        return 1
    path = args[0]
    try:
        with open(path, encoding="utf-8") as f:
            workflow = yaml.safe_load(f)
    except OSError as error:
        print(f"{path}: cannot read: {error.strerror}")
        return 1
    except yaml.YAMLError as error:
        print(f"{path}: not valid YAML: {error}")
        return 1
    errors = check(workflow)
    if self_test:
        if errors:
            print(f"{path}: the workflow itself is rejected, so the self-test proves nothing: " + "; ".join(errors))
            return 1
        missed = [label for label, broken in breakages(workflow) if not check(broken)]
        for label in missed:
            print(f"self-test: a workflow with '{label}' was accepted")
        if missed:
            return 1
        print(f"ok: every one of {len(breakages(workflow))} broken copies of {path} is rejected")
        return 0
    for error in errors:
        print(f"{path}: {error}")
    if errors:
        return 1
    print(f"ok: {path} runs make test on debian:12, debian:13 and ubuntu-24.04, the fuzz build, the trixie check and the Windows check")
    return 0


if __name__ == "__main__":
    sys.exit(main())
