# waterworld - build, test, demo. `make help` lists the targets.
#
#   make            build ./waterworld (warnings are errors, -ffp-contract=off)
#   make demo       install what is missing, build, render the tour into out/demo/ and out/demo.mp4
#   make review     one frame per shot of scenes/review.list: out/review/review.png + index.html
#   make test       install, build, run the test suite, then the same suite under ASan + UBSan
#   make unit       the test suite only (T=NAME runs the tests whose name holds NAME)
#   make asan       the test suite under AddressSanitizer + UBSan only
#   make test-long  the long tier: soaks, benchmarks as tests, the largest renders
#   make golden     re-render the golden images in golden/ (read README first)
#   make bench      speed and memory figures (not part of test)
#   make fuzz       libFuzzer on every reader, FUZZ_SECONDS each (make fuzz-NAME: one of them)
#   make soak       one hour of simulated time at 120 Hz with every system on (not part of test)
#   make farm-test  a real one-node Slurm and parallel over ssh here, joined, = one process

BUILD   ?= build
CC      ?= cc
OPT     ?= -O2 -g
WARN    := -std=c11 -Wall -Wextra -Wpedantic -Werror -Wvla -Wimplicit-fallthrough \
           -Wmissing-prototypes -Wstrict-prototypes
# -fno-math-errno: sqrt and the like never set errno, so a loop over them vectorises (the
# simulation's lanes); every result is the same, only errno after a domain error differs.
# -fpeel-loops (on at -O3): loops of a few iterations known when compiling (the 3-vectors, the
# blocks of 8 lanes) are unrolled whole even where that grows the code; the same operations in
# the same order (the lake's step: 48.5 k -> 45.4 k instructions, every state the same)
CFLAGS  += $(OPT) $(WARN) -ffp-contract=off -fno-fast-math -fno-math-errno -fpeel-loops $(SAN)
CPPFLAGS+= -D_DEFAULT_SOURCE -D_POSIX_C_SOURCE=200809L -Isrc -I$(BUILD)/gen -MMD -MP

# library flags from pkg-config (OpenEXR 3.2+ headers include their neighbours by bare name, so
# its include folder must be on the path), with Debian's paths as the fallback where pkg-config
# or a .pc file is missing. Include folders go in as -isystem: our -Werror judges our code, not
# a library's headers. Of OpenEXR only the C library (OpenEXRCore) is linked. EGL and OSMesa
# are opened with dlopen: EGL's headers only, OSMesa nothing at build time.
PKG_CONFIG ?= pkg-config
pkg_cflags = $(patsubst -I%,-isystem %,$(shell $(PKG_CONFIG) --cflags $(1) 2>/dev/null))
EXR_PC_LIBS := $(shell $(PKG_CONFIG) --libs OpenEXR 2>/dev/null)
EXR_CFLAGS  := $(or $(call pkg_cflags,OpenEXR),$(addprefix -isystem ,$(wildcard /usr/include/OpenEXR)))
EXR_LIBS    := $(filter -L%,$(EXR_PC_LIBS)) $(or $(filter -lOpenEXRCore%,$(EXR_PC_LIBS)),-lOpenEXRCore)
YAML_CFLAGS := $(call pkg_cflags,yaml-0.1)
YAML_LIBS   := $(or $(shell $(PKG_CONFIG) --libs yaml-0.1 2>/dev/null),-lyaml)
GL_CFLAGS   := $(call pkg_cflags,egl) $(call pkg_cflags,cglm)
CPPFLAGS+= $(EXR_CFLAGS) $(YAML_CFLAGS) $(GL_CFLAGS)
LDLIBS  += $(YAML_LIBS) $(EXR_LIBS) -ldl -lm -lpthread
VERSION := $(shell cat VERSION 2>/dev/null || echo 0.0.0)
CPPFLAGS+= -DWW_VERSION='"$(VERSION)"'

LIB_SRC := $(filter-out src/cli/main.c,$(wildcard src/*/*.c))
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/%.o) $(BUILD)/gen/shaders_embed.o
TEST_SRC:= $(wildcard tests/*.c)
TEST_OBJ:= $(TEST_SRC:%.c=$(BUILD)/%.o)
SHADERS := $(sort $(wildcard shaders/*.glsl))
BIN     ?= waterworld

# the test runner runs this many tests at once (default: the CPU count)
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)

.PHONY: all deps demo review test unit asan test-long golden bench fuzz soak farm-test clean help
all: $(BIN)

# V=1 shows the full command lines
Q       := $(if $(V),,@)

$(BIN): $(BUILD)/src/cli/main.o $(BUILD)/libww.a
	@echo "  LD  $@"
	$(Q)$(CC) $(CFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/libww.a: $(LIB_OBJ)
	@rm -f $@
	$(Q)ar rcs $@ $^

$(BUILD)/%.o: %.c
	@mkdir -p $(dir $@)
	@echo "  CC  $<"
	$(Q)$(CC) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

# shaders are embedded so that the binary is self-contained
$(BUILD)/gen/shaders_embed.c: $(SHADERS) scripts/embed-shaders.sh
	@mkdir -p $(dir $@)
	$(Q)sh scripts/embed-shaders.sh $(SHADERS) > $@.tmp && mv $@.tmp $@

$(BUILD)/gen/shaders_embed.o: $(BUILD)/gen/shaders_embed.c
	$(Q)$(CC) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

# the test binary wraps the allocator so a test can count allocations inside ww_step, and fork
# and ww_backend_open so that the runner can hold unit tests to their tier
$(BUILD)/ww-tests: $(TEST_OBJ) $(BUILD)/libww.a
	@echo "  LD  $@"
	$(Q)$(CC) $(CFLAGS) -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=fork,--wrap=ww_backend_open \
	    -o $@ $^ $(LDLIBS)

# the fuzz targets built without libFuzzer (tests/fuzz/replay.c), to replay their seeds in the
# test suite (fuzz_targets_replay_their_seeds), with this build's compiler and sanitizers
FUZZ_TARGETS := scene obj png inflate exr wav image
REPLAY  := $(FUZZ_TARGETS:%=$(BUILD)/fuzz-replay/fuzz_%)
$(BUILD)/fuzz-replay/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_file.h tests/fuzz/replay.c $(BUILD)/libww.a
	@mkdir -p $(dir $@)
	@echo "  LD  $@"
	$(Q)$(CC) $(CPPFLAGS) $(CFLAGS) -o $@ $< tests/fuzz/replay.c $(BUILD)/libww.a $(LDLIBS) -lz

deps:
	@sh scripts/install-deps.sh

unit: $(BIN) $(BUILD)/ww-tests $(REPLAY)
	WW_BIN=./$(BIN) $(BUILD)/ww-tests -j $(JOBS) $(T)

test: deps
	@$(MAKE) --no-print-directory -j$(JOBS) $(BIN) $(BUILD)/ww-tests $(REPLAY)
	@$(MAKE) --no-print-directory unit
	@$(MAKE) --no-print-directory asan

test-long: $(BIN) $(BUILD)/ww-tests
	WW_BIN=./$(BIN) $(BUILD)/ww-tests -j $(JOBS) --tier long $(T)

# intercept_tls_get_addr=0: LeakSanitizer's scan of dynamic TLS reads a stale DTV entry left by
# the GL driver's libraries on this glibc (2.36) and its tracer dies with SIGSEGV ("DTLS 10 at
# 0xcb6-...", now and then, after a render); without the interception the scan skips dynamic TLS
asan:
	@$(MAKE) --no-print-directory -j$(JOBS) BUILD=build/asan BIN=build/asan/waterworld OPT="-O1 -g" \
	    SAN="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
	    build/asan/waterworld build/asan/ww-tests $(FUZZ_TARGETS:%=build/asan/fuzz-replay/fuzz_%)
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp ASAN_OPTIONS=detect_leaks=1:intercept_tls_get_addr=0 UBSAN_OPTIONS=print_stacktrace=1 WW_BIN=build/asan/waterworld \
	    WW_ASAN=1 build/asan/ww-tests -j $(JOBS) --tier unit,proc $(T)

# the tour (scenes/tour.yaml: stones, rod, boat, seat view, a dive to the chest, the sunset) with
# its sound track: frames and out/demo/sound.wav in out/demo/, then out/demo.mp4 (H.264 + AAC,
# tagged BT.709) when ffmpeg is here. DEMO_SIZE=1920x1080 for full HD, DEMO_FRAMES=N for the
# first N frames only, DEMO_SCENE for another scene (one with an audio: section)
DEMO_SCENE  ?= scenes/tour.yaml
DEMO_SIZE   ?= 640x360
DEMO_FRAMES ?=
# processes the render runs in (render --jobs): on CPU rendering two share the cores better
# than one process's llvmpipe threads (docs/speed.md)
DEMO_JOBS   ?= 2
demo: deps
	@$(MAKE) --no-print-directory $(BIN)
	@mkdir -p out/demo
	@rm -f out/demo/frame_*.png out/demo/sound.wav out/demo.mp4
	./$(BIN) render $(DEMO_SCENE) --size $(DEMO_SIZE) $(if $(DEMO_FRAMES),--frames $(DEMO_FRAMES)) \
	    -o out/demo --audio out/demo/sound.wav --jobs $(DEMO_JOBS) --progress
	@fps=$$(./$(BIN) plan $(DEMO_SCENE) | sed -n 's/^frames .* at \([0-9.]*\) fps.*/\1/p'); \
	if ! command -v ffmpeg >/dev/null 2>&1; then \
	    echo "video: skipped, ffmpeg is not installed (apt-get install ffmpeg); frames and sound are in out/demo/"; \
	else \
	    ffmpeg -hide_banner -loglevel error -y -framerate $$fps -i out/demo/frame_%05d.png \
	        -i out/demo/sound.wav -map 0:v -map 1:a -c:v libx264 -preset medium -crf 20 \
	        -vf scale=out_color_matrix=bt709:out_range=tv -pix_fmt yuv420p -colorspace bt709 \
	        -color_primaries bt709 -color_trc bt709 -color_range tv -c:a aac -b:a 192k -shortest \
	        -movflags +faststart -f mp4 out/demo.mp4.tmp && mv -f out/demo.mp4.tmp out/demo.mp4 && \
	    echo "video: out/demo.mp4 (with its sound track)"; \
	fi
	@echo "frames: out/demo/frame_00000.png ..., sound: out/demo/sound.wav"

# the review set: every scene and feature in one labelled contact sheet and one HTML page
# (REVIEW_ARGS adds options: --size 320x180, --jobs 1, --cols 6; see `waterworld review --help`)
REVIEW_LIST ?= scenes/review.list
REVIEW_OUT  ?= out/review
REVIEW_ARGS ?=
review: $(BIN)
	./$(BIN) review $(REVIEW_LIST) -o $(REVIEW_OUT) $(REVIEW_ARGS)

golden: $(BIN)
	sh scripts/make-golden.sh ./$(BIN)

bench: $(BIN)
	./$(BIN) bench render
	./$(BIN) bench quality
	./$(BIN) bench waves
	./$(BIN) bench sim
	./$(BIN) bench output
	./$(BIN) bench compare

# libFuzzer (clang) on every reader, one target each (tests/fuzz/fuzz_NAME.c):
#   scene    the scene loader: YAML, --set, --script, compile, validate, plan, first steps
#   obj      OBJ + MTL                      png      io/png_read.c (+ inflate), against stb_image
#   inflate  io/inflate.c, against zlib     exr      io/exr.c (OpenEXRCore), the compare loader
#   wav      io/wav.c and the resampler     image    textures, cubemaps, PNG/compare through stb
# `make fuzz` runs each for FUZZ_SECONDS (60); `make fuzz-NAME` runs one. The library is built
# with the fuzzer's coverage and ASan + UBSan into build/fuzz/; corpora grow in
# build/fuzz/corpus/NAME/ from the seeds in tests/fuzz/corpus/NAME/; a crash is written to
# build/fuzz/crash/NAME/ (rerun one: build/fuzz/fuzz_NAME FILE). FUZZ_ARGS adds libFuzzer flags.
FUZZ_SECONDS ?= 60
FUZZ_ARGS    ?=
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_LEN_scene   := 16384
FUZZ_LEN_obj     := 16384
FUZZ_LEN_png     := 65536
FUZZ_LEN_inflate := 65536
FUZZ_LEN_exr     := 65536
FUZZ_LEN_wav     := 65536
FUZZ_LEN_image   := 65536
FUZZ_DICT_scene  := -dict=tests/fuzz/scene.dict
FUZZ_DICT_obj    := -dict=tests/fuzz/obj.dict
# the repository's own files join the committed seeds
FUZZ_SEEDS_scene := scenes tests/bad tests/data
FUZZ_SEEDS_obj   := tests/data
.PHONY: fuzz-lib fuzz-build fuzz-seeds $(FUZZ_TARGETS:%=fuzz-%)

fuzz: fuzz-build
	@for t in $(FUZZ_TARGETS); do $(MAKE) --no-print-directory fuzz-$$t || exit 1; done

fuzz-build: $(FUZZ_TARGETS:%=build/fuzz/fuzz_%)

fuzz-lib:
	@sh scripts/install-deps.sh --fuzz
	@$(MAKE) --no-print-directory BUILD=build/fuzz CC=clang OPT="-O1 -g" \
	    SAN="-fsanitize=fuzzer-no-link $(FUZZ_SAN)" build/fuzz/libww.a

build/fuzz/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_file.h fuzz-lib
	@echo "  LD  $@"
	$(Q)clang -D_DEFAULT_SOURCE -D_POSIX_C_SOURCE=200809L -Isrc -Ibuild/fuzz/gen $(WARN) -O1 -g \
	    -fsanitize=fuzzer $(FUZZ_SAN) -o $@ $< build/fuzz/libww.a $(LDLIBS) -lz

$(FUZZ_TARGETS:%=fuzz-%): fuzz-%: build/fuzz/fuzz_%
	@mkdir -p build/fuzz/corpus/$* build/fuzz/crash/$*
	build/fuzz/fuzz_$* -max_total_time=$(FUZZ_SECONDS) -rss_limit_mb=2048 -timeout=60 \
	    -max_len=$(FUZZ_LEN_$*) $(FUZZ_DICT_$*) -artifact_prefix=build/fuzz/crash/$*/ \
	    -print_final_stats=1 $(FUZZ_ARGS) build/fuzz/corpus/$* tests/fuzz/corpus/$* $(FUZZ_SEEDS_$*)

# the binary seeds of tests/fuzz/corpus/ (PNG, zlib streams, WAV, EXR), rewritten in place
fuzz-seeds: $(BUILD)/libww.a
	$(Q)$(CC) $(CPPFLAGS) $(CFLAGS) -o $(BUILD)/make_seeds tests/fuzz/make_seeds.c $(BUILD)/libww.a $(LDLIBS) -lz
	@mkdir -p $(FUZZ_TARGETS:%=tests/fuzz/corpus/%)
	$(BUILD)/make_seeds tests/fuzz/corpus

# one hour at 120 Hz of SOAK_SCENE (every system on): exit 3 names the system, field, index and
# step of a NaN or Inf; --stats prints simulated seconds per wall second. A 60 s version runs in
# the tests (soak_short in tests/test_simtools.c).
SOAK_SCENE ?= scenes/soak.yaml
SOAK_SECONDS ?= 3600
soak: $(BIN)
	./$(BIN) simulate $(SOAK_SCENE) --set time.dt=1/120 --set time.fps=30 \
	    --set time.duration=$(SOAK_SECONDS) --stats

# a one-node Slurm cluster started here on 127.0.0.1 (munged, slurmctld, slurmd as root, stopped
# at the end): a 4-task array render of scenes/lake.yaml with sound and a 16-point sweep with
# thumbnails, each joined by a dependent job, held byte for byte to one process; then GNU
# parallel's --sshlogin against an sshd started the same way (scripts/farm/check-slurm.sh,
# check-ssh.sh; docs/farm.md). A skip (exit 77 of a script) says why and is not a pass.
farm-test: $(BIN)
	@sh scripts/install-deps.sh --farm
	@for c in slurm ssh; do \
	    WW_BIN=./$(BIN) sh scripts/farm/check-$$c.sh; rc=$$?; \
	    if [ $$rc -eq 77 ]; then echo "farm-test: $$c skipped (the reason is above), not passed"; \
	    elif [ $$rc -ne 0 ]; then exit $$rc; fi; \
	done

clean:
	rm -rf build $(BIN)

help:
	@sed -n '1,15p' Makefile

-include $(LIB_OBJ:.o=.d) $(TEST_OBJ:.o=.d) $(BUILD)/src/cli/main.d
