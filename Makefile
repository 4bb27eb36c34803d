# stin — build, test, bench, install.
#   make            libstin.a, libstin_platform.a, stin-render, stin-bench
#   make check      install deps if missing, unit tests (ASan+UBSan), image tests per profile
#   make demo       install deps if missing, render the example scenes at every tier into out/
#   make bench      run stin-bench (docs/benchmarks.md)
#   make install    PREFIX=/usr/local DESTDIR=  headers, archives, stin.pc
#   make clean

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

PLATFORM_LIBS := -lEGL -lOSMesa -ldl
TOOL_LIBS := -lOpenImageIO -lOpenImageIO_Util -lassimp -lcjson -lstdc++ -lm
REF_LIBS := -lembree3

LIB_SRC := $(sort $(wildcard src/*.c))
SHADERS := $(sort $(wildcard shaders/gl2/*.vert shaders/gl2/*.frag shaders/gl4/*.vert shaders/gl4/*.frag shaders/gl4/*.geom))
PLATFORM_SRC := $(sort $(wildcard platform/*.c))
COMMON_SRC := $(sort $(wildcard tools/common/*.c))
COMMON_CXX := $(sort $(wildcard tools/common/*.cpp))
REF_SRC := $(sort $(wildcard tests/reference/*.c))

LIB_OBJ := $(LIB_SRC:%.c=$(B)/lib/%.o) $(B)/lib/shaders_embedded.o
CHECKED_OBJ := $(LIB_SRC:%.c=$(B)/checked/%.o) $(B)/checked/shaders_embedded.o
PLATFORM_OBJ := $(PLATFORM_SRC:%.c=$(B)/obj/%.o)
COMMON_OBJ := $(COMMON_SRC:%.c=$(B)/obj/%.o) $(COMMON_CXX:%.cpp=$(B)/obj/%.o)
REF_OBJ := $(REF_SRC:%.c=$(B)/obj/%.o)

.PHONY: all check demo bench install clean deps unit-tests image-tests
all: $(B)/libstin.a $(B)/libstin_platform.a $(B)/stin-render $(B)/stin-bench

deps:
	@sh platform/install-deps.sh

# ---- library -------------------------------------------------------------
$(B)/shaders_embedded.c: $(SHADERS) tools/embed-shaders.sh
	@mkdir -p $(@D)
	sh tools/embed-shaders.sh $(SHADERS) > $@.tmp && mv $@.tmp $@

$(B)/lib/%.o: %.c $(wildcard include/stin/*.h src/*.h)
	@mkdir -p $(@D)
	$(CC) $(LIB_CFLAGS) -c $< -o $@
$(B)/lib/shaders_embedded.o: $(B)/shaders_embedded.c
	@mkdir -p $(@D)
	$(CC) $(LIB_CFLAGS) -c $< -o $@
$(B)/libstin.a: $(LIB_OBJ)
	rm -f $@ && $(AR) rcs $@ $^

# Test build: every GL call is checked against the capability profile.
$(B)/checked/%.o: %.c $(wildcard include/stin/*.h src/*.h)
	@mkdir -p $(@D)
	$(CC) $(LIB_CFLAGS) -DSTIN_GL_CHECK=1 -c $< -o $@
$(B)/checked/shaders_embedded.o: $(B)/shaders_embedded.c
	@mkdir -p $(@D)
	$(CC) $(LIB_CFLAGS) -c $< -o $@
$(B)/libstin_checked.a: $(CHECKED_OBJ)
	rm -f $@ && $(AR) rcs $@ $^

# ---- platform, tool support, reference -------------------------------------
$(B)/obj/%.o: %.c $(wildcard include/stin/*.h platform/*.h tools/common/*.h tests/reference/*.h)
	@mkdir -p $(@D)
	$(CC) $(TOOL_CFLAGS) -c $< -o $@
$(B)/obj/%.o: %.cpp $(wildcard tools/common/*.h)
	@mkdir -p $(@D)
	$(CXX) $(TOOL_CXXFLAGS) -c $< -o $@
$(B)/libstin_platform.a: $(PLATFORM_OBJ)
	rm -f $@ && $(AR) rcs $@ $^
$(B)/libstin_tools.a: $(COMMON_OBJ)
	rm -f $@ && $(AR) rcs $@ $^
$(B)/libstin_reference.a: $(REF_OBJ)
	rm -f $@ && $(AR) rcs $@ $^



# ---- tools -----------------------------------------------------------------
$(B)/stin-render: $(B)/obj/tools/render/main.o $(B)/libstin_tools.a $(B)/libstin_platform.a $(B)/libstin.a
	$(CC) $(OPT) -o $@ $^ $(TOOL_LIBS) $(PLATFORM_LIBS)
IMAGETEST_OBJ := $(patsubst %.c,$(B)/obj/%.o,$(sort $(wildcard tests/image/*.c)))
$(B)/stin-imagetest: $(IMAGETEST_OBJ) $(B)/libstin_reference.a $(B)/libstin_tools.a $(B)/libstin_platform.a $(B)/libstin_checked.a
	$(CC) $(OPT) -o $@ $^ $(REF_LIBS) $(TOOL_LIBS) $(PLATFORM_LIBS)
