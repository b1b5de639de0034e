# SPDX-License-Identifier: MIT
# orbillum: the one entry point. `make help` lists the targets.

CC ?= cc
AR ?= ar
BUILDDIR ?= build
VENV ?= .venv
PY := $(VENV)/bin/python

WARN := -std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion -Werror
OPT ?= -O2
# The runtime never reads errno: -fno-math-errno lets sqrt be one instruction
# (no libm call on the error path), on the host and on the Cortex-M targets.
RT_MATH := -fno-math-errno
RT_CFLAGS := $(WARN) $(OPT) $(RT_MATH) -ffunction-sections -fdata-sections -Iinclude -Isrc -Itables
HOST_CFLAGS := $(WARN) $(OPT) -g -Iinclude -Isrc -Itables -Itests/c
# Tests mix double references with oi_real: strict, but without the promotion/conversion checks.
TEST_CFLAGS := -std=c99 -Wall -Wextra -Wpedantic -Wshadow -Werror -O1 -g -Iinclude -Isrc -Itables -Itests/c
HOST_LDFLAGS := -Wl,--gc-sections

# Runtime sources: src/<layer>/*.c, the layers from the bottom up (docs/architecture.md), and
# tables/*.c (generated tables). Linked in the order of their file names, whatever their layer.
RT_LAYERS := math model shadow sources target camera scene batch
RT_LAYER_SRC := $(wildcard $(addprefix src/,$(addsuffix /*.c,$(RT_LAYERS))))
RT_SRC := $(foreach b,$(sort $(notdir $(RT_LAYER_SRC))),$(filter %/$(b),$(RT_LAYER_SRC))) \
  $(sort $(wildcard tables/*.c))

# Precision variants: build/ (double, the contract) and build/float/.
OBJ_double := $(patsubst %.c,$(BUILDDIR)/obj/double/%.o,$(RT_SRC))
OBJ_float  := $(patsubst %.c,$(BUILDDIR)/obj/float/%.o,$(RT_SRC))
LIB_double := $(BUILDDIR)/liborbillum.a
LIB_float  := $(BUILDDIR)/float/liborbillum.a
DEF_double :=
DEF_float  := -DOI_SINGLE_PRECISION

# C unit tests: every tests/c/test_*.c is one cmocka program, built per precision.
CTEST_SRC := $(sort $(wildcard tests/c/test_*.c))
CTEST_double := $(patsubst tests/c/%.c,$(BUILDDIR)/tests/double/%,$(CTEST_SRC))
CTEST_float  := $(patsubst tests/c/%.c,$(BUILDDIR)/tests/float/%,$(CTEST_SRC))

PLAN_SRC := $(sort $(wildcard planner/*.c))
PLAN := $(BUILDDIR)/oi-plan
QUICKSTART := $(BUILDDIR)/quickstart

.PHONY: all lib demo test test-c test-py test-py-0 test-py-1 test-layers clean help
.DEFAULT_GOAL := all

all: lib $(PLAN) $(QUICKSTART) ## build the library (both precisions), the planner and the README example

lib: $(LIB_double) $(LIB_float) ## build build/liborbillum.a and build/float/liborbillum.a

$(BUILDDIR)/obj/double/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(RT_CFLAGS) $(DEF_double) $(EXTRA_DEFS) -MMD -MP -c $< -o $@

$(BUILDDIR)/obj/float/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(RT_CFLAGS) $(DEF_float) $(EXTRA_DEFS) -MMD -MP -c $< -o $@

$(LIB_double): $(OBJ_double)
	@mkdir -p $(dir $@)
	rm -f $@ && $(AR) rcs $@ $^

$(LIB_float): $(OBJ_float)
	@mkdir -p $(dir $@)
	rm -f $@ && $(AR) rcs $@ $^

$(PLAN): $(PLAN_SRC) $(LIB_double)
	@mkdir -p $(dir $@)
	$(CC) $(HOST_CFLAGS) -Iplanner $(PLAN_SRC) $(LIB_double) -lm $(HOST_LDFLAGS) -o $@

$(QUICKSTART): examples/quickstart/quickstart.c $(LIB_double)
	@mkdir -p $(dir $@)
	$(CC) $(TEST_CFLAGS) $< $(LIB_double) -lm -o $@

demo: $(PLAN) ## run the exposure planner on its built-in scenario
	$(PLAN)

# ---- tests
# test_numtext compiles the planner's number text into itself
$(BUILDDIR)/tests/double/test_numtext $(BUILDDIR)/tests/float/test_numtext: planner/numtext.c planner/numtext.h
# test_csv_read compiles the planner's CSV reader into itself
$(BUILDDIR)/tests/double/test_csv_read $(BUILDDIR)/tests/float/test_csv_read: planner/csv_read.c planner/csv_read.h planner/csv_mem.c
$(BUILDDIR)/tests/double/%: tests/c/%.c $(LIB_double) | deps-c
	@mkdir -p $(dir $@)
	$(CC) $(TEST_CFLAGS) $(DEF_double) $< $(LIB_double) -lcmocka -lm -o $@

$(BUILDDIR)/tests/float/%: tests/c/%.c $(LIB_float) | deps-c
	@mkdir -p $(dir $@)
	$(CC) $(TEST_CFLAGS) $(DEF_float) $< $(LIB_float) -lcmocka -lm -o $@

# Fragments in mk/, by role, add their own targets and append to TEST_TARGETS. The order
# matters where one fragment's template uses another's variables: the matrix comes last.
TEST_TARGETS := test-c test-py
include mk/deps.mk mk/target.mk
-include mk/size.mk
include mk/analysis.mk mk/python.mk mk/generated.mk mk/report.mk mk/wasm.mk mk/matrix.mk

# The planner's CSV reader and number text take SSE2 paths where the compiler has them (every
# x86-64): their tests again without it, so that the portable paths are tested too.
CTEST_PORTABLE := $(BUILDDIR)/tests/portable/test_csv_read $(BUILDDIR)/tests/portable/test_numtext
$(BUILDDIR)/tests/portable/test_csv_read: planner/csv_read.c planner/csv_read.h planner/csv_mem.c
$(BUILDDIR)/tests/portable/test_numtext: planner/numtext.c planner/numtext.h
$(BUILDDIR)/tests/portable/%: tests/c/%.c $(LIB_double) | deps-c
	@mkdir -p $(dir $@)
	$(CC) $(TEST_CFLAGS) -U__SSE2__ $(DEF_double) $< $(LIB_double) -lcmocka -lm -o $@

test-c: $(CTEST_double) $(CTEST_float) $(CTEST_PORTABLE) $(PLAN) $(QUICKSTART) ## C unit tests, double and single precision
	@set -e; for t in $(CTEST_double) $(CTEST_float) $(CTEST_PORTABLE); do echo "== $$t"; $$t; done
	$(QUICKSTART)

# The Python suite in two shards (every other file of the sorted list), so that `make -j2 test`
# keeps both cores busy; `make test-py` runs both, `make test-py-0` or `test-py-1` one.
PY_TEST_FILES := $(sort $(wildcard tests/python/test_*.py))
py_shard = $(foreach i,$(shell seq $(1) 2 $(words $(PY_TEST_FILES))),$(word $(i),$(PY_TEST_FILES)))
PY_SHARD_FIRST_test-py-0 := 1
PY_SHARD_FIRST_test-py-1 := 2
test-py: test-py-0 test-py-1 ## Python tests (baker, references, planner, binding, catalog)
test-py-0 test-py-1: deps-py all
	$(PY) -m pytest -q -p no:cacheprovider $(call py_shard,$(PY_SHARD_FIRST_$@))

# The layer rule (docs/architecture.md): every include and call of src/<layer>/ goes down, no
# two files need each other; on the objects of both precisions.
test-layers: lib deps-py ## check that each layer of src/ calls only the layers below it
	$(PY) tools/check_layers.py --layers "$(RT_LAYERS)" --objects $(BUILDDIR)/obj/double
	$(PY) tools/check_layers.py --layers "$(RT_LAYERS)" --objects $(BUILDDIR)/obj/float
TEST_TARGETS += test-layers

# A mismatch of precision between a program and the archive fails at link time.
test-precision-guard: lib ## link a program against the wrong-precision archive and expect the named failure
	sh tests/c/precision_guard.sh $(BUILDDIR) $(CC)
TEST_TARGETS += test-precision-guard

# Each section header of the public API (include/orbillum/*.h) compiles alone.
.PHONY: test-headers
test-headers: ## compile each section header include/orbillum/*.h alone: both precisions, every option
	sh tests/c/header_sections.sh $(CC)
TEST_TARGETS += test-headers

test: deps $(TEST_TARGETS) ## every test: C (both precisions) and Python
	@echo "all tests passed"

clean: ## remove build outputs
	rm -rf $(BUILDDIR)

help: ## list the targets
	@grep -hE '^[a-zA-Z_-]+:.*## ' $(MAKEFILE_LIST) | sed 's/:.*## /\t/' | sort

-include $(OBJ_double:.o=.d) $(OBJ_float:.o=.d)
