# Two commands: `make run` and `make test`. Both install what is missing (Debian 12 packages through
# apt-get, as root or with sudo), configure with CMake and build before doing their job.
PRESET   ?= debug
BUILD    := build
BIN      := $(BUILD)/bin
OUT      := out
STAGES    = $(shell cat $(BUILD)/stages.txt 2>/dev/null)
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)

# Debian packages the build and `make run` need (the same names on Debian 12, Debian 13 and Ubuntu 22.04
# and 24.04). zlib1g-dev: OpenEXR 2.5's CMake package (Ubuntu 22.04) looks for zlib without depending on it.
PACKAGES := cmake ninja-build g++ pkg-config python3 libglfw3-dev libglm-dev libegl-dev libegl1-mesa-dev \
            libgl1-mesa-dri libosmesa6-dev libopenexr-dev zlib1g-dev libstb-dev libcli11-dev libtinygltf-dev \
            nlohmann-json3-dev libimgui-dev
# What `make test` needs on top: every program a test runs (time: tests/reliability/measure.sh runs
# /usr/bin/time; git: the platform tests package a checkout; bubblewrap: the grader's sandbox; xvfb +
# xauth: the window tests; python3-jsonschema: the dev container's schema test; nodejs: the platform
# tests run GitHub Classroom's released grading reporter, tests/fixtures/classroom-reporter;
# glslang-tools: glslangValidator checks the GLSL ES translation of every shader; default-jre-headless
# and maven: the Java that runs JPlag for the similarity tests and the client that fetches its jars; emscripten: the
# browser build that the web tests load in Chromium; the site's tools and fonts) and Catch2. `make
# run` installs none of them.
# Chromium is the package chromium on Debian 12 and 13, chromium-browser on Ubuntu (24.04: a wrapper
# that installs the snap); the site's CMake finds either program. Firefox ESR (the web stages' second
# engine, under Xvfb) is firefox-esr on Debian; Ubuntu has no such package, and that test says it skips.
BROWSER_PACKAGE := $(shell . /etc/os-release 2>/dev/null; [ "$$ID" = ubuntu ] && echo chromium-browser || echo chromium)
FIREFOX_PACKAGE := $(shell . /etc/os-release 2>/dev/null; [ "$$ID" = ubuntu ] || echo firefox-esr)
TEST_PACKAGES := catch2 xvfb xauth time git bubblewrap python3-yaml python3-jsonschema nodejs glslang-tools emscripten \
                 default-jre-headless maven jekyll ruby-html-proofer $(BROWSER_PACKAGE) $(FIREFOX_PACKAGE) libjs-katex fonts-katex libjs-codemirror \
                 python3-pygments fonts-dejavu-core webp
SUDO := $(shell [ "$$(id -u)" -eq 0 ] || echo sudo)

.PHONY: all deps configure build run test bless clean help

all: build

help:
	@echo "make run    open the final stage in a window, or render every stage headless into $(OUT)/"
	@echo "make test   build and run every test (ctest)"
	@echo "make build  install what is missing, configure ($(PRESET) preset) and build into $(BUILD)/ (also: make, make all)"
	@echo "make deps   install the Debian packages the build needs (apt-get, as root or with sudo)"
	@echo "make configure  configure with CMake into $(BUILD)/ (once)"
	@echo "make bless  re-record the golden images on purpose (STAGES=\"name ...\" for some)"
	@echo "make clean  remove $(BUILD)/, build-release/, build-web/, build-web-release/ and $(OUT)/"
	@echo "make views  render every view (--view) of every stage into $(OUT)/views/, with each view's line in views.txt"
	@echo "make web   build every stage for the browser (WebAssembly, WebGL 2) into $(OUT)/web/<stage>/ (STAGE=name for one; WEB_PRESET=web-release: -O3)"
	@echo "make web-serve  serve $(OUT)/web on http://127.0.0.1:$(WEB_PORT)/ (WEB_PORT=N)"
	@echo "make site   build the documentation site into $(BUILD)/site/"
	@echo "make site-deps  install the site tests' npm tools (axe-core, pinned) into $(BUILD)/site-axe/"
	@echo "make site-audit  Lighthouse (mobile) on the tutorial page: accessibility 100, performance, LCP and bytes printed"
	@echo "make site-live  check the site's live embeds of the web stages (make web first) in headless Chromium and Firefox ESR"
	@echo "make web-agreement  the page's check (Module.t10Check) against t10-grade on every shader-only mistake of the grader's batches and of make grade-sweep (WEB_RENDERER=swiftshader: no GPU)"
	@echo "make site-serve  serve $(BUILD)/site on http://127.0.0.1:4000/ (SITE_PORT=N), rebuilding it only when stale"
	@echo "make test-asan  build and run every test with ASan and UBSan (build-asan/)"
	@echo "make fuzz-build  build the libFuzzer targets (tga, exr, cli, glsl_es, gltf; clang, ASan, UBSan) into $(BUILD)/fuzz/"
	@echo "make fuzz   run every fuzz target FUZZ_SECONDS each (default 60; FUZZ_TARGETS=\"gltf ...\" for some)"
	@echo "make bench  time the tutorial's chain against the usual alternatives (release build, $(OUT)/bench/)"
	@echo "make bench-passes  exercise 39: post-process GPU time and halo radius for 0-10 blur passes (release build)"
	@echo "make bench-gltf  time loading a generated one-million-triangle glTF scene (release build)"
	@echo "make grade PART=1|2|3 SUBMISSIONS=\"dir ...\"  grade students' stages into $(REPORT)/ (REPORT=, GRADE_JOBS=, SIMILARITY=1)"
	@echo "make bench-grader  grade the grader's test batches with a fresh cache: submissions per minute, CPU s and peak memory each"
	@echo "make grade-sweep  every fitted constant of the grader's mistake catalogue across its fit's range: named, measured within 10 %"
	@echo "make grade-jobs-check  a fork bomb graded beside honest submissions (--jobs 2) by a non-root grader, 20 rounds: none starved"
	@echo "make grade-deps  install FLIP (pinned, from PyPI) into $(GRADE_VENV)/ for the grader"
	@echo "make similarity-deps  install Java (Debian) and JPlag (pinned jars, from Maven Central) into $(SIMILARITY_ENGINE)/"
	@echo "make bench-similarity  compare 900 generated Part 3 submissions with JPlag: wall and CPU time, peak memory"
	@echo "make similarity PART=N SUBMISSIONS=\"dir ...\"|SUBMISSIONS_DIR=folder  pairs of students to review (JPlag, the handed-out code excluded) into $(REPORT)/"
	@echo "make grader  build only what grading needs (the grader, the reference stages, FLIP): for grading machines"
	@echo "make grader-packages  print the packages make grader installs (grader/platforms/install_grader.sh checks them)"
	@echo "make gradescope PART=1|2|3  package a Gradescope autograder into $(OUT)/gradescope/partN/autograder.zip"
	@echo "make prairielearn PART=1|2|3  write a PrairieLearn external grader into $(OUT)/prairielearn/partN/"
	@echo "make student PART=1|2|3  start your own version of a part in $(STUDENT_DIR)/partN/ (never overwrites)"
	@echo "make check PART=1|2|3 [DIR=folder] [ISOLATION=none]  build your part, grade it, say what to fix first (exit 0 only at 100)"
	@echo "make run STAGE=student_partN  run your part (window, or headless into $(OUT)/); any stage name works"
	@echo "make distro-check DISTRO=bookworm|trixie [MODES=\"root user\"] [TARGETS=\"run test\"]  make run and make test (or TARGETS) in a fresh Debian root (mmdebstrap, $(BUILD)/distro-check/)"
	@echo "make devcontainer-check  build the dev container's image in a fresh Debian 12 root and prove its desktop, GL, make run, noVNC and make check ($(BUILD)/devcontainer-check/)"
	@echo "make devcontainer-packages  print the Debian packages the dev container's image installs (.devcontainer/Dockerfile)"
	@echo "make windows-check  cross-build for Windows (MinGW-w64) and run the goldens, unit and GL tests under Wine ($(BUILD)/windows/)"
	@echo "make help   this list"

deps:
	@missing=$$(for p in $(PACKAGES); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	    echo "Installing Debian packages:" $$missing; \
	    $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	fi

# The tests are configured in only when Catch2 is installed (`make test` installs it), so that `make run`
# needs none of the test packages; a build configured without them gains them when they arrive.
TESTS_ON = $(shell dpkg-query -W -f='$${Status}' catch2 2>/dev/null | grep -q 'ok installed' && echo ON || echo OFF)
# CONFIGURE_FLAGS: more -D settings for the first configure (make grader leaves extras/ out); any other
# target given a build that make grader configured puts extras/ back.
CONFIGURE_FLAGS :=
configure: deps
	@if [ ! -f $(BUILD)/build.ninja ]; then cmake --preset $(PRESET) -DT10_BUILD_TESTS=$(TESTS_ON) $(CONFIGURE_FLAGS); \
	elif [ "$(TESTS_ON)" = ON ] && grep -qx 'T10_BUILD_TESTS:BOOL=OFF' $(BUILD)/CMakeCache.txt; then \
	    echo "Catch2 is installed now: configuring $(BUILD)/ with the tests"; cmake $(BUILD) -DT10_BUILD_TESTS=ON; fi
	@if [ -z "$(CONFIGURE_FLAGS)" ] && grep -qx 'T10_BUILD_EXTRAS:BOOL=OFF' $(BUILD)/CMakeCache.txt; then \
	    echo "configuring $(BUILD)/ with extras/ (make grader left it out)"; cmake $(BUILD) -DT10_BUILD_EXTRAS=ON; fi

build: configure
	cmake --build $(BUILD) -j $(JOBS)

run: build
	@if [ -n "$(STAGE)" ]; then \
	    $(MAKE) --no-print-directory run-stage; \
	elif [ -n "$$DISPLAY$$WAYLAND_DISPLAY" ]; then \
	    last=$$(tail -n 1 $(BUILD)/stages.txt); \
	    echo "Opening $$last (Esc quits; WASD moves, right mouse button looks, scroll zooms)"; \
	    $(BIN)/$$last; \
	else \
	    mkdir -p $(OUT); \
	    echo "No display: rendering every stage headless into $(OUT)/"; \
	    for stage in $(STAGES); do \
	        $(BIN)/$$stage --headless --frames 1 --output $(OUT)/$$stage.png >/dev/null || exit 1; \
	        echo "  $(OUT)/$$stage.png"; \
	    done; \
	fi

# make test installs what the build needs first (with Catch2, which turns the tests on, and python3-venv
# for FLIP's venv); then, while the C++ builds, apt-get installs what only the tests run (TEST_PACKAGES,
# its output in $(BUILD)/test-packages.log) and pip makes FLIP's venv, both mostly waiting on the
# network and dpkg; as soon as the packages are in, `make web` builds the browser pages beside the
# native build (emscripten, into $(OUT)/web; its output in $(BUILD)/web.log) for ctest's web tests
# (tests/web/); then CMake configures again, finding the programs installed meanwhile (xvfb-run,
# jekyll, chromium, firefox-esr), and ctest runs every test. The tests' llvmpipe skips LLVM's
# optimisation passes and compiles 128-bit vectors (GALLIVM_PERF=nopt LP_NATIVE_VECTOR_WIDTH=128, as
# the grader's renders do): the frames are bit-identical (the test "llvmpipe: ... the same bits" checks
# it) and the suite's small renders spend more CPU compiling shaders than drawing them (the vectors:
# ctest 163 s, not 168).
# Java and Maven before the rest: grade-deps-or-skip fetches JPlag's jars with mvn beside the build, while the
# other test packages are still being installed.
test: PACKAGES += catch2 python3-venv default-jre-headless maven
AXE_WARNING := warning: axe-core could not be installed from npm: the site's accessibility tests will fail and say so
test: deps
	@# axe-core's npm ci runs beside the build below; first, alone, only where npm itself must be installed
	@# (apt-get then, which must not run beside the test packages' apt-get).
	@command -v npm >/dev/null || $(MAKE) --no-print-directory site-deps || echo "$(AXE_WARNING)"
	@missing=$$(for p in $(TEST_PACKAGES); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || printf '%s ' $$p; done); \
	if [ -n "$$missing" ]; then \
	    [ -z "$(SUDO)" ] || $(SUDO) true || exit 1; \
	    mkdir -p $(BUILD); echo "Installing Debian packages while building (log: $(BUILD)/test-packages.log):" $$missing; \
	    $(MAKE) --no-print-directory deps PACKAGES="$$missing" >$(BUILD)/test-packages.log 2>&1 & packages=$$!; \
	fi; \
	$(MAKE) --no-print-directory grade-deps-or-skip & venv=$$!; \
	{ $(MAKE) --no-print-directory site-deps || echo "$(AXE_WARNING)"; } & axe=$$!; \
	mkdir -p $(BUILD); \
	( if [ -n "$$missing" ]; then while kill -0 $$packages 2>/dev/null; do sleep 2; done; fi; \
	  if command -v emcc >/dev/null; then $(MAKE) --no-print-directory web >$(BUILD)/web.log 2>&1; \
	  else echo "emcc is not installed: no web build (the web tests report themselves skipped)" >$(BUILD)/web.log; fi ) & web=$$!; \
	$(MAKE) --no-print-directory build; built=$$?; wait $$venv; wait $$axe; \
	if [ -n "$$missing" ] && ! wait $$packages; then \
	    tail -n 20 $(BUILD)/test-packages.log; echo "make test: installing $$missing failed (log: $(BUILD)/test-packages.log)"; exit 1; \
	fi; \
	[ $$built -eq 0 ] || exit $$built; \
	if [ -n "$$missing" ]; then cmake $(BUILD) >/dev/null && cmake --build $(BUILD) -j $(JOBS); fi; \
	wait $$web || { tail -n 30 $(BUILD)/web.log; echo "make test: make web failed (log: $(BUILD)/web.log)"; exit 1; }; \
	grep -h '^make web: built\|^emcc is not' $(BUILD)/web.log || true
	@# -LE audit: the tests make site-audit runs (site/CMakeLists.txt 3c), which took make test past 5 minutes.
	cd $(BUILD) && GALLIVM_PERF=nopt LP_NATIVE_VECTOR_WIDTH=128 ctest --output-on-failure --no-tests=error -j $(JOBS) -LE audit

bless: build
	tests/golden/bless.sh $(BIN) $(if $(filter command line,$(origin STAGES)),$(STAGES),$(shell cat $(BUILD)/golden_stages.txt))

clean:
	rm -rf $(BUILD) build-release build-web build-web-release $(OUT)

# Exercise 39 measured: post-process GPU time and halo radius for 0-10 blur passes at 1280x720
# (extras/), timed in a release build (build-release/, the CMake preset of that name): debug code
# would time the driver's checks, not the passes.
.PHONY: bench-passes
# gnuplot draws the plot; only this target needs it.
bench-passes: PACKAGES += gnuplot-nox
bench-passes: deps
	@[ -f build-release/build.ninja ] || cmake --preset release -DT10_BUILD_TESTS=$(TESTS_ON)
	cmake --build build-release -j $(JOBS) --target extras make_test_images halo_radius
	tools/bench_passes/bench_passes.sh build-release/bin $(OUT) 10 5 1280x720 3

# The browser build (issue 36): every stage, or STAGE=name (a student's folder too: student_partN),
# compiled by Debian's emscripten to WebAssembly + WebGL 2 into $(OUT)/web/<stage>/ (index.html and its
# .js, .wasm and .data), in build-web/ (the CMake preset `web`, -O1; cmake/T10Web.cmake), or with
# WEB_PRESET=web-release in build-web-release/ at -O3 (what the published site uses: smaller pages, a
# longer build). make web-serve serves $(OUT)/web on http://127.0.0.1:$(WEB_PORT)/ (loopback only).
# NODE_PATH: Debian's emscripten runs its JavaScript tools with the system's Node, which finds their
# modules (acorn) only there.
WEB_PRESET ?= web
WEB_BUILD := build-$(WEB_PRESET)
WEB_PORT  ?= 8000
WEB_ENV   := NODE_PATH=/usr/share/nodejs
.PHONY: web web-serve
web: PACKAGES += emscripten libjs-codemirror
web: deps
	@case "$(WEB_PRESET)" in web|web-release) ;; \
	 *) echo "make web: WEB_PRESET=$(WEB_PRESET) is not a web preset (web: -O1, the default; web-release: -O3)"; exit 2;; esac
	@[ -f $(WEB_BUILD)/build.ninja ] || $(WEB_ENV) emcmake cmake --preset $(WEB_PRESET) -DT10_WEB_OUTPUT_DIR=$(CURDIR)/$(OUT)/web
	@start=$$(date +%s); \
	$(WEB_ENV) cmake --build $(WEB_BUILD) -j $(JOBS) $(if $(STAGE),--target $(STAGE)) || exit 1; \
	echo "make web: built in $$(( $$(date +%s) - start )) s; each page's download (gzip as a server may send it):"; \
	for stage in $(or $(STAGE),$$(cat $(WEB_BUILD)/stages.txt)); do \
	    dir=$(OUT)/web/$$stage; \
	    files="$$dir/index.html $$dir/$$stage.js $$dir/$$stage.wasm $$dir/$$stage.data"; \
	    bytes=$$(cat $$files | wc -c); gz=$$(cat $$files | gzip -6 | wc -c); \
	    printf '  %-28s %5d KiB (gzip %5d KiB)  %s/index.html\n' $$stage $$((bytes / 1024)) $$((gz / 1024)) $$dir; \
	done

web-serve:
	@[ -d $(OUT)/web ] || { echo "make web-serve: $(OUT)/web/ does not exist: run make web first"; exit 2; }
	@echo "Serving $(OUT)/web on http://127.0.0.1:$(WEB_PORT)/ (e.g. /tutorial10_part3_gaussian/; Ctrl-C stops)"
	@PYTHONPATH=$(CURDIR)/tools exec python3 -m web.web_page --serve $(OUT)/web --port $(WEB_PORT)

# The documentation site (site/): built by Debian's jekyll into build/site/; site-serve serves it on
# http://127.0.0.1:$(SITE_PORT)/ (loopback only; Ctrl-C stops it).
.PHONY: site site-serve
# make site installs the site's own tools (a build configured before they were installed looks again);
# chromium measures the web stages' first frames when make web has built them ($(OUT)/web/).
SITE_PACKAGES := jekyll ruby-html-proofer $(BROWSER_PACKAGE) libjs-katex fonts-katex libjs-codemirror python3-pygments fonts-dejavu-core webp
site site-serve: PACKAGES += $(SITE_PACKAGES)
site: configure
	@! grep -Eq '^T10_(JEKYLL|CHROMIUM|CWEBP):FILEPATH=.*NOTFOUND' $(BUILD)/CMakeCache.txt || cmake $(BUILD) >/dev/null
	cmake --build $(BUILD) --target site

# The site's tools that Debian lacks, pinned from the npm registry into $(BUILD)/ (npm ci: the versions and
# integrity hashes of the lock file): axe-core (site/tests/axe/) for the accessibility test of make test.
# npm is Debian's package where no npm is on PATH (NodeSource's nodejs carries its own).
SITE_AXE := $(BUILD)/site-axe
.PHONY: site-deps
site-deps:
	@command -v npm >/dev/null || $(MAKE) --no-print-directory deps PACKAGES=npm
	@cmp -s site/tests/axe/package-lock.json $(SITE_AXE)/package-lock.json && [ -f $(SITE_AXE)/node_modules/axe-core/axe.min.js ] || { \
	    rm -rf $(SITE_AXE) && mkdir -p $(SITE_AXE) && cp site/tests/axe/package.json site/tests/axe/package-lock.json $(SITE_AXE)/ && \
	    npm ci --prefix $(SITE_AXE) --ignore-scripts --no-audit --no-fund --loglevel=error >/dev/null && echo "axe-core installed into $(SITE_AXE)"; }

# make site-audit: the site's tests labelled audit (axe-core on every page at both widths in both schemes, the
# keyboard test of every embed with axe-core while they run: site/CMakeLists.txt 3c), then Lighthouse (pinned
# 12.x, site/tests/lighthouse/; 13 needs Node 22) on the tutorial page with its mobile preset: accessibility
# 100 asserted, performance, LCP and bytes printed (site/tests/lighthouse_audit.py). About two minutes and
# 185 MB of node_modules, so not in make test; .ci/run runs it (after make web, so that the embeds run).
SITE_LIGHTHOUSE := $(BUILD)/site-lighthouse
.PHONY: site-audit
site-audit: site site-deps
	cd $(BUILD) && ctest --output-on-failure --no-tests=error -L audit
	@command -v npm >/dev/null || $(MAKE) --no-print-directory deps PACKAGES=npm
	@cmp -s site/tests/lighthouse/package-lock.json $(SITE_LIGHTHOUSE)/package-lock.json && [ -x $(SITE_LIGHTHOUSE)/node_modules/.bin/lighthouse ] || { \
	    rm -rf $(SITE_LIGHTHOUSE) && mkdir -p $(SITE_LIGHTHOUSE) && cp site/tests/lighthouse/package.json site/tests/lighthouse/package-lock.json $(SITE_LIGHTHOUSE)/ && \
	    npm ci --prefix $(SITE_LIGHTHOUSE) --ignore-scripts --no-audit --no-fund --loglevel=error >/dev/null && echo "Lighthouse installed into $(SITE_LIGHTHOUSE)"; }
	PYTHONPATH=$(CURDIR)/tools python3 site/tests/lighthouse_audit.py --site $(BUILD)/site --page tutorial10.html --chromium $$(command -v chromium || command -v chromium-browser) \
	    --lighthouse $(SITE_LIGHTHOUSE)/node_modules/.bin/lighthouse --out $(BUILD)/site-tests/lighthouse

# The site's live embeds in headless Chromium (site/tests/live_test.py), after building the site with the
# web stages: every stage's embed renders, the exercises' controls change the frame and back, without
# WebGL the pictures stay; screenshots in $(BUILD)/site-tests/live/. About two minutes on two cores, so
# not in make test; CI runs it after make web. Without $(OUT)/web it says SKIPPED and fails. The same
# embeds in Firefox ESR under Xvfb first (site/tests/live_firefox_test.py, about 30 s).
.PHONY: site-live
site-live: PACKAGES += $(FIREFOX_PACKAGE) xvfb
site-live: site
	@! grep -Eq '^T10_(FIREFOX|XVFB):FILEPATH=.*NOTFOUND' $(BUILD)/CMakeCache.txt || cmake $(BUILD) >/dev/null
	cmake --build $(BUILD) --target site-live

# site-serve rebuilds the site only when something it is made from (site/, the programs in $(BIN)/)
# is newer than its index.html, then execs the server, so that stopping make stops the server too.
site-serve: configure
	@index=$(BUILD)/site/index.html; \
	if [ ! -f $$index ] || [ -n "$$(find site $(BIN) $(OUT)/web -newer $$index -print -quit 2>/dev/null)" ]; then \
	    cmake --build $(BUILD) --target site || exit 1; \
	else echo "$(BUILD)/site is up to date"; fi; \
	port=$(or $(SITE_PORT),4000); echo "Serving $(BUILD)/site on http://127.0.0.1:$$port/ (Ctrl-C stops)"; \
	exec python3 -m http.server --bind 127.0.0.1 --directory $(BUILD)/site $$port

# Fuzzing (fuzz/): every libFuzzer target (tga, exr, cli, glsl_es, gltf) built with clang, ASan and UBSan into
# $(BUILD)/fuzz/, each run for FUZZ_SECONDS (default 60); FUZZ_TARGETS="tga gltf" picks some. Not part
# of `make test`.
.PHONY: fuzz fuzz-build
FUZZ_SECONDS ?= 60
# clang's runtime (libFuzzer and the sanitizers) is packaged per clang major version: libclang-rt-14-dev
# on Debian 12, -19-dev on Debian 13, -18-dev on Ubuntu 24.04; the name is taken from the clang installed.
fuzz-build: PACKAGES += clang
fuzz-build: deps
	@major=$$(clang --version | sed -n 's/.*clang version \([0-9][0-9]*\)\..*/\1/p' | head -n 1); \
	[ -n "$$major" ] || { echo "make fuzz-build: cannot read clang's version from clang --version"; exit 1; }; \
	$(MAKE) --no-print-directory deps PACKAGES="libclang-rt-$$major-dev"
	@[ -f $(BUILD)/fuzz/build.ninja ] || CC=clang CXX=clang++ cmake -S fuzz -B $(BUILD)/fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
	cmake --build $(BUILD)/fuzz -j $(JOBS)

fuzz: fuzz-build
	fuzz/run.sh $(BUILD)/fuzz $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# The whole suite built with AddressSanitizer and UndefinedBehaviorSanitizer (the asan preset, in
# build-asan/). Mesa's own leaks are suppressed by library (tests/sanitizers/lsan.supp); a test
# proves a leak in project code still fails. Not part of `make test`.
.PHONY: test-asan
test-asan: PACKAGES += $(TEST_PACKAGES)
test-asan: deps
	@[ -f build-asan/build.ninja ] || cmake --preset asan
	@# The web stages as make test builds them (into $(OUT)/web, beside this build; log in build-asan/web.log):
	@# the web tests and the site's tests of the live embeds (keyboard, weight) need them. Without them
	@# CI's fresh clone failed here, since test-asan runs before anything else has made $(OUT)/web.
	@mkdir -p build-asan; \
	( if command -v emcc >/dev/null; then $(MAKE) --no-print-directory web >build-asan/web.log 2>&1; \
	  else echo "emcc is not installed: no web build (the web tests report themselves skipped)" >build-asan/web.log; fi ) & web=$$!; \
	cmake --build build-asan -j $(JOBS); built=$$?; \
	wait $$web || { tail -n 30 build-asan/web.log; echo "make test-asan: make web failed (log: build-asan/web.log)"; exit 1; }; \
	[ $$built -eq 0 ] || exit $$built; \
	grep -h '^make web: built\|^emcc is not' build-asan/web.log || true
	@# The grader's tests run here too: FLIP into this build's own venv and JPlag beside it (else they skip, saying why), made
	@# with Debian's interpreter where there is one, which every user may run: the as-user fork-bomb test
	@# skips with a venv of a Python under a 0700 home (pyenv's under /root), and this suite skips none.
	@$(MAKE) --no-print-directory grade-deps-or-skip GRADE_VENV=build-asan/grade-venv \
	    GRADE_PYTHON=$(firstword $(wildcard /usr/bin/python3) python3) SIMILARITY_ENGINE=build-asan/jplag
	@$(MAKE) --no-print-directory site-deps SITE_AXE=build-asan/site-axe || echo "warning: axe-core could not be installed from npm: the site's accessibility tests will fail and say so"
	cd build-asan && GALLIVM_PERF=nopt LP_NATIVE_VECTOR_WIDTH=128 ctest --output-on-failure --no-tests=error -j $(JOBS)

# `make bench` (tools/bench/): the tutorial's chain against LearnOpenGL-style bloom, a 13-tap chain
# and a key-once final pass, and the key three ways with its error, at 320x180 .. 3840x2160 in a
# release build (build-release/). Prints the tables; writes CSV, report.txt and bench.png into
# $(OUT)/bench/. BENCH_ARGS passes options (e.g. BENCH_ARGS="--sizes 640x360,1280x720 --repeats 3").
.PHONY: bench
bench: PACKAGES += gnuplot-nox catch2
bench: deps
	@[ -f build-release/build.ninja ] || cmake --preset release
	cmake --build build-release -j $(JOBS) --target t10-bench
	build-release/bin/t10-bench --out $(OUT)/bench $(BENCH_ARGS)
	gnuplot -e "dir='$(OUT)/bench'" tools/bench/plot.gp
	@echo "wrote $(OUT)/bench/bench.png"

# The glTF loader's speed: a generated scene of about one million triangles loaded by a release build
# (tools/bench_gltf_load; not a test). The loader must stay under 2 s on the 2-core CI machine.
.PHONY: bench-gltf
bench-gltf: deps
	@[ -f build-release/build.ninja ] || cmake --preset release -DT10_BUILD_TESTS=$(TESTS_ON)
	cmake --build build-release -j $(JOBS) --target make_gltf_fixtures bench_gltf_load
	build-release/bin/make_gltf_fixtures --big 1000000 build-release/bench/million.glb
	build-release/bin/bench_gltf_load build-release/bench/million.glb 5

# Every view of every stage (--view), one frame each, into $(OUT)/views/<stage>/<view>.png; the views
# a stage lacks are skipped (the program refuses them with exit code 2). Each view's one-line text (Ya,
# dg, counts: what the program prints as "view NAME: ...") goes into $(OUT)/views/views.txt as
# "<stage>/<view>.png: <text>", written whole at the end.
VIEW_NAMES := final hdr luminance key bloom0 bloom1 blur ev nan
.PHONY: views
views: build
	@mkdir -p $(OUT)/views; : >$(OUT)/views/views.txt.tmp; \
	for stage in $(STAGES); do \
	    mkdir -p $(OUT)/views/$$stage; \
	    for view in $(VIEW_NAMES); do \
	        $(BIN)/$$stage --headless --frames 1 --size $(or $(VIEW_SIZE),640x360) --view $$view \
	            --output $(OUT)/views/$$stage/$$view.png >$(OUT)/views/out.txt 2>$(OUT)/views/error.txt; \
	        code=$$?; \
	        if [ $$code -eq 0 ]; then \
	            echo "  $(OUT)/views/$$stage/$$view.png"; \
	            line=$$(sed -n "s/^view $$view: //p" $(OUT)/views/out.txt); \
	            echo "$$stage/$$view.png: $${line:-(the frame as shown; no line)}" >>$(OUT)/views/views.txt.tmp; \
	        elif [ $$code -ne 2 ]; then cat $(OUT)/views/error.txt; exit 1; fi; \
	    done; \
	done; rm -f $(OUT)/views/error.txt $(OUT)/views/out.txt; mv $(OUT)/views/views.txt.tmp $(OUT)/views/views.txt; \
	echo "  $(OUT)/views/views.txt"

# Grading (grader/, for instructors): make grade PART=N SUBMISSIONS="dir1 dir2 ..." [REPORT=dir]
# [GRADE_JOBS=N]. FLIP, the perceptual image metric the grader compares frames with, is not a Debian
# package: grade-deps installs the pinned flip-evaluator from PyPI into a venv under build/.
FLIP_VERSION := 1.7
GRADE_VENV   := $(BUILD)/grade-venv
REPORT       ?= grade-report
GRADE_JOBS   ?= $(JOBS)
# The interpreter FLIP's venv is made with (and runs with): it must be reachable by the user grading.
GRADE_PYTHON ?= python3
.PHONY: grade grade-args grade-deps grade-deps-or-skip
# python3-venv is installed here, not by a target-specific PACKAGES: `deps` runs once per make, first
# for whichever prerequisite comes first (build, for make grade-jobs-check), so a package grade-deps
# added there was never installed (a fresh Debian 13: "ensurepip is not available").
grade-deps: deps
	@$(MAKE) --no-print-directory deps PACKAGES=python3-venv
	@[ -x $(GRADE_VENV)/bin/flip ] && $(GRADE_VENV)/bin/pip show flip-evaluator 2>/dev/null | grep -qx 'Version: $(FLIP_VERSION)' || { \
	    rm -rf $(GRADE_VENV) && $(GRADE_PYTHON) -m venv $(GRADE_VENV) && \
	    $(GRADE_VENV)/bin/pip install --quiet --disable-pip-version-check flip-evaluator==$(FLIP_VERSION); }
	@python3 grader/flip_reach.py $(GRADE_VENV)

grade-args:
	@[ -n "$(PART)" ] && [ -n "$(SUBMISSIONS)" ] || { echo 'usage: make grade PART=1|2|3 SUBMISSIONS="dir ..." [REPORT=dir] [GRADE_JOBS=N]'; exit 2; }

# The grader is built with the tests (their CPU reference): Catch2 and its sandbox, bubblewrap.
grade check: PACKAGES += catch2 bubblewrap
# SIMILARITY=1 also compares the class (t10-grade --similarity; make similarity-deps first).
grade: grade-args build grade-deps $(if $(SIMILARITY),similarity-deps)
	$(BIN)/t10-grade --part $(PART) --report $(REPORT) --jobs $(GRADE_JOBS) $(if $(SIMILARITY),--similarity) $(SUBMISSIONS)

# make bench-grader: what grading a class costs (grader/bench_grader.py): the grader's test batches (every
# part's references, known mistakes, fitted parameters and broken submissions) graded with a fresh
# cache into $(OUT)/bench-grader/; prints submissions per minute, CPU seconds and peak memory per submission.
.PHONY: bench-grader
bench-grader: PACKAGES += catch2 bubblewrap
bench-grader: build grade-deps
	python3 grader/bench_grader.py $(BIN)/t10-grade grader/tests/make_submissions.py $(CURDIR) $(OUT)/bench-grader $(GRADE_JOBS)

# make grade-sweep (issue 38): every fitted parameter of the grader's mistake catalogue at values spread over
# the range its fit searches (grader/tests/sweep.py), each as a submission: named with its value measured
# within 10 %, or 100 for a value within the tolerance; prints the per-parameter table of the instructors'
# page. 124 submissions, about 4 minutes of 2 cores: too long for make test, which grades the value
# that regressed (Part 1's middle grey 1.0); .ci/run runs it.
.PHONY: grade-sweep
grade-sweep: PACKAGES += catch2 bubblewrap
grade-sweep: build grade-deps
	python3 grader/tests/sweep.py $(BIN)/t10-grade $(CURDIR) $(OUT)/grade-sweep $(GRADE_JOBS)

# make web-agreement: the page's check (Module.t10Check) against t10-grade on every shader-only
# submission of the grader's test batches and of make grade-sweep (issue 52, tests/web/agreement.py; make
# test runs three of them): the batches graded by their ctest tests and the sweep by sweep.py, then each
# submission's shaders set in its part's page and checked there. About 8 minutes after the build (the
# batches and the sweep), 3 of them in Chromium. WEB_RENDERER=swiftshader: Chromium without a GPU.
WEB_RENDERER ?= llvmpipe
.PHONY: web-agreement
web-agreement: PACKAGES += catch2 bubblewrap
web-agreement: build grade-deps web
	cd $(BUILD) && ctest --output-on-failure -R '^grade: (write the test submissions|part [123] batch with --jobs 2)$$'
	python3 grader/tests/sweep.py $(BIN)/t10-grade $(CURDIR) $(OUT)/grade-sweep $(GRADE_JOBS)
	PYTHONPATH=$(CURDIR)/tools python3 tests/web/agreement.py --web $(OUT)/web --source $(CURDIR) --all \
	    --submissions $(BUILD)/grader/test-out/submissions --reports $(BUILD)/grader/test-out/reports \
	    --sweep $(OUT)/grade-sweep --renderer $(WEB_RENDERER) --out $(OUT)/web-agreement

# make grade-jobs-check: the proof that a grader other than root keeps its jobs apart (issue 38): a fork
# bomb graded beside honest copies with --jobs 2, twenty rounds (grader/tests/isolation/fork_bomb_jobs.py;
# make test runs two). As root the grader runs as an unprivileged uid; SKIPPED (and passes) where that
# cannot run at all (no namespaces, or a checkout or FLIP out of other users' reach: make grade-deps says so).
.PHONY: grade-jobs-check
# catch2 as for make grade: without the tests configured, t10-grade is not in `build` (CMakeLists.txt).
grade-jobs-check: PACKAGES += catch2 bubblewrap
grade-jobs-check: build grade-deps
	@python3 grader/tests/isolation/fork_bomb_jobs.py $(CURDIR) $(BIN)/t10-grade $(GRADE_VENV)/bin/flip $(BUILD)/grade-jobs-check 20; \
	rc=$$?; [ $$rc -eq 77 ] && echo "grade-jobs-check: SKIPPED (above: why)" && exit 0; exit $$rc

# The grader's tests need FLIP too (make test makes it); without it (no network for PyPI) they report
# themselves skipped. The same for JPlag's jars (make test installs Java with the test packages).
grade-deps-or-skip:
	@$(MAKE) --no-print-directory grade-deps || echo "warning: FLIP could not be installed: the grader's tests will be skipped"
	@python3 grader/similarity/fetch_engine.py grader/similarity/jplag.lock $(SIMILARITY_ENGINE) || \
	    echo "warning: JPlag could not be fetched: the similarity tests will be skipped"

# Similarity between students (issue 51; grader/similarity/): JPlag 4.3.0, a library on Maven Central,
# pinned jar by jar (size and SHA-256) in grader/similarity/jplag.lock and fetched into
# $(SIMILARITY_ENGINE)/ by similarity-deps; run by Debian's Java (default-jre-headless: OpenJDK 17 on
# Debian 12, 21 on Debian 13 and Ubuntu 24.04; JPlag 4.3 needs 17 or later). Nothing is fetched when it
# runs. make similarity PART=N SUBMISSIONS="dir ..." (or SUBMISSIONS_DIR=folder of submission folders)
# writes similarity.json, .csv and .html into $(REPORT)/; t10-grade --similarity does the same after
# grading a class. Neither make run nor make build needs any of it.
SIMILARITY_ENGINE := $(BUILD)/jplag
.PHONY: similarity similarity-deps
similarity-deps:
	@$(MAKE) --no-print-directory deps PACKAGES="default-jre-headless maven"
	@python3 grader/similarity/fetch_engine.py grader/similarity/jplag.lock $(SIMILARITY_ENGINE)

# make bench-similarity: 900 generated Part 3 submissions compared (grader/similarity/bench_similarity.py):
# wall and CPU time, peak memory; fails above two minutes of wall time.
.PHONY: bench-similarity
bench-similarity: similarity-deps
	python3 grader/similarity/bench_similarity.py $(CURDIR) $(SIMILARITY_ENGINE) $(OUT)/bench-similarity

similarity: similarity-deps
	@[ -n "$(PART)" ] && [ -n "$(SUBMISSIONS)$(SUBMISSIONS_DIR)" ] || { \
	    echo 'usage: make similarity PART=1|2|3 SUBMISSIONS="dir ..." | SUBMISSIONS_DIR=folder [REPORT=dir] [SIMILARITY_THRESHOLD=x]'; exit 2; }
	python3 grader/similarity/similarity.py --part $(PART) --report $(REPORT) --engine $(SIMILARITY_ENGINE) \
	    $(if $(SIMILARITY_THRESHOLD),--threshold $(SIMILARITY_THRESHOLD)) \
	    $(if $(SUBMISSIONS_DIR),--folder "$(SUBMISSIONS_DIR)") $(SUBMISSIONS)

# Students (tools/student/): `make student PART=N` starts student/partN/ (Part 1 from
# tutorial10_part0_start/, Part N from the student's own part(N-1) or else the reference of Part N-1);
# the build finds student/*/ (cmake/T10Student.cmake) and builds each only when asked, as
# build/bin/student_<folder>; `make check PART=N [DIR=folder]` builds it, grades it against Part N and
# prints what to fix first; `make run STAGE=student_partN` runs it. STUDENT_DIR= puts the folders
# elsewhere (the build discovers T10_STUDENT_DIR, student/ unless configured otherwise).
STUDENT_DIR ?= student
# The compiler's own messages from a build log: ninja's progress lines and the failed command dropped,
# paths relative to the repository root (ninja's are relative to $(BUILD)/).
COMPILER_MESSAGES := sed -e '/^FAILED: /{N;d;}' -e '/^\[[0-9]*\/[0-9]*\] /d' -e '/^ninja: build stopped/d' -e 's\#\(^\|[[:space:]]\)\.\./\#\1\#g'
CHECK_REPORT := $(BUILD)/check
.PHONY: student check check-args run-stage
student:
	@python3 tools/student/new_student.py --part "$(PART)" --student-dir "$(STUDENT_DIR)" --source-root "$(CURDIR)"

check-args:
	@case "$(PART)" in 1|2|3) ;; *) echo 'usage: make check PART=1|2|3 [DIR=folder]   (make student PART=N creates the folder)'; exit 2 ;; esac
	@dir="$(or $(DIR),$(STUDENT_DIR)/part$(PART))"; [ -d "$$dir" ] || { \
	    echo "make check: $$dir/: no such folder (make student PART=$(PART) creates $(STUDENT_DIR)/part$(PART)/)"; exit 2; }

# ISOLATION=none grades without the sandbox, for a student's own code on a machine that refuses it
# (a container started with Docker's defaults: tools/student/check.sh says so and what to do).
ISOLATION ?=
# The student's program is built by its own target first (when the build has found the folder), so that
# a compile error shows with the project's flags and names the file and line; then t10-grade grades it.
check: check-args build grade-deps
	@dir="$(or $(DIR),$(STUDENT_DIR)/part$(PART))"; full=$$(cd "$$dir" && pwd -P); \
	target=$$(while read -r name folder; do [ "$$folder" = "$$full" ] && echo "$$name"; done < $(BUILD)/student_stages.txt); \
	if [ -n "$$target" ]; then \
	    cmake --build $(BUILD) --target $$target >$(BUILD)/student-build.log 2>&1 || { \
	        $(COMPILER_MESSAGES) $(BUILD)/student-build.log | head -n 40; \
	        echo "make check: $$dir/ does not build: fix the first error above (file:line), then make check PART=$(PART) again"; \
	        echo "(the compiler's whole output: $(BUILD)/student-build.log)"; exit 1; }; \
	fi; \
	tools/student/check.sh $(BIN)/t10-grade $(PART) $(CHECK_REPORT)/part$(PART) "$$dir" $(ISOLATION)

# make run STAGE=name: one stage, reference or student, in a window or headless into $(OUT)/name.png.
run-stage:
	@known=$$(cat $(BUILD)/stages.txt; cut -d' ' -f1 $(BUILD)/student_stages.txt 2>/dev/null); \
	echo "$$known" | grep -qx "$(STAGE)" || { \
	    echo "make run: STAGE=$(STAGE): no such stage; choose one of:" $$known "(make student PART=N adds student_partN)"; exit 2; }
	@cmake --build $(BUILD) --target $(STAGE) >$(BUILD)/stage-build.log 2>&1 || { \
	    $(COMPILER_MESSAGES) $(BUILD)/stage-build.log | head -n 40; echo "make run: $(STAGE) does not build: fix the first error above (file:line)"; exit 1; }
	@if [ -n "$$DISPLAY$$WAYLAND_DISPLAY" ]; then \
	    echo "Opening $(STAGE) (Esc quits; WASD moves, right mouse button looks, scroll zooms; V cycles the views)"; \
	    $(BIN)/$(STAGE); \
	else \
	    mkdir -p $(OUT); \
	    echo "No display: rendering $(STAGE) headless into $(OUT)/"; \
	    $(BIN)/$(STAGE) --headless --frames 1 --output $(OUT)/$(STAGE).png >/dev/null && echo "  $(OUT)/$(STAGE).png"; \
	fi

# Grading on the platforms courses use (grader/platforms; site/instructors.md): `make grader`
# installs and builds only what grading needs (t10-grade, the reference stages, FLIP); `make gradescope
# PART=N` packs out/gradescope/partN/autograder.zip; `make prairielearn PART=N` writes
# out/prairielearn/partN/ (the entrypoint and an info.json snippet).
# The grader needs only common/ (not the tests, nor extras/ and its Dear ImGui): bubblewrap is its sandbox,
# python3-venv holds FLIP. Configured without the tests and extras where make grader configures first.
GRADER_PACKAGES := $(filter-out libimgui-dev,$(PACKAGES)) bubblewrap python3-venv
.PHONY: grader grader-packages gradescope prairielearn platform-part
grader: PACKAGES := $(GRADER_PACKAGES)
grader: CONFIGURE_FLAGS := -DT10_BUILD_EXTRAS=OFF
# The list the platforms' install script (grader/platforms/install_grader.sh) checks and installs.
grader-packages:
	@echo $(GRADER_PACKAGES)

grader: configure grade-deps
	cmake --build $(BUILD) -j $(JOBS) --target t10-grade

platform-part:
	@case "$(PART)" in 1|2|3) ;; *) echo 'usage: make gradescope|prairielearn PART=1|2|3'; exit 2;; esac

gradescope: platform-part
	python3 grader/platforms/package.py gradescope $(PART) . $(OUT)/gradescope/part$(PART)

prairielearn: platform-part
	python3 grader/platforms/package.py prairielearn $(PART) . $(OUT)/prairielearn/part$(PART)

# `make distro-check DISTRO=bookworm|trixie [MODES="root user"] [TARGETS="run test"]` (tools/distro_check/):
# `make run` and `make test` (or the TARGETS given) from a clone of this checkout's HEAD in a fresh minimal Debian root (mmdebstrap, cached in
# $(BUILD)/distro-check/), as root and as a user with sudo. Not part of `make test`; run it for trixie
# before resolving an issue that touches CMake, packages or a third-party API.
.PHONY: distro-check
distro-check: PACKAGES := mmdebstrap
distro-check: deps
	tools/distro_check/distro_check.sh "$(DISTRO)" "$(or $(MODES),root user)" . $(BUILD)/distro-check "$(or $(TARGETS),run test)"

# The dev container (.devcontainer/: GitHub Codespaces, VS Code's Dev Containers): its Dockerfile
# installs what devcontainer-packages prints, the lists above (the build's, make test's with Catch2 and
# FLIP's venv), so that they live here only. `make devcontainer-check` (tools/devcontainer_check/) runs
# the Dockerfile's steps in a fresh Debian 12 root (mmdebstrap, cached in $(BUILD)/devcontainer-check/)
# and proves, as the container's user, its desktop, GL context, `make run`'s window, noVNC's page in
# Chromium and `make check`. Not part of `make test`: about 31 minutes fresh on 2 loaded cores (the
# minbase root 2.4, the image 8.4, the project's build 15.9, the checks 2.5); CI (.ci/run) runs it.
DEVCONTAINER_PACKAGES := $(sort $(PACKAGES) catch2 python3-venv $(TEST_PACKAGES))
.PHONY: devcontainer-packages devcontainer-check
devcontainer-packages:
	@echo $(DEVCONTAINER_PACKAGES)

# The check's tools on the host: mmdebstrap, ip (its own network), git (the clone), python3 (the
# Dockerfile's reader), ps (a uid no process uses).
devcontainer-check: PACKAGES := mmdebstrap iproute2 git python3 procps
devcontainer-check: deps
	tools/devcontainer_check/devcontainer_check.sh . $(BUILD)/devcontainer-check

# Windows, proven here (tools/windows_check/): the project cross-compiled with Debian's MinGW-w64
# (GLFW, Imath, OpenEXR, Catch2 built from Debian's source packages into $(BUILD)/windows-deps/, once),
# then its Windows tests (the four goldens through the WGL pbuffer backend, the unit and GL tests) run
# under Wine in Xvfb. Not part of `make test`: fresh it takes about 4.6 minutes on 2 cores, more than the
# whole suite may (warm: 19 s; tools/windows_check/README.md). CI runs it as a job of its own.
.PHONY: windows-check
windows-check: PACKAGES += g++-mingw-w64-x86-64-posix libz-mingw-w64-dev wine wine64 dpkg-dev xvfb xauth
windows-check: deps
	tools/windows_check/windows_check.sh $(BUILD)/windows-deps $(BUILD)/windows
