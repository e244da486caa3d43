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
- (issue 36) `make web` before `make test` on debian:12 and debian:13, a step that fails the job
  when a browser test (a name with "web" or "live") was skipped there anyway, and `make site-live`
  (the site's live embeds) after `make web`;
- every `uses:` pinned to a version (@...).

Given the Pages workflow too (pages.yml), it checks that it builds the site with the web stages and
publishes it with GitHub Pages' own actions: `make web` before `make site`, `make site-live` (the
embeds render) before the upload, actions/configure-pages,
actions/upload-pages-artifact of build/site, actions/deploy-pages in a job that needs the build, with
pages: write and id-token: write and the github-pages environment, on push to main; every action pinned.

  ci_workflow.py CI_YML [PAGES_YML]              prints every fault; exit 0 when there is none
  ci_workflow.py --self-test CI_YML [PAGES_YML]  breaks a copy of each workflow in each of the ways
                                                 above and exits 0 only when every broken copy is rejected"""
import copy
import re
import sys


def matrix_entries(job):
    return job.get("strategy", {}).get("matrix", {}).get("include") or [{}]


def applies(condition, entry):
    """Whether a step's `if:` holds for one matrix entry. Understands what these workflows write:
    startsWith(matrix.X, 'v'), matrix.X == 'v', matrix.X != 'v' (and no condition); anything else
    counts as not holding, so that the check never credits a step it cannot read."""
    condition = str(condition or "").strip()
    if condition.startswith("${{") and condition.endswith("}}"):
        condition = condition[3:-2].strip()
    if not condition:
        return True
    value = lambda key: str(entry.get(key, ""))
    m = re.fullmatch(r"startsWith\(\s*matrix\.([\w-]+)\s*,\s*'([^']*)'\s*\)", condition)
    if m:
        return value(m[1]).startswith(m[2])
    m = re.fullmatch(r"matrix\.([\w-]+)\s*(==|!=)\s*'([^']*)'", condition)
    if m:
        return (value(m[1]) == m[3]) == (m[2] == "==")
    return False


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


def step_index(job, pattern):
    """The index of the first step of job whose run matches pattern, or None."""
    for i, step in enumerate(job.get("steps", [])):
        if re.search(pattern, str(step.get("run", ""))):
            return i
    return None


def check_web(jobs):
    """make web before make test on Debian 12 and 13, and no browser test skipped there."""
    errors = []
    webbed = set()
    for name, job in jobs.items():
        web, test = step_index(job, r"\bmake web\b"), step_index(job, r"(^|[;&|\s])make test\b")
        if web is None or test is None:
            continue
        if web > test:
            errors.append(f"job {name}: `make web` runs after `make test`, so the browser tests skip")
            continue
        condition = job["steps"][web].get("if", "")
        for entry, (container, runner) in zip(matrix_entries(job), systems(job)):
            if applies(condition, entry):
                webbed.add(container)
        if not any("Skipped" in str(s.get("run", "")) and re.search(r"web", str(s.get("run", "")))
                   for s in job["steps"][test + 1:]):
            errors.append(f"job {name}: no step after `make test` fails when a browser test was skipped")
        live = step_index(job, r"\bmake site-live\b")
        if live is None or live < web or job["steps"][live].get("if", "") != condition:
            errors.append(f"job {name}: no `make site-live` after `make web` on the same systems (the site's live embeds)")
    for wanted in ("debian:12", "debian:13"):
        if wanted not in webbed:
            errors.append(f"no job runs `make web` before `make test` on {wanted}")
    return errors


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
    errors += check_web(jobs)
    return errors + unpinned(jobs)


def unpinned(jobs):
    errors = []
    for name, job in jobs.items():
        for step in job.get("steps", []):
            uses = step.get("uses")
            if uses and "@" not in str(uses):
                errors.append(f"job {name}: `uses: {uses}` is not pinned to a version")
    return errors


def check_pages(workflow):
    """pages.yml: the site with the web stages, published by GitHub Pages' own actions."""
    if not isinstance(workflow, dict):
        return ["the Pages workflow is not a YAML mapping"]
    errors = []
    triggers = workflow.get("on", workflow.get(True))
    push = triggers.get("push") if isinstance(triggers, dict) else None
    if not isinstance(push, dict) or "main" not in (push.get("branches") or []):
        errors.append(f"Pages: triggers {triggers!r}: a push to main must publish")
    jobs = workflow.get("jobs") or {}
    if not isinstance(jobs, dict) or not jobs:
        return errors + ["Pages: no jobs"]

    def using(action):
        return [(n, j, s) for n, j in jobs.items() for s in j.get("steps", []) if str(s.get("uses", "")).startswith(action + "@")]

    builders = [n for n, j in jobs.items() if step_index(j, r"\bmake site\b(?!-)") is not None]
    if not builders:
        errors.append("Pages: no job runs `make site`")
    for name in builders:
        web, site = step_index(jobs[name], r"\bmake web\b"), step_index(jobs[name], r"\bmake site\b(?!-)")
        if web is None or web > site:
            errors.append(f"Pages: job {name} does not run `make web` before `make site`, so the site has no live stages")
        live = step_index(jobs[name], r"\bmake site-live\b")
        upload = next((i for i, s in enumerate(jobs[name].get("steps", []))
                       if str(s.get("uses", "")).startswith("actions/upload-pages-artifact")), None)
        if live is None or live < site or (upload is not None and live > upload):
            errors.append(f"Pages: job {name} does not run `make site-live` between `make site` and the upload")
    if not using("actions/configure-pages"):
        errors.append("Pages: no actions/configure-pages step")
    uploads = using("actions/upload-pages-artifact")
    if not any(str(s.get("with", {}).get("path", "")).rstrip("/") == "build/site" and n in builders for n, _, s in uploads):
        errors.append("Pages: no actions/upload-pages-artifact of build/site in the job that builds it")
    deploys = using("actions/deploy-pages")
    if not deploys:
        errors.append("Pages: no actions/deploy-pages step")
    for name, job, _ in deploys:
        needs = job.get("needs") or []
        needs = [needs] if isinstance(needs, str) else needs
        if not any(b in needs for b in builders):
            errors.append(f"Pages: job {name} deploys without needing the job that builds the site")
        permissions = dict(workflow.get("permissions") or {}, **(job.get("permissions") or {}))
        for scope in ("pages", "id-token"):
            if permissions.get(scope) != "write":
                errors.append(f"Pages: job {name} lacks `{scope}: write` (deploy-pages needs it)")
        environment = job.get("environment")
        if (environment.get("name") if isinstance(environment, dict) else environment) != "github-pages":
            errors.append(f"Pages: job {name} does not deploy to the github-pages environment")
    return errors + [f"Pages: {e}" for e in unpinned(jobs)]


def editor(workflow):
    """edit(label, change): (label, a copy of workflow that change(copy) broke), for the breakages."""
    def edit(label, change):
        broken = copy.deepcopy(workflow)
        change(broken)
        return label, broken
    return edit


def unpin(broken):
    """Every action used without its pinned version."""
    for job in broken["jobs"].values():
        for step in job.get("steps", []):
            if "uses" in step:
                step["uses"] = step["uses"].split("@")[0]


def breakages(workflow):
    """Copies of the workflow, each broken in one way check() must reject."""
    edit = editor(workflow)

    def jobs_running(broken, command):
        return [j for j in broken["jobs"].values() if command in runs(j)]

    def drop_system(broken, system):
        for job in jobs_running(broken, "make test"):
            include = job.get("strategy", {}).get("matrix", {}).get("include", [])
            include[:] = [e for e in include if system not in e.values()]

    def drop_step(broken, command, predicate):
        for job in jobs_running(broken, command):
            job["steps"] = [s for s in job["steps"] if not predicate(s)]

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
        edit("no make web", lambda w: drop_step(w, "make test", lambda s: "make web" in str(s.get("run", "")))),
        edit("make web after make test", web_last),
        edit("no web on debian:13", lambda w: web_only_on(w, "debian-12")),
        edit("no check for skipped browser tests",
             lambda w: drop_step(w, "make test", lambda s: "Skipped" in str(s.get("run", "")))),
        edit("no site-live", lambda w: drop_step(w, "make test", lambda s: "site-live" in str(s.get("run", "")))),
    ]


def web_last(broken):
    for job in broken["jobs"].values():
        steps = job.get("steps", [])
        web = [s for s in steps if "make web" in str(s.get("run", ""))]
        if web:
            job["steps"] = [s for s in steps if s not in web] + web


def web_only_on(broken, system):
    for job in broken["jobs"].values():
        for step in job.get("steps", []):
            if "make web" in str(step.get("run", "")):
                step["if"] = f"matrix.system == '{system}'"


def pages_breakages(workflow):
    """Copies of the Pages workflow, each broken in one way check_pages() must reject."""
    edit = editor(workflow)

    def drop(broken, predicate):
        for job in broken["jobs"].values():
            job["steps"] = [s for s in job.get("steps", []) if not predicate(s)]

    def each_job(broken, change):
        for job in broken["jobs"].values():
            change(job)

    runs_ = lambda word: (lambda s: word in str(s.get("run", "")))
    uses_ = lambda word: (lambda s: word in str(s.get("uses", "")))
    return [
        edit("no make web", lambda w: drop(w, runs_("make web"))),
        edit("no make site", lambda w: drop(w, lambda s: re.search(r"\bmake site\b(?!-)", str(s.get("run", ""))))),
        edit("no make site-live", lambda w: drop(w, runs_("make site-live"))),
        edit("no configure-pages", lambda w: drop(w, uses_("configure-pages"))),
        edit("no upload", lambda w: drop(w, uses_("upload-pages-artifact"))),
        edit("upload of another folder", lambda w: [s["with"].update(path="build") for j in w["jobs"].values()
                                                     for s in j["steps"] if "upload-pages-artifact" in str(s.get("uses", ""))]),
        edit("no deploy-pages", lambda w: drop(w, uses_("deploy-pages"))),
        edit("deploy not after the build", lambda w: each_job(w, lambda j: j.pop("needs", None))),
        edit("no pages: write", lambda w: each_job(w, lambda j: (j.get("permissions") or {}).pop("pages", None))),
        edit("no id-token: write", lambda w: each_job(w, lambda j: (j.get("permissions") or {}).pop("id-token", None))),
        edit("no github-pages environment", lambda w: each_job(w, lambda j: j.pop("environment", None))),
        edit("no push trigger", lambda w: w.get("on", w.get(True)).pop("push")),
        edit("unpinned action", unpin),
    ]


def load(yaml, path):
    try:
        with open(path, encoding="utf-8") as f:
            return yaml.safe_load(f)
    except OSError as error:
        raise SystemExit(f"{path}: cannot read: {error.strerror}")
    except yaml.YAMLError as error:
        raise SystemExit(f"{path}: not valid YAML: {error}")


def main():
    args = sys.argv[1:]
    self_test = bool(args) and args[0] == "--self-test"
    if self_test:
        args = args[1:]
    if len(args) not in (1, 2):
        print(__doc__)
        return 2
    try:
        import yaml
    except ImportError:
        print("python3-yaml is not installed (make test installs it: the Makefile's TEST_PACKAGES)")
        return 1
    try:
        files = [(args[0], load(yaml, args[0]), check, breakages)]
        if len(args) == 2:
            files.append((args[1], load(yaml, args[1]), check_pages, pages_breakages))
    except SystemExit as error:
        print(error)
        return 1
    if self_test:
        total = 0
        for path, workflow, checker, breaker in files:
            errors = checker(workflow)
            if errors:
                print(f"{path}: the workflow itself is rejected, so the self-test proves nothing: " + "; ".join(errors))
                return 1
            missed = [label for label, broken in breaker(workflow) if not checker(broken)]
            for label in missed:
                print(f"self-test: {path} with '{label}' was accepted")
            if missed:
                return 1
            total += len(breaker(workflow))
        print(f"ok: every one of {total} broken copies of {' and '.join(p for p, *_ in files)} is rejected")
        return 0
    errors = [f"{path}: {e}" for path, workflow, checker, _ in files for e in checker(workflow)]
    for error in errors:
        print(error)
    if errors:
        return 1
    print(f"ok: {args[0]} runs make test on debian:12, debian:13 (after make web) and ubuntu-24.04, the fuzz "
          f"build, the trixie check and the Windows check" + (f"; {args[1]} publishes the site with the web stages"
                                                              if len(args) == 2 else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
