# SPDX-License-Identifier: MIT
# stin — build, test, bench, install.
#   make            libstin.a, libstin_platform.a, stin-render, stin-bench, examples/
#   make check      install deps if missing, unit tests (ASan+UBSan), image tests per profile,
#                   the layer rule, the stin-bench --quick smoke, the browser image tests
#                   (tests/web/run.sh); suites run in parallel
#   make web        libstin and its browser front end in WebAssembly (emscripten), the
#                   pages and the scenes as packs under build/web/ (docs/web.md)
#   make web-demo   serves the demo page on 127.0.0.1:WEB_PORT (default 8047)
#   make check-quick  the edit loop: unit tests, one profile per tier on EGL, the CLI and layers
#   make demo       install deps if missing, render the example scenes at every tier into out/
#   make bench      run stin-bench (docs/benchmarks.md)
#   make fuzz       libFuzzer on the scene loader and on model/texture files, FUZZ_SECONDS
#                   (default 60) each (docs/fuzzing.md)
#   make install    PREFIX=/usr/local DESTDIR=  headers, archives, pkg-config and CMake files
#   make uninstall  the same PREFIX and DESTDIR: removes what install wrote
#   make clean
# Options: OSMESA=no builds the platform without the OSMesa backend and
# OIIO=no the tools without OpenImageIO (file reads and writes then fail with
# a message): a bench-only build for a GPU machine that has neither, e.g.
#   make B=build/gpu OSMESA=no OIIO=no build/gpu/stin-bench

PREFIX ?= /usr/local
DESTDIR ?=
B := build
CC ?= cc
CXX ?= c++
AR ?= ar

WARN := -Wall -Wextra -Werror
OPT ?= -O2 -g
LIB_CFLAGS := -std=c99 -pedantic $(WARN) $(OPT) -Iinclude -Isrc -I$(B)
TOOL_CFLAGS := -std=c99 $(WARN) $(OPT) -D_POSIX_C_SOURCE=200809L -Iinclude -Iplatform -Itools/common \
  -Itests/reference $(shell pkg-config --cflags libcjson 2>/dev/null)
TOOL_CXXFLAGS := -std=c++17 $(WARN) $(OPT) -Iinclude -Itools/common
SAN := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
# Every object depends on exactly the headers it includes (.d files beside it).
DEPFLAGS = -MMD -MP

OSMESA ?= yes
OIIO ?= yes
# The interactive viewer (examples/viewer) needs GLFW (libglfw3-dev): built
# by make examples and make tests where it is installed, by make viewer always.
VIEWER_GLFW := $(shell pkg-config --exists glfw3 2>/dev/null && echo yes)
PLATFORM_LIBS := -lEGL $(if $(filter no,$(OSMESA)),,-lOSMesa) -ldl
TOOL_LIBS := $(if $(filter no,$(OIIO)),,-lOpenImageIO -lOpenImageIO_Util) -lassimp -lcjson -lstdc++ -lm
REF_LIBS := -lembree3

LIB_SRC := $(sort $(wildcard src/*/*.c))
SHADERS := $(sort $(wildcard shaders/gl2/*.vert shaders/gl2/*.frag shaders/gl2/*.glsl shaders/gl4/*.vert shaders/gl4/*.frag shaders/gl4/*.geom shaders/gl4/*.tesc shaders/gl4/*.glsl))
PLATFORM_SRC := $(if $(filter no,$(OSMESA)),$(filter-out platform/platform_osmesa.c,$(sort $(wildcard platform/*.c))) \
  platform/absent/osmesa_absent.c,$(sort $(wildcard platform/*.c)))
COMMON_SRC := $(sort $(wildcard tools/common/*.c)) $(if $(filter no,$(OIIO)),tools/common/absent/image_io_absent.c)
COMMON_CXX := $(if $(filter no,$(OIIO)),,$(sort $(wildcard tools/common/*.cpp)))
REF_SRC := $(sort $(wildcard tests/reference/*.c))

LIB_OBJ := $(LIB_SRC:%.c=$(B)/lib/%.o) $(B)/lib/shaders_embedded.o
CHECKED_OBJ := $(LIB_SRC:%.c=$(B)/checked/%.o) $(B)/checked/shaders_embedded.o
PLATFORM_OBJ := $(PLATFORM_SRC:%.c=$(B)/obj/%.o)
COMMON_OBJ := $(COMMON_SRC:%.c=$(B)/obj/%.o) $(COMMON_CXX:%.cpp=$(B)/obj/%.o)
REF_OBJ := $(REF_SRC:%.c=$(B)/obj/%.o)

.PHONY: all check check-quick demo bench install uninstall clean deps tests fuzz examples viewer
all: $(B)/libstin.a $(B)/libstin_platform.a $(B)/stin-render $(B)/stin-bench examples

deps:
	@sh platform/install-deps.sh

# ---- library -------------------------------------------------------------
$(B)/shaders_embedded.c: $(SHADERS) tools/embed-shaders.sh
	@mkdir -p $(@D)
	sh tools/embed-shaders.sh $(SHADERS) > $@.tmp && mv $@.tmp $@

$(B)/lib/%.o: %.c
	@mkdir -p $(@D)
	@echo "  CC      $<"; $(CC) $(LIB_CFLAGS) $(DEPFLAGS) -c $< -o $@
$(B)/lib/shaders_embedded.o: $(B)/shaders_embedded.c
	@mkdir -p $(@D)
	@echo "  CC      $<"; $(CC) $(LIB_CFLAGS) -c $< -o $@
$(B)/libstin.a: $(LIB_OBJ)
	rm -f $@ && $(AR) rcs $@ $^

# Test build: every GL call is checked against the capability profile.
$(B)/checked/%.o: %.c
	@mkdir -p $(@D)
	@echo "  CC      $<"; $(CC) $(LIB_CFLAGS) $(DEPFLAGS) -DSTIN_GL_CHECK=1 -c $< -o $@
$(B)/checked/shaders_embedded.o: $(B)/shaders_embedded.c
	@mkdir -p $(@D)
	@echo "  CC      $<"; $(CC) $(LIB_CFLAGS) -c $< -o $@
$(B)/libstin_checked.a: $(CHECKED_OBJ)
	rm -f $@ && $(AR) rcs $@ $^

# ---- platform, tool support, reference -------------------------------------
$(B)/obj/%.o: %.c
	@mkdir -p $(@D)
	@echo "  CC      $<"; $(CC) $(TOOL_CFLAGS) $(DEPFLAGS) -c $< -o $@
$(B)/obj/%.o: %.cpp
	@mkdir -p $(@D)
	@echo "  CXX     $<"; $(CXX) $(TOOL_CXXFLAGS) $(DEPFLAGS) -c $< -o $@
$(B)/libstin_platform.a: $(PLATFORM_OBJ)
	rm -f $@ && $(AR) rcs $@ $^
$(B)/libstin_tools.a: $(COMMON_OBJ)
	rm -f $@ && $(AR) rcs $@ $^
$(B)/libstin_reference.a: $(REF_OBJ)
	rm -f $@ && $(AR) rcs $@ $^



# ---- tools -----------------------------------------------------------------
# stin-render loads OpenImageIO at its first image file (image_io_lazy.c):
# linked in, it cost every start 0.55 CPU s, and most runs touch no file.
ifeq ($(OIIO),no)
RENDER_IMAGE_IO :=
RENDER_LIBS := $(TOOL_LIBS)
else
RENDER_IMAGE_IO := $(B)/obj/tools/common/lazy/image_io_lazy.o $(B)/libstin_image_io.so
RENDER_LIBS := $(filter-out -lOpenImageIO -lOpenImageIO_Util,$(TOOL_LIBS))
endif
$(B)/stin-render: $(patsubst %.c,$(B)/obj/%.o,$(sort $(wildcard tools/render/*.c))) $(RENDER_IMAGE_IO) $(B)/libstin_tools.a $(B)/libstin_platform.a $(B)/libstin.a
	$(CC) $(OPT) -o $@ $(filter-out %.so,$^) $(RENDER_LIBS) $(PLATFORM_LIBS)
$(B)/pic/%.o: %.c
	@mkdir -p $(@D)
	@echo "  CC pic  $<"; $(CC) $(TOOL_CFLAGS) -fPIC $(DEPFLAGS) -c $< -o $@
$(B)/pic/%.o: %.cpp
	@mkdir -p $(@D)
	@echo "  CXX pic $<"; $(CXX) $(TOOL_CXXFLAGS) -fPIC $(DEPFLAGS) -c $< -o $@
$(B)/libstin_image_io.so: $(B)/pic/tools/common/image_io.o $(B)/pic/tools/common/image_buffer.o
	$(CXX) -shared -o $@ $^ -lOpenImageIO -lOpenImageIO_Util
# tests/image/readback_log.c: every read-back hashed into STIN_READBACK_LOG
READBACK_WRAP := -Wl,--wrap=stin_platform_read_color,--wrap=stin_platform_read_depth
# tests/image/gl_errors.c: every public call that takes a context, so that a
# GL error is known to be stin's (STIN_CALLS there; the link checks the two agree)
STIN_CALL_WRAP := $(addprefix -Xlinker --wrap=,stin_create stin_destroy \
  stin_query_desc stin_query_caps stin_query_tier stin_query_choice stin_detect_caps \
  stin_query_extension stin_create_mesh stin_query_mesh_info stin_query_mesh_adjacency \
  stin_query_mesh_tangent stin_destroy_mesh stin_update_mesh stin_create_texture stin_destroy_texture \
  stin_begin_frame stin_add_light stin_draw stin_end_frame stin_draw_csg stin_query_csg_terms \
  stin_query_frame_stats stin_query_frame_projection stin_query_visibility_map \
  stin_bind_visibility stin_debug_query_counters stin_debug_query_shadow_map)
IMAGETEST_OBJ := $(patsubst %.c,$(B)/obj/%.o,$(sort $(wildcard tests/image/*.c)))
$(B)/stin-imagetest: $(IMAGETEST_OBJ) $(B)/libstin_reference.a $(B)/libstin_tools.a $(B)/libstin_platform.a $(B)/libstin_checked.a
	$(CC) $(OPT) -o $@ $^ $(READBACK_WRAP) $(STIN_CALL_WRAP) $(REF_LIBS) $(TOOL_LIBS) $(PLATFORM_LIBS)

# ---- unit tests (cmocka, AddressSanitizer + UndefinedBehaviorSanitizer) ----
SAN_CFLAGS := -std=c99 $(WARN) -g -O1 $(SAN) -D_POSIX_C_SOURCE=200809L -Iinclude -Isrc -I$(B) \
  -Iplatform -Itools/common -Itests/reference -Itests/unit $(shell pkg-config --cflags libcjson 2>/dev/null)
LIB_UNIT := $(filter-out test_noheap test_scene test_reference test_gl_audit,$(patsubst tests/unit/%.c,%,$(wildcard tests/unit/test_*.c)))
UNIT_BINS := $(LIB_UNIT:%=$(B)/tests/%) $(B)/tests/test_scene $(B)/tests/test_reference $(B)/tests/test_noheap \
  $(B)/tests/test_gl_audit \
  $(B)/tests/test_fuzz_scene $(B)/tests/test_fuzz_files

# Everything a unit test links is compiled once under the sanitisers into
# $(B)/san/ (the library as libstin_san.a), not once per test binary.
$(B)/san/%.o: %.c
	@mkdir -p $(@D)
	@echo "  CC san  $<"; $(CC) $(SAN_CFLAGS) $(DEPFLAGS) -c $< -o $@
$(B)/san/%.o: %.cpp
	@mkdir -p $(@D)
	@echo "  CXX san $<"; $(CXX) -std=c++17 $(WARN) -g -O1 $(SAN) -Iinclude -Itools/common $(DEPFLAGS) -c $< -o $@
$(B)/san/shaders_embedded.o: $(B)/shaders_embedded.c
	@mkdir -p $(@D)
	@echo "  CC san  $<"; $(CC) $(SAN_CFLAGS) -c $< -o $@
$(B)/libstin_san.a: $(LIB_SRC:%.c=$(B)/san/%.o) $(B)/san/shaders_embedded.o
	rm -f $@ && $(AR) rcs $@ $^
san_obj = $(patsubst %.cpp,$(B)/san/%.o,$(patsubst %.c,$(B)/san/%.o,$(1)))
# stin-render under ASan + UBSan, library included, for the hostile scene run
# (tools/hostile-scenes.py, docs/fuzzing.md); not part of make or make check.
RENDER_SAN_SRC := $(sort $(wildcard tools/render/*.c)) $(COMMON_SRC) $(COMMON_CXX) $(PLATFORM_SRC)
$(B)/stin-render-san: $(call san_obj,$(RENDER_SAN_SRC)) $(B)/libstin_san.a
	$(CXX) $(SAN) -o $@ $^ $(TOOL_LIBS) $(PLATFORM_LIBS)
FAKE_GL_SRC := tests/unit/fake_gl.c tests/unit/fake_gl_state.c tests/unit/fake_gl_attrib.c
$(LIB_UNIT:%=$(B)/tests/%): $(B)/tests/%: $(B)/san/tests/unit/%.o $(call san_obj,$(FAKE_GL_SRC)) $(B)/libstin_san.a
	@mkdir -p $(@D)
	$(CC) $(SAN) -o $@ $^ -lcmocka
# The checked build's GL audit: the test is compiled as the checked library
# is (STIN_GL_CHECK) and linked against it, with the fake GL.
$(B)/san-checked/tests/unit/test_gl_audit.o: tests/unit/test_gl_audit.c
	@mkdir -p $(@D)
	@echo "  CC san  $<"; $(CC) $(SAN_CFLAGS) -DSTIN_GL_CHECK=1 $(DEPFLAGS) -c $< -o $@
$(B)/tests/test_gl_audit: $(B)/san-checked/tests/unit/test_gl_audit.o $(call san_obj,$(FAKE_GL_SRC)) $(B)/libstin_checked.a
	@mkdir -p $(@D)
	$(CC) $(SAN) -o $@ $^ -lcmocka
$(B)/tests/test_scene: $(call san_obj,tests/unit/test_scene.c $(COMMON_SRC) $(COMMON_CXX) $(PLATFORM_SRC)) $(B)/libstin.a
	@mkdir -p $(@D)
	$(CXX) $(SAN) -o $@ $^ -lcmocka $(TOOL_LIBS) $(PLATFORM_LIBS)
$(B)/tests/test_reference: $(call san_obj,tests/unit/test_reference.c $(REF_SRC)) $(B)/libstin.a
	@mkdir -p $(@D)
	$(CC) $(SAN) -o $@ $^ -lcmocka $(REF_LIBS) -lm
# The allocator is interposed here, so no AddressSanitizer (it owns malloc).
$(B)/tests/test_noheap: tests/unit/test_noheap.c $(FAKE_GL_SRC) $(B)/libstin.a
	@mkdir -p $(@D)
	$(CC) -std=c99 $(WARN) -g -O1 -fsanitize=undefined -fno-sanitize-recover=all -D_GNU_SOURCE -Iinclude -Isrc -I$(B) -Itests/unit \
	  -o $@ $(filter %.c %.a,$^) -lcmocka

# stin-bench --csg times OpenCSG too where it is installed (libopencsg-dev,
# libglew-dev): its C++ shim, compiled only for the bench
BENCH_OPENCSG := $(shell printf '\043include <opencsg.h>\n\043include <GL/glew.h>\n' | \
  $(CXX) -E -x c++ - >/dev/null 2>&1 && echo yes)
ifeq ($(BENCH_OPENCSG),yes)
BENCH_CXX_OBJ := $(B)/obj/tools/bench/opencsg_shim.o
BENCH_CXX_LIBS := -lopencsg -lGLEW -lGL
$(B)/obj/tools/bench/section_csg.o: TOOL_CFLAGS += -DSTIN_BENCH_OPENCSG
endif
$(B)/obj/tools/bench/opencsg_shim.o: tools/bench/opencsg_shim.cpp tools/bench/opencsg_shim.h
	@mkdir -p $(@D)
	@echo "  CXX     $<"; $(CXX) $(TOOL_CXXFLAGS) -c $< -o $@
# stin-bench --peers times osgShadow too where it is installed
# (libopenscenegraph-dev): its C++ shim, compiled only for the bench
BENCH_OSG := $(shell printf '\043include <osgShadow/ShadowedScene>\n\043include <osgViewer/Viewer>\n' | \
  $(CXX) -E -x c++ - >/dev/null 2>&1 && echo yes)
ifeq ($(BENCH_OSG),yes)
BENCH_CXX_OBJ += $(B)/obj/tools/bench/osgshadow_shim.o
BENCH_CXX_LIBS += -losgShadow -losgViewer -losgGA -losgText -losgDB -losgUtil -losg -lOpenThreads -lGL
$(B)/obj/tools/bench/peers_osg.o $(B)/obj/tools/bench/peers_rows.o \
  $(B)/obj/tools/bench/section_peers.o: TOOL_CFLAGS += -DSTIN_BENCH_OSGSHADOW
endif
$(B)/obj/tools/bench/osgshadow_shim.o: tools/bench/osgshadow_shim.cpp tools/bench/osgshadow_shim.h
	@mkdir -p $(@D)
	@echo "  CXX     $<"; $(CXX) $(TOOL_CXXFLAGS) -c $< -o $@
# --peers judges visibility against the exact reference (Embree), with the
# image tests' light_reaches and near_shadow_edge
BENCH_REF_OBJ := $(B)/obj/tests/image/light_reach.o $(B)/libstin_reference.a
$(B)/obj/tools/bench/peers_vis.o: TOOL_CFLAGS += -Itests/image
$(B)/stin-bench: $(patsubst %.c,$(B)/obj/%.o,$(sort $(wildcard tools/bench/*.c))) $(BENCH_CXX_OBJ) $(BENCH_REF_OBJ) $(B)/libstin_tools.a $(B)/libstin_platform.a $(B)/libstin.a
	$(CC) $(OPT) -o $@ $^ $(REF_LIBS) $(TOOL_LIBS) $(BENCH_CXX_LIBS) $(PLATFORM_LIBS)

tests: $(UNIT_BINS) $(B)/stin-imagetest $(B)/stin-render $(B)/stin-bench $(B)/libstin.a \
  $(if $(VIEWER_GLFW),$(B)/examples/viewer)

# The build uses every core unless the caller's make already hands out jobs
# (MAKEFLAGS names the jobserver only inside a recipe, so the test is there).
NPROC := $(shell nproc 2>/dev/null || echo 2)
JOBS_FLAG = $$(case "$(MAKEFLAGS)" in *jobserver*|*-j*) ;; *) echo -j$(NPROC) ;; esac)

check: deps
	@$(MAKE) --no-print-directory $(JOBS_FLAG) tests web
	@sh tests/run.sh $(B)

# The edit loop: every unit test, the image tests of three profiles (one a
# tier: gl11, gl21, gl45-core) on EGL, the render CLI and the layer check.
check-quick: deps
	@$(MAKE) --no-print-directory $(JOBS_FLAG) tests
	@STIN_TEST_QUICK=1 STIN_TEST_PLATFORMS=egl STIN_TEST_PROFILES="gl11 gl21 gl45-core" sh tests/run.sh $(B)

bench: deps
	@$(MAKE) --no-print-directory $(B)/stin-bench
	$(B)/stin-bench

# Every example scene at every tier the default context runs, and on the
# OpenGL ES 3.0 and 3.2 profiles (EGL), into out/.
demo: deps
	@$(MAKE) --no-print-directory $(B)/stin-render
	@mkdir -p out
	@for s in tests/scenes/*.json; do n=$$(basename $$s .json); \
	  for t in gl1 gl2 gl4 es30 es32; do \
	    case $$t in es*) how="--profile $$t";; *) how="--tier $$t";; esac; \
	    $(B)/stin-render $$s $$how -o out/$$n-$$t.png > out/$$n-$$t.txt 2>&1 \
	      && echo "out/$$n-$$t.png" || echo "$$n at $$t: $$(tail -n 1 out/$$n-$$t.txt)"; \
	  done; done

# ---- examples (examples/: headless programs; make check builds them again
# against a scratch install and checks their pictures) ----------------------
EXAMPLE_CFLAGS := -std=c99 -D_POSIX_C_SOURCE=200809L $(WARN) -pedantic $(OPT) -Iinclude
examples: $(B)/examples/egl_shadow $(B)/examples/egl_app_shader $(B)/examples/osmesa_shadow \
  $(B)/examples/skinned $(if $(VIEWER_GLFW),$(B)/examples/viewer)
$(B)/examples/egl_%: examples/egl_%.c examples/example_scene.h examples/example_egl.h $(B)/libstin.a
	@mkdir -p $(@D)
	$(CC) $(EXAMPLE_CFLAGS) -o $@ $< $(B)/libstin.a -lEGL -lm
$(B)/examples/skinned: examples/skinned.c examples/example_scene.h examples/example_egl.h $(B)/libstin.a
	@mkdir -p $(@D)
	$(CC) $(EXAMPLE_CFLAGS) -o $@ $< $(B)/libstin.a -lEGL -lm
$(B)/examples/osmesa_shadow: examples/osmesa_shadow.c examples/example_scene.h $(B)/libstin.a
	@mkdir -p $(@D)
	$(CC) $(EXAMPLE_CFLAGS) -o $@ $< $(B)/libstin.a -lOSMesa -lm

VIEWER_OBJ := $(patsubst %.c,$(B)/obj/%.o,$(sort $(wildcard examples/viewer/*.c)))
$(VIEWER_OBJ): TOOL_CFLAGS += -pedantic $(shell pkg-config --cflags glfw3 2>/dev/null)
viewer: $(B)/examples/viewer
$(B)/examples/viewer: $(VIEWER_OBJ) $(B)/libstin_tools.a $(B)/libstin.a
	@mkdir -p $(@D)
	$(CC) $(OPT) -o $@ $^ $(shell pkg-config --libs glfw3 2>/dev/null || echo -lglfw) $(TOOL_LIBS)

# ---- install ---------------------------------------------------------------
# The version comes from the header; the installed files are listed once, for
# install and uninstall.
VERSION := $(shell sed -n 's/^\#define STIN_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)$$/\2/p' include/stin/stin.h | paste -sd.)
INSTALLED := include/stin/stin.h include/stin/stin_debug.h include/stin/stin_platform.h \
  lib/libstin.a lib/libstin_checked.a lib/libstin_platform.a lib/pkgconfig/stin.pc \
  lib/pkgconfig/stin-platform.pc lib/cmake/stin/stinConfig.cmake \
  lib/cmake/stin/stinConfigVersion.cmake
SUBST = sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(VERSION)|'

install: $(B)/libstin.a $(B)/libstin_checked.a $(B)/libstin_platform.a
	install -d $(DESTDIR)$(PREFIX)/include/stin $(DESTDIR)$(PREFIX)/lib/pkgconfig \
	  $(DESTDIR)$(PREFIX)/lib/cmake/stin
	install -m 644 include/stin/stin.h include/stin/stin_debug.h platform/stin_platform.h $(DESTDIR)$(PREFIX)/include/stin/
	install -m 644 $(B)/libstin.a $(B)/libstin_checked.a $(B)/libstin_platform.a $(DESTDIR)$(PREFIX)/lib/
	$(SUBST) stin.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/stin.pc
	$(SUBST) stin-platform.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/stin-platform.pc
	$(SUBST) stinConfig.cmake.in > $(DESTDIR)$(PREFIX)/lib/cmake/stin/stinConfig.cmake
	$(SUBST) stinConfigVersion.cmake.in > $(DESTDIR)$(PREFIX)/lib/cmake/stin/stinConfigVersion.cmake

# Removes exactly what install wrote, then the directories it made if empty.
uninstall:
	rm -f $(addprefix $(DESTDIR)$(PREFIX)/,$(INSTALLED))
	-rmdir $(DESTDIR)$(PREFIX)/include/stin $(DESTDIR)$(PREFIX)/lib/cmake/stin \
	  $(DESTDIR)$(PREFIX)/lib/cmake $(DESTDIR)$(PREFIX)/lib/pkgconfig 2>/dev/null || true

clean:
	rm -rf $(B) out

# ---- fuzzing (docs/fuzzing.md) ----------------------------------------------
# The loader's sources without GL, and stin (built for the fuzzer) for the
# csg products' checks (stin_csg_measure): no GL call is made, no platform.
FUZZ_SRC := $(addprefix tools/common/,image_buffer.c isolate.c name_table.c one_line.c scene_camera.c scene_csg.c \
  scene_csg_check.c scene_entries.c scene_import_memo.c scene_json.c scene_json_util.c scene_mesh_file.c \
  scene_model_check.c scene_model_import.c scene_model_materials.c scene_model_wire.c scene_primitives.c scene_texture.c)
FUZZ_LIBS := -lOpenImageIO -lOpenImageIO_Util -lassimp -lcjson -lstdc++ -lm
FUZZ_CXX ?= clang++
FUZZ_SECONDS ?= 60
FUZZ_SAN := -g -O1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_DIRS_scene := tests/scenes:tests/scenes/bad:tests/fuzz/corpus/scene:tests/fuzz/crashes/scene
FUZZ_DIRS_files := tests/fuzz/corpus/files:tests/fuzz/crashes/files
$(B)/fuzz/image_io.o: tools/common/image_io.cpp tools/common/image_io.h
	@mkdir -p $(@D)
	$(FUZZ_CXX) -std=c++17 $(WARN) $(FUZZ_SAN) -fsanitize=fuzzer-no-link -Itools/common -c $< -o $@
$(B)/fuzz/lib/%.o: %.c
	@mkdir -p $(@D)
	@echo "  CC fuzz $<"; $(FUZZ_CXX) -x c $(LIB_CFLAGS) $(FUZZ_SAN) -fsanitize=fuzzer-no-link -c $< -o $@
$(B)/fuzz/libstin.a: $(LIB_SRC:%.c=$(B)/fuzz/lib/%.o) $(B)/fuzz/lib/$(B)/shaders_embedded.o
	rm -f $@ && $(AR) rcs $@ $^
$(B)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c $(FUZZ_SRC) $(B)/fuzz/image_io.o $(B)/fuzz/libstin.a $(wildcard tools/common/*.h)
	$(FUZZ_CXX) -x c -std=c99 $(WARN) $(FUZZ_SAN) -fsanitize=fuzzer -D_POSIX_C_SOURCE=200809L -Iinclude \
	  -Itools/common $(shell pkg-config --cflags libcjson 2>/dev/null) -o $@ $< $(FUZZ_SRC) -x none \
	  $(B)/fuzz/image_io.o $(B)/fuzz/libstin.a $(FUZZ_LIBS)
# make check replays the committed corpus and every crash found, without libFuzzer.
$(B)/tests/test_fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/replay_main.c $(call san_obj,$(FUZZ_SRC) tools/common/image_io.cpp) $(B)/libstin_san.a
	@mkdir -p $(@D)
	$(CC) $(SAN_CFLAGS) -DREPLAY_NAME='"fuzz_$*"' -DREPLAY_DIRS='"$(FUZZ_DIRS_$*)"' \
	  -o $@ $< tests/fuzz/replay_main.c $(call san_obj,$(FUZZ_SRC) tools/common/image_io.cpp) \
	  $(B)/libstin_san.a $(FUZZ_LIBS)
fuzz: deps $(B)/fuzz/fuzz_scene $(B)/fuzz/fuzz_files
	@sh tests/fuzz/run.sh $(B) $(FUZZ_SECONDS)

$(B)/stin-reference: $(B)/obj/tests/tools/reference_render.o $(B)/libstin_reference.a $(B)/libstin_tools.a $(B)/libstin_platform.a $(B)/libstin.a
	$(CC) $(OPT) -o $@ $^ $(REF_LIBS) $(TOOL_LIBS) $(PLATFORM_LIBS)

-include $(shell find $(B) -name '*.d' 2>/dev/null)

# ---- WebAssembly (docs/web.md): libstin and the browser front end compiled
# with emscripten for WebGL 2, its pages and the repository's scenes as packs
# under $(B)/web/ ---------------------------------------------------------------
EMCC ?= emcc
EMAR ?= emar
# Debian's emscripten finds Debian's acorn through NODE_PATH and runs under
# the system python (a python3 first on PATH may lack nothing but is slower)
WEB_ENV := NODE_PATH=/usr/share/nodejs EMSDK_PYTHON=/usr/bin/python3
# clang (emcc) warns on partly initialised designated initialisers, gcc not
WEB_OPT ?= -O1
WEB_CFLAGS := -std=c99 -pedantic $(WARN) -Wno-missing-field-initializers $(WEB_OPT) -Iinclude -Isrc -I$(B)
WEB_TOOL_CFLAGS := -std=c99 $(WARN) $(WEB_OPT) -Iinclude -Itools/common $(shell pkg-config --cflags-only-I libcjson 2>/dev/null)
WEB_FRONT_SRC := platform/web/stin_web.c tools/common/scene_gpu.c tools/common/scene_pack.c tools/common/scene_camera.c \
  tools/common/scene_csg.c tools/common/scene_csg_check.c
WEB_LINK := -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2 -sALLOW_MEMORY_GROWTH=1 -sENVIRONMENT=web \
  -sMODULARIZE=1 -sEXPORT_NAME=createStin -sEXPORTED_RUNTIME_METHODS=ccall,cwrap,UTF8ToString,HEAPU8,HEAPF32 \
  -sEXPORTED_FUNCTIONS=_malloc,_free
WEB_PAGES := $(wildcard examples/web/*.html examples/web/*.js examples/web/*.css tests/web/*.html) tests/web/test.js
WEB_SCENES := $(sort $(wildcard tests/scenes/*.json))

$(B)/web/lib/%.o: %.c
	@mkdir -p $(@D)
	@echo "  EMCC    $<"; $(WEB_ENV) $(EMCC) $(WEB_CFLAGS) $(DEPFLAGS) -c $< -o $@
$(B)/web/lib/shaders_embedded.o: $(B)/shaders_embedded.c
	@mkdir -p $(@D)
	@echo "  EMCC    $<"; $(WEB_ENV) $(EMCC) $(WEB_CFLAGS) -c $< -o $@
$(B)/web/libstin.a: $(LIB_SRC:%.c=$(B)/web/lib/%.o) $(B)/web/lib/shaders_embedded.o
	rm -f $@ && $(WEB_ENV) $(EMAR) rcs $@ $^
$(B)/web/obj/%.o: %.c
	@mkdir -p $(@D)
	@echo "  EMCC    $<"; $(WEB_ENV) $(EMCC) $(WEB_TOOL_CFLAGS) $(DEPFLAGS) -c $< -o $@
$(B)/web/stin.js: $(WEB_FRONT_SRC:%.c=$(B)/web/obj/%.o) $(B)/web/libstin.a
	$(WEB_ENV) $(EMCC) $(WEB_OPT) $(WEB_LINK) -o $@ $^
$(B)/stin-scene-pack: $(B)/obj/tools/pack/main.o $(B)/libstin_tools.a
	$(CC) $(OPT) -o $@ $^ $(TOOL_LIBS)
$(B)/web/scenes.stamp: $(B)/stin-scene-pack $(WEB_SCENES)
	@mkdir -p $(B)/web/scenes
	$(B)/stin-scene-pack $(B)/web/scenes $(WEB_SCENES)
	@ls $(B)/web/scenes | sed -n 's/\.stinscene$$//p' > $(B)/web/scenes/list.txt
	@mkdir -p $(B)/web/scenes/variants
	$(B)/stin-scene-pack --variants $(B)/web/scenes/variants tests/scenes/stone-wall.json
	@touch $@
$(B)/web/pages.stamp: $(WEB_PAGES)
	@mkdir -p $(B)/web
	cp $(WEB_PAGES) $(B)/web/
	@touch $@

.PHONY: web web-demo
web: $(B)/web/stin.js $(B)/web/scenes.stamp $(B)/web/pages.stamp
# The demo page on 127.0.0.1 (WEB_PORT, default 8047) until interrupted.
WEB_PORT ?= 8047
web-demo: web
	node tests/web/server.js --root $(B)/web --port $(WEB_PORT)
