# waterworld - build, test, demo. `make help` lists the targets.
#
#   make            build ./waterworld (warnings are errors, -ffp-contract=off)
#   make demo       install what is missing, build, render scenes/demo.yaml into out/demo/
#   make test       install, build, run the test suite, then the same suite under ASan + UBSan
#   make unit       the test suite only (T=NAME runs the tests whose name holds NAME)
#   make asan       the test suite under AddressSanitizer + UBSan only
#   make test-long  the long tier: soaks, benchmarks as tests, the largest renders
#   make golden     re-render the golden images in golden/ (read README first)
#   make bench      speed and memory figures (not part of test)
#   make fuzz       libFuzzer on the scene loader, then the OBJ reader, FUZZ_SECONDS each
#   make soak       one hour of simulated time at 120 Hz with every system on (not part of test)

BUILD   ?= build
CC      ?= cc
OPT     ?= -O2 -g
WARN    := -std=c11 -Wall -Wextra -Wpedantic -Werror -Wvla -Wimplicit-fallthrough \
           -Wmissing-prototypes -Wstrict-prototypes
CFLAGS  += $(OPT) $(WARN) -ffp-contract=off -fno-fast-math $(SAN)
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

.PHONY: all deps demo test unit asan test-long golden bench fuzz soak clean help
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

deps:
	@sh scripts/install-deps.sh

unit: $(BIN) $(BUILD)/ww-tests
	WW_BIN=./$(BIN) $(BUILD)/ww-tests -j $(JOBS) $(T)

test: deps
	@$(MAKE) --no-print-directory -j$(JOBS) $(BIN) $(BUILD)/ww-tests
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
	    build/asan/waterworld build/asan/ww-tests
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp ASAN_OPTIONS=detect_leaks=1:intercept_tls_get_addr=0 UBSAN_OPTIONS=print_stacktrace=1 WW_BIN=build/asan/waterworld \
	    WW_ASAN=1 build/asan/ww-tests -j $(JOBS) --tier unit,proc $(T)

demo: deps
	@$(MAKE) --no-print-directory $(BIN)
	./$(BIN) render scenes/demo.yaml -o out/demo
	@echo "frames: out/demo/frame_00000.png ... frame_00299.png"
	@echo "video:  ffmpeg -framerate 30 -i out/demo/frame_%05d.png -pix_fmt yuv420p demo.mp4"

golden: $(BIN)
	sh scripts/make-golden.sh ./$(BIN)

bench: $(BIN)
	./$(BIN) bench render
	./$(BIN) bench quality
	./$(BIN) bench waves
	./$(BIN) bench sim
	./$(BIN) bench output
	./$(BIN) bench compare

# libFuzzer on the scene loader and the OBJ reader (clang; not part of test). FUZZ_SECONDS=60
# each by default.
FUZZ_SECONDS ?= 60
fuzz: deps
	@command -v clang >/dev/null || sh scripts/install-deps.sh --fuzz
	@mkdir -p build/fuzz/corpus && cp scenes/*.yaml tests/bad/*.yaml build/fuzz/corpus/
	clang -g -O1 -std=c11 -fsanitize=fuzzer,address,undefined -D_DEFAULT_SOURCE -Isrc \
	    -o build/fuzz/fuzz_scene tests/fuzz/fuzz_scene.c src/scene/*.c src/core/*.c -lyaml -lm
	build/fuzz/fuzz_scene -max_total_time=$(FUZZ_SECONDS) build/fuzz/corpus
	@mkdir -p build/fuzz/corpus_obj && cp tests/data/*.obj build/fuzz/corpus_obj/
	clang -g -O1 -std=c11 -fsanitize=fuzzer,address,undefined -D_DEFAULT_SOURCE -Isrc \
	    -o build/fuzz/fuzz_obj tests/fuzz/fuzz_obj.c src/scene/obj.c src/scene/assets.c \
	    src/core/*.c -lm
	build/fuzz/fuzz_obj -max_total_time=$(FUZZ_SECONDS) build/fuzz/corpus_obj

# one hour at 120 Hz of SOAK_SCENE (every system on): exit 3 names the system, field, index and
# step of a NaN or Inf; --stats prints simulated seconds per wall second. A 60 s version runs in
# the tests (soak_short in tests/test_simtools.c).
SOAK_SCENE ?= scenes/soak.yaml
SOAK_SECONDS ?= 3600
soak: $(BIN)
	./$(BIN) simulate $(SOAK_SCENE) --set time.dt=1/120 --set time.fps=30 \
	    --set time.duration=$(SOAK_SECONDS) --stats

clean:
	rm -rf build $(BIN)

help:
	@sed -n '1,13p' Makefile

-include $(LIB_OBJ:.o=.d) $(TEST_OBJ:.o=.d) $(BUILD)/src/cli/main.d
